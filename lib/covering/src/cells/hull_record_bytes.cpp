#include "cells/hull_record_bytes.h"

#include <cmath>
#include <cstring>
#include <limits>

namespace hullcover::detail {
namespace {

// Nothing in a record may need more entries than this per list: a bound
// that keeps a hostile count from asking for unbounded memory before the
// bytes run out (each entry takes at least 4 bytes anyway).
constexpr std::uint32_t kMostEntriesPerList = 1u << 28;

} // namespace

void write_statistics(LittleEndianWriter& out, const CoveringStatistics& s) {
  std::vector<std::int64_t> values = {
      s.zero_area_faces_skipped, s.merges,      s.near_merges,       s.dissolved_patches,
      s.candidates_tested,       s.qhull_calls, s.incremental_hulls, s.prisms_made_flat,
      s.solids_kept_as_grown,    s.kept_try};
  values.insert(values.end(), s.rejections.begin(), s.rejections.end());
  out.u32(static_cast<std::uint32_t>(values.size()));
  for (std::int64_t v : values) out.u64(static_cast<std::uint64_t>(v));
}

bool read_statistics(LittleEndianReader& in, CoveringStatistics& s) {
  constexpr std::uint32_t kFixed = 10;
  if (in.u32() != kFixed + kValidityCount) return false;
  std::vector<std::int64_t> v(kFixed + kValidityCount);
  for (std::int64_t& x : v) x = static_cast<std::int64_t>(in.u64());
  for (std::int64_t x : v)
    if (x < 0 || x > std::numeric_limits<int>::max()) return false;
  s.zero_area_faces_skipped = static_cast<int>(v[0]);
  s.merges = static_cast<int>(v[1]);
  s.near_merges = static_cast<int>(v[2]);
  s.dissolved_patches = static_cast<int>(v[3]);
  s.candidates_tested = v[4];
  s.qhull_calls = v[5];
  s.incremental_hulls = v[6];
  s.prisms_made_flat = static_cast<int>(v[7]);
  s.solids_kept_as_grown = static_cast<int>(v[8]);
  s.kept_try = static_cast<int>(v[9]);
  for (int i = 0; i < kValidityCount; ++i) s.rejections[i] = v[kFixed + i];
  return !in.failed;
}

void write_plane(LittleEndianWriter& out, const Plane& p) {
  for (int k = 0; k < 3; ++k) out.f64(p.normal[k]);
  out.f64(p.offset);
}

bool read_count(LittleEndianReader& in, size_t entry_bytes, std::uint32_t& n) {
  n = in.u32();
  return !in.failed && n <= kMostEntriesPerList && in.has(static_cast<size_t>(n) * entry_bytes);
}

bool read_plane(LittleEndianReader& in, Plane& p) {
  for (int k = 0; k < 3; ++k) p.normal[k] = in.f64();
  p.offset = in.f64();
  return !in.failed && p.normal.allFinite() && std::isfinite(p.offset);
}

bool read_vector(LittleEndianReader& in, Eigen::Vector3d& v) {
  for (int k = 0; k < 3; ++k) v[k] = in.f64();
  return !in.failed && v.allFinite();
}

void write_solid(LittleEndianWriter& out, const ConvexPolytope& solid, const VertexNaming& naming) {
  out.u32(static_cast<std::uint32_t>(solid.vertices.size()));
  for (const Eigen::Vector3d& v : solid.vertices)
    for (int k = 0; k < 3; ++k) out.f64(v[k]);
  out.u32(static_cast<std::uint32_t>(solid.facets.size()));
  for (const std::vector<int>& facet : solid.facets) {
    out.u32(static_cast<std::uint32_t>(facet.size()));
    for (int c : facet) out.u32(static_cast<std::uint32_t>(c));
  }
  out.u32(static_cast<std::uint32_t>(solid.planes.size()));
  for (const Plane& p : solid.planes) write_plane(out, p);
  out.u32(static_cast<std::uint32_t>(solid.vertex_ids.size()));
  for (int id : solid.vertex_ids) out.i32(id < 0 ? -1 : naming.stored(id));
}

bool read_solid(LittleEndianReader& in, const VertexNaming& naming, ConvexPolytope& solid) {
  std::uint32_t n = 0;
  if (!read_count(in, 24, n)) return false;
  solid.vertices.resize(n);
  for (Eigen::Vector3d& v : solid.vertices)
    if (!read_vector(in, v)) return false;
  if (!read_count(in, 4, n)) return false;
  solid.facets.resize(n);
  for (std::vector<int>& facet : solid.facets) {
    std::uint32_t corners = 0;
    if (!read_count(in, 4, corners) || corners < 3) return false;
    for (std::uint32_t i = 0; i < corners; ++i) {
      const std::uint32_t c = in.u32();
      if (c >= solid.vertices.size()) return false;
      facet.push_back(static_cast<int>(c));
    }
  }
  if (!read_count(in, 32, n) || n < solid.facets.size()) return false;
  solid.planes.resize(n);
  for (Plane& p : solid.planes)
    if (!read_plane(in, p)) return false;
  if (!read_count(in, 4, n) || (n != 0 && n != solid.vertices.size())) return false;
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::int32_t number = in.i32();
    int id = -1;
    if (number != -1 && !naming.vertex(number, id)) return false;
    solid.vertex_ids.push_back(id);
  }
  return !in.failed;
}

Status open_checked_record(const std::string& bytes, const char (&magic)[8], std::uint32_t version,
                           std::size_t smallest, const std::string& what, LittleEndianReader& in) {
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  if (bytes.size() < sizeof magic + 4 || std::memcmp(data, magic, sizeof magic) != 0)
    return Status{StatusCode::unknown_format, "not a hullcover " + what};
  LittleEndianReader stored{data, bytes.size(), sizeof magic};
  if (stored.u32() != version) return Status{StatusCode::unknown_format, what + " of another version"};
  if (bytes.size() < smallest) return {StatusCode::unreadable_file, what + ": truncated"};
  LittleEndianReader tail{data, bytes.size(), bytes.size() - 8};
  if (tail.u64() != fnv1a(data, bytes.size() - 8)) return {StatusCode::unreadable_file, what + ": checksum mismatch"};
  in = LittleEndianReader{data, bytes.size() - 8, sizeof magic + 4};
  return Status::success();
}

void write_surface_planes(LittleEndianWriter& out, const CoveringHull& hull) {
  out.u32(static_cast<std::uint32_t>(hull.surface_planes.size()));
  for (bool own : hull.surface_planes) out.u8(own);
}

bool read_surface_planes(LittleEndianReader& in, CoveringHull& hull) {
  std::uint32_t n = 0;
  if (!read_count(in, 1, n) || n != hull.polytope.planes.size()) return false;
  for (std::uint32_t i = 0; i < n; ++i) hull.surface_planes.push_back(in.u8() != 0);
  return !in.failed;
}

bool hull_holds_its_faces(const CoveringHull& hull, const MeshView& mesh, double tol) {
  if (!std::isfinite(hull.thickness) || hull.thickness < 0.0 || !std::isfinite(hull.volume) || hull.volume < 0.0 ||
      (!hull.planar && hull.thickness != 0.0))
    return false;
  for (int f : hull.faces)
    for (int k = 0; k < 3; ++k)
      if (deepest_signed_distance(hull.polytope.planes, mesh.positions[mesh.triangles[f][k]]) > tol) return false;
  return true;
}

} // namespace hullcover::detail
