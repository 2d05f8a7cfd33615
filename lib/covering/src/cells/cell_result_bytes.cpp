#include "cells/cell_result_bytes.h"
#include "cells/hull_record_bytes.h"

#include "hullcover/geometry/little_endian_bytes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace hullcover::detail {
namespace {

constexpr char kMagic[8] = {'H', 'C', 'C', 'E', 'L', 'L', '\0', '\0'};
constexpr std::uint32_t kVersion = 3;
// Part of every cell key: raise it whenever a change to the merging or to
// the making of hulls makes a cell keep other patches or hulls, so caches
// filled by older builds are not reused.
constexpr std::uint32_t kMergingRevision = 1;

// The cell's vertices, numbered by first use in its faces (slot order).
VertexNaming cell_vertices(const DecompositionStages& stages, int cell) {
  VertexNaming v;
  for (int f : stages.cells.faces_of_cell[cell])
    for (int k = 0; k < 3; ++k) {
      const int g = stages.prepared.mesh.triangles[f][k];
      if (v.local.emplace(g, static_cast<int>(v.global.size())).second) v.global.push_back(g);
    }
  return v;
}

// A patch's hull (patch_hulls.h): faces, material and planar are the
// patch's own and not written.
void write_patch_hull(LittleEndianWriter& out, const PatchHull& made, const VertexNaming& vertices) {
  write_solid(out, made.hull.polytope, vertices);
  out.f64(made.hull.thickness);
  out.f64(made.hull.volume);
  out.u8(made.kept_as_grown);
  write_surface_planes(out, made.hull);
}

bool read_patch_hull(LittleEndianReader& in, const VertexNaming& vertices, const Patch& patch, const MeshView& mesh,
                     double tol, PatchHull& made) {
  CoveringHull& hull = made.hull;
  if (!read_solid(in, vertices, hull.polytope) || hull.polytope.facets.empty()) return false;
  hull.thickness = in.f64();
  hull.volume = in.f64();
  made.kept_as_grown = in.u8() != 0;
  if (!read_surface_planes(in, hull)) return false;
  hull.planar = patch.planar;
  hull.material = patch.material;
  hull.faces = patch.faces;
  std::sort(hull.faces.begin(), hull.faces.end());
  // Whatever else it is, a hull holds its own faces (within its place's
  // tolerance).
  return !in.failed && hull_holds_its_faces(hull, mesh, tol);
}

Status unreadable(const std::string& what) { return {StatusCode::unreadable_file, "cell result: " + what}; }

// cell_key, with the cell's vertices already gathered.
std::uint64_t key_of_cell(const DecompositionStages& stages, int cell, const VertexNaming& vertices) {
  const Covering& covering = stages.covering;
  const DecomposeOptions& options = covering.options;
  const MeshView& mesh = stages.prepared.mesh;
  LittleEndianWriter key;
  key.bytes.assign(kMagic, sizeof kMagic);
  key.u32(kVersion);
  key.u32(kMergingRevision);
  const SceneIndex& index = stages.index_of_cell(cell);
  key.f64(index.tol());
  key.f64(cell_near_merge_distance(stages, cell));
  key.f64(island_bar_half_length(stages, stages.cells.island_of_cell[cell]));
  write_merging_options(key, covering);
  // What making its hulls reads besides: the prism cap (the user's or the
  // islands' extents) and how far free space is kept.
  key.f64(options.prism_thickness_cap.value_or(-1.0));
  key.f64(covering.free_space_reach);
  const int island = stages.cells.island_of_cell[cell];
  if (island >= 0) {
    key.f64(covering.island_extents[island]);
  } else {
    for (double extent : covering.island_extents) key.f64(extent);
  }
  key.u32(static_cast<std::uint32_t>(stages.cells.faces_of_cell[cell].size()));
  for (int f : stages.cells.faces_of_cell[cell]) {
    for (int k = 0; k < 3; ++k) key.u32(static_cast<std::uint32_t>(vertices.local.at(mesh.triangles[f][k])));
    key.i32(mesh.material_ids[f]);
  }
  for (int g : vertices.global)
    for (int k = 0; k < 3; ++k) key.f64(mesh.positions[g][k]);
  return fnv1a(reinterpret_cast<const unsigned char*>(key.bytes.data()), key.bytes.size());
}

} // namespace

void write_merging_options(LittleEndianWriter& out, const Covering& covering) {
  const DecomposeOptions& options = covering.options;
  out.u8(static_cast<std::uint8_t>(options.conditions));
  out.u8(static_cast<std::uint8_t>(options.order));
  out.u64(options.seed);
  out.u32(static_cast<std::uint32_t>(options.order_tries));
  out.u8(options.keep_materials_apart);
  out.u8(covering.dissolve);
  out.u32(static_cast<std::uint32_t>(options.max_hull_vertices));
  out.u32(static_cast<std::uint32_t>(options.max_hull_triangles.value_or(0)));
  out.f64(options.agent_radius.value_or(0.0));
  out.f64(options.max_deviation.value_or(0.0));
}

std::uint64_t cell_key(const DecompositionStages& stages, int cell) {
  return key_of_cell(stages, cell, cell_vertices(stages, cell));
}

std::string cell_result_bytes(const DecompositionStages& stages, int cell, const CellResult& result) {
  const VertexNaming vertices = cell_vertices(stages, cell);
  const CellLayout& cells = stages.cells;
  LittleEndianWriter out;
  out.bytes.assign(kMagic, sizeof kMagic);
  out.u32(kVersion);
  out.u64(key_of_cell(stages, cell, vertices));
  out.u32(static_cast<std::uint32_t>(cells.faces_of_cell[cell].size()));
  out.u32(static_cast<std::uint32_t>(vertices.global.size()));
  write_statistics(out, result.statistics);
  out.u32(static_cast<std::uint32_t>(result.patches.size()));
  for (const Patch& patch : result.patches) {
    out.u32(static_cast<std::uint32_t>(patch.faces.size()));
    for (int f : patch.faces) out.u32(static_cast<std::uint32_t>(cells.slot_in_cell[f]));
    out.u32(static_cast<std::uint32_t>(patch.hull_vertices.size()));
    for (int v : patch.hull_vertices) out.u32(static_cast<std::uint32_t>(vertices.local.at(v)));
    out.u32(static_cast<std::uint32_t>(patch.face_planes.size()));
    for (const Plane& p : patch.face_planes) write_plane(out, p);
    out.f64(patch.area);
    out.f64(patch.boundary_length);
    for (int k = 0; k < 3; ++k) out.f64(patch.area_vector[k]);
    out.u8(patch.planar);
    out.i32(patch.material);
    out.i32(patch.version);
    out.u8(patch.solid.has_value());
    if (patch.solid) write_solid(out, *patch.solid, vertices);
  }
  for (const PatchHull& made : result.hulls) write_patch_hull(out, made, vertices);
  out.u64(fnv1a(reinterpret_cast<const unsigned char*>(out.bytes.data()), out.bytes.size()));
  return out.bytes;
}

Result<CellResult> cell_result_from_bytes(const DecompositionStages& stages, int cell, const std::string& bytes) {
  // Magic, version, key, the two sizes, the checksum.
  constexpr size_t kSmallest = sizeof kMagic + 4 + 8 + 4 + 4 + 8;
  LittleEndianReader in;
  if (Status opened = open_checked_record(bytes, kMagic, kVersion, kSmallest, "cell result", in); !opened.ok())
    return opened;
  const std::vector<int>& faces = stages.cells.faces_of_cell[cell];
  const VertexNaming vertices = cell_vertices(stages, cell);
  if (in.u64() != key_of_cell(stages, cell, vertices))
    return unreadable("made for other faces or options (cell key differs)");
  if (in.u32() != faces.size() || in.u32() != vertices.global.size()) return unreadable("cell size differs");
  CellResult result;
  if (!read_statistics(in, result.statistics)) return unreadable("bad statistics");
  std::uint32_t patch_count = 0;
  if (!read_count(in, 4, patch_count)) return unreadable("truncated");
  std::vector<char> used(faces.size(), 0);
  for (std::uint32_t i = 0; i < patch_count; ++i) {
    Patch patch;
    std::uint32_t n = 0;
    if (!read_count(in, 4, n) || n == 0) return unreadable("bad face list");
    for (std::uint32_t j = 0; j < n; ++j) {
      const std::uint32_t slot = in.u32();
      if (slot >= faces.size() || used[slot]) return unreadable("face slot out of range or in two patches");
      used[slot] = 1;
      patch.faces.push_back(faces[slot]);
    }
    if (!read_count(in, 4, n)) return unreadable("bad hull vertex list");
    for (std::uint32_t j = 0; j < n; ++j) {
      const std::uint32_t v = in.u32();
      if (v >= vertices.global.size()) return unreadable("hull vertex out of range");
      patch.hull_vertices.push_back(vertices.global[v]);
    }
    std::sort(patch.hull_vertices.begin(), patch.hull_vertices.end());
    if (!read_count(in, 32, n)) return unreadable("bad plane list");
    patch.face_planes.resize(n);
    for (Plane& p : patch.face_planes)
      if (!read_plane(in, p)) return unreadable("bad face plane");
    patch.area = in.f64();
    patch.boundary_length = in.f64();
    if (!read_vector(in, patch.area_vector) || !std::isfinite(patch.area) || !std::isfinite(patch.boundary_length))
      return unreadable("bad patch measures");
    patch.planar = in.u8() != 0;
    patch.material = in.i32();
    patch.version = in.i32();
    if (in.u8() != 0) {
      patch.solid.emplace();
      if (!read_solid(in, vertices, *patch.solid)) return unreadable("bad solid hull");
    }
    if (in.failed) return unreadable("truncated");
    // The smallest material of its faces, as merging keeps it: an id the
    // exporters can index.
    int smallest = std::numeric_limits<int>::max();
    for (int f : patch.faces) smallest = std::min(smallest, stages.prepared.mesh.material_ids[f]);
    if (patch.material != smallest) return unreadable("a patch's material is not its faces'");
    result.patches.push_back(std::move(patch));
  }
  result.hulls.resize(result.patches.size());
  for (size_t i = 0; i < result.patches.size(); ++i)
    if (!read_patch_hull(in, vertices, result.patches[i], stages.prepared.mesh, stages.index_of_cell(cell).tol(),
                         result.hulls[i]))
      return unreadable("bad patch hull, or one that does not hold its faces");
  if (in.failed || in.at != in.size) return unreadable("trailing or missing bytes");
  for (size_t slot = 0; slot < faces.size(); ++slot)
    if (!used[slot] && stages.index_data.face_normals[faces[slot]] != Eigen::Vector3d::Zero())
      return unreadable("a face of non-zero area is in no patch");
  return result;
}

} // namespace hullcover::detail
