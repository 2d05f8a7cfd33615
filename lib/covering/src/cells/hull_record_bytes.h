#pragma once
// The records the stages' byte forms share (cell results, cell_result_bytes.h;
// seam results, seam_result_bytes.h): counts, planes, solids and a run's
// statistics, in the byte order of little_endian_bytes.h. Readers check
// every count against the bytes left and every value for finiteness, so
// bytes from another process or a cache are never trusted.

#include "prepared_scene_view.h"

#include "hullcover/covering/covering_types.h"
#include "hullcover/geometry/convex_polytope.h"
#include "hullcover/geometry/little_endian_bytes.h"
#include "hullcover/geometry/status.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace hullcover::detail {

/// How a record names mesh vertices: by their number in a list (a cell's
/// vertices by first use, so the bytes still mean the same in an edited
/// scene), or by mesh vertex id.
struct VertexNaming {
  std::vector<int> global;            ///< stored number -> mesh vertex
  std::unordered_map<int, int> local; ///< mesh vertex -> stored number
  /// >= 0: stored numbers are mesh vertex ids below this (the lists unused).
  int mesh_vertex_count = -1;

  static VertexNaming by_mesh_id(int mesh_vertex_count) {
    VertexNaming naming;
    naming.mesh_vertex_count = mesh_vertex_count;
    return naming;
  }
  std::int32_t stored(int vertex) const { return mesh_vertex_count >= 0 ? vertex : local.at(vertex); }
  /// The mesh vertex stored as `number`; false when it names none.
  bool vertex(std::int32_t number, int& vertex) const {
    const long long count = mesh_vertex_count >= 0 ? mesh_vertex_count : static_cast<long long>(global.size());
    if (number < 0 || number >= count) return false;
    vertex = mesh_vertex_count >= 0 ? number : global[static_cast<size_t>(number)];
    return true;
  }
};

/// The counts a run's statistics carry (timings are the whole run's).
void write_statistics(LittleEndianWriter& out, const CoveringStatistics& s);
bool read_statistics(LittleEndianReader& in, CoveringStatistics& s);

void write_plane(LittleEndianWriter& out, const Plane& p);
bool read_plane(LittleEndianReader& in, Plane& p);
bool read_vector(LittleEndianReader& in, Eigen::Vector3d& v);

/// A count, refused when the bytes left cannot hold that many entries of
/// `entry_bytes` each.
bool read_count(LittleEndianReader& in, size_t entry_bytes, std::uint32_t& n);

/// A convex polytope: u32 V + V x 3 f64, u32 F + per facet u32 n + n u32
/// corners, u32 P + P x 4 f64 planes, u32 (0 or V) + i32 vertex ids (-1:
/// none, else as `naming` stores them).
void write_solid(LittleEndianWriter& out, const ConvexPolytope& solid, const VertexNaming& naming);
bool read_solid(LittleEndianReader& in, const VertexNaming& naming, ConvexPolytope& solid);

/// Opens a record laid out as an 8-byte magic, u32 version, its body, and
/// u64 FNV-1a-64 of everything before it: `unknown_format` for another
/// magic ("not a hullcover WHAT") or version, `unreadable_file` for fewer
/// than `smallest` bytes or a checksum that does not match; else `in`
/// reads the body.
Status open_checked_record(const std::string& bytes, const char (&magic)[8], std::uint32_t version,
                           std::size_t smallest, const std::string& what, LittleEndianReader& in);

/// A hull's surface planes (CoveringHull::surface_planes): u32 P + P u8;
/// read back, P must be the polytope's plane count.
void write_surface_planes(LittleEndianWriter& out, const CoveringHull& hull);
bool read_surface_planes(LittleEndianReader& in, CoveringHull& hull);

/// Whether a hull read back is sound: finite thickness and volume, neither
/// negative, a thickness only for a planar hull; and every corner of its
/// faces within `tol` of it, so bytes can never drop a face's collision.
bool hull_holds_its_faces(const CoveringHull& hull, const MeshView& mesh, double tol);

} // namespace hullcover::detail
