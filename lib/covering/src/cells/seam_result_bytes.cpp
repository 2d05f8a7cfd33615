#include "cells/seam_result_bytes.h"

#include "cells/hull_record_bytes.h"

#include <algorithm>
#include <limits>

namespace hullcover::detail {
namespace {

constexpr char kMagic[8] = {'H', 'C', 'S', 'E', 'A', 'M', '\0', '\0'};
constexpr std::uint32_t kVersion = 1;

Status unreadable(const std::string& what) { return {StatusCode::unreadable_file, "seam result: " + what}; }

void write_hull(LittleEndianWriter& out, const CoveringHull& hull, const VertexNaming& naming) {
  write_solid(out, hull.polytope, naming);
  out.u32(static_cast<std::uint32_t>(hull.faces.size()));
  for (int f : hull.faces) out.u32(static_cast<std::uint32_t>(f));
  out.u8(hull.planar);
  out.f64(hull.thickness);
  out.i32(hull.material);
  out.f64(hull.volume);
  write_surface_planes(out, hull);
}

// A hull of seam cell `seam`; `used` marks, by slot in the seam cell, the
// faces the hulls read so far hold.
bool read_hull(LittleEndianReader& in, const DecompositionStages& stages, const CellLayout& seams, int seam,
               const VertexNaming& naming, std::vector<char>& used, CoveringHull& hull) {
  const MeshView& mesh = stages.prepared.mesh;
  if (!read_solid(in, naming, hull.polytope) || hull.polytope.facets.empty()) return false;
  std::uint32_t n = 0;
  if (!read_count(in, 4, n) || n == 0) return false;
  int smallest_material = std::numeric_limits<int>::max();
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t f = in.u32();
    if (f >= mesh.triangles.size() || seams.cell_of_face[f] != seam || used[seams.slot_in_cell[f]] ||
        (!hull.faces.empty() && static_cast<int>(f) <= hull.faces.back()))
      return false;
    used[seams.slot_in_cell[f]] = 1;
    hull.faces.push_back(static_cast<int>(f));
    smallest_material = std::min(smallest_material, mesh.material_ids[f]);
  }
  hull.planar = in.u8() != 0;
  hull.thickness = in.f64();
  hull.material = in.i32();
  hull.volume = in.f64();
  if (!read_surface_planes(in, hull) || hull.material != smallest_material) return false;
  // As a cell result's: a hull holds its own faces within its island's
  // tolerance.
  return hull_holds_its_faces(hull, mesh, stages.index_of_island(seams.island_of_cell[seam]).tol());
}

} // namespace

std::string seam_result_bytes(const DecompositionStages& stages, const CellLayout& seams, int seam,
                              const SeamResult& result) {
  const VertexNaming naming = VertexNaming::by_mesh_id(static_cast<int>(stages.prepared.mesh.positions.size()));
  LittleEndianWriter out;
  out.bytes.assign(kMagic, sizeof kMagic);
  out.u32(kVersion);
  out.u32(static_cast<std::uint32_t>(seam));
  out.u32(static_cast<std::uint32_t>(seams.faces_of_cell[seam].size()));
  out.u32(static_cast<std::uint32_t>(stages.prepared.mesh.triangles.size()));
  write_statistics(out, result.statistics);
  out.u64(static_cast<std::uint64_t>(result.statistics.seam_merges));
  out.i32(result.largest_cell);
  out.i32(result.largest_cell_kept_try);
  out.u32(static_cast<std::uint32_t>(result.hulls.size()));
  for (const CoveringHull& hull : result.hulls) write_hull(out, hull, naming);
  out.u64(fnv1a(reinterpret_cast<const unsigned char*>(out.bytes.data()), out.bytes.size()));
  return out.bytes;
}

Result<SeamResult> seam_result_from_bytes(const DecompositionStages& stages, const CellLayout& seams, int seam,
                                          const std::string& bytes) {
  // Magic, version, the three counts, the checksum.
  constexpr size_t kSmallest = sizeof kMagic + 4 + 3 * 4 + 8;
  LittleEndianReader in;
  if (Status opened = open_checked_record(bytes, kMagic, kVersion, kSmallest, "seam result", in); !opened.ok())
    return opened;
  const MeshView& mesh = stages.prepared.mesh;
  if (in.u32() != static_cast<std::uint32_t>(seam) || in.u32() != seams.faces_of_cell[seam].size() ||
      in.u32() != mesh.triangles.size())
    return unreadable("made for another seam cell or scene");
  SeamResult result;
  if (!read_statistics(in, result.statistics)) return unreadable("bad statistics");
  const std::uint64_t seam_merges = in.u64();
  if (seam_merges > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) return unreadable("bad statistics");
  result.statistics.seam_merges = static_cast<int>(seam_merges);
  result.largest_cell = in.i32();
  result.largest_cell_kept_try = in.i32();
  const int cell_count = static_cast<int>(stages.cells.faces_of_cell.size());
  if (result.largest_cell < -1 || result.largest_cell >= cell_count || result.largest_cell_kept_try < 0 ||
      (result.largest_cell >= 0 && seams.cell_of_face[stages.cells.faces_of_cell[result.largest_cell].front()] != seam))
    return unreadable("its largest cell is not one of its cells");
  std::uint32_t hull_count = 0;
  if (!read_count(in, 4, hull_count)) return unreadable("truncated");
  const VertexNaming naming = VertexNaming::by_mesh_id(static_cast<int>(mesh.positions.size()));
  std::vector<char> used(seams.faces_of_cell[seam].size(), 0);
  for (std::uint32_t h = 0; h < hull_count; ++h) {
    CoveringHull hull;
    if (!read_hull(in, stages, seams, seam, naming, used, hull))
      return unreadable("bad hull, or one that does not hold its faces");
    result.hulls.push_back(std::move(hull));
  }
  if (in.failed || in.at != in.size) return unreadable("trailing or missing bytes");
  return result;
}

} // namespace hullcover::detail
