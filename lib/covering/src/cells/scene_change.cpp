#include "cells/scene_change.h"

#include "hullcover/geometry/little_endian_bytes.h"
#include "hullcover/geometry/tolerances.h"

#include "cells/cell_merging.h"
#include "cells/cell_result_bytes.h"
#include "validity/first_hit_bound.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace hullcover::detail {
namespace {

constexpr char kSnapshotMagic[8] = {'H', 'C', 'S', 'C', 'E', 'N', 'E', '\0'};
constexpr std::uint32_t kSnapshotVersion = 1;
// A hostile count may not ask for more entries than this before the bytes
// run out (each entry takes at least 16 bytes anyway).
constexpr std::uint32_t kMostEntries = 1u << 28;

std::uint64_t hash_of(const LittleEndianWriter& w) {
  return fnv1a(reinterpret_cast<const unsigned char*>(w.bytes.data()), w.bytes.size());
}

// Everything scene-wide a check reads: two bakes with the same settings
// hash differ only in faces (and what follows from them per island).
std::uint64_t settings_hash(const DecompositionStages& stages) {
  const Covering& c = stages.covering;
  const DecomposeOptions& o = c.options;
  LittleEndianWriter w;
  w.u32(kSnapshotVersion);
  write_merging_options(w, c);
  w.f64(o.cell_size.value_or(-1.0));
  w.f64(c.bar_half_length);
  w.f64(c.prism_thickness_cap);
  w.f64(c.free_space_reach);
  w.u8(c.free_space_capped);
  w.f64(c.tolerance.length);
  w.f64(c.tolerance.largest_length());
  w.f64(c.tolerance.largest_island);
  return hash_of(w);
}

// A face as its checks and its neighbours' see it: corners to the bit,
// material, and its island's lengths.
std::uint64_t face_hash(const DecompositionStages& stages, int f) {
  const MeshView& mesh = stages.prepared.mesh;
  const int island = stages.prepared.islands.island_of_face[f];
  LittleEndianWriter w;
  for (int k = 0; k < 3; ++k)
    for (int d = 0; d < 3; ++d) w.f64(mesh.positions[mesh.triangles[f][k]][d]);
  w.i32(mesh.material_ids[f]);
  w.f64(stages.prepared.face_tolerance(f));
  w.f64(stages.island_tolerance[island]);
  w.f64(island_bar_half_length(stages, island));
  w.f64(stages.covering.island_extents[island]);
  return hash_of(w);
}

Aabb face_box(const MeshView& mesh, int f) {
  Aabb box;
  for (int k = 0; k < 3; ++k) box.extend(mesh.positions[mesh.triangles[f][k]]);
  return box;
}

// True when every corner of `box` lies outside one of the sweep's planes
// (shrunk by its inset): the box holds no point of the sweep.
bool sweep_misses_box(const FreeSpaceSweep& sweep, const Aabb& box) {
  for (size_t i = 0; i < sweep.planes.size(); ++i) {
    bool all_out = true;
    for (int corner = 0; corner < 8 && all_out; ++corner) {
      const Eigen::Vector3d p((corner & 1) ? box.max.x() : box.min.x(), (corner & 2) ? box.max.y() : box.min.y(),
                              (corner & 4) ? box.max.z() : box.min.z());
      all_out = sweep.planes[i].signed_distance(p) + sweep.insets[i] > 0.0;
    }
    if (all_out) return true;
  }
  return false;
}

// Whether `sweep` meets a changed face's box (grown by `slack`).
bool crosses_changed(const FreeSpaceSweep& sweep, const std::vector<Aabb>& changed, const AabbTree& changed_tree,
                     double slack, std::vector<int>& near) {
  near.clear();
  changed_tree.overlapping(grown(bounding_box_of(sweep.corners), slack), near);
  for (int i : near)
    if (!sweep_misses_box(sweep, grown(changed[i], slack))) return true;
  return false;
}

// The views the checks run in (one per island, and the scene's): their
// finest and coarsest tolerance, scene units.
struct ViewTolerances {
  double finest = 0.0;
  double coarsest = 0.0;
};

ViewTolerances view_tolerances(const DecompositionStages& stages) {
  const Tolerance& tolerance = stages.prepared.tolerance;
  ViewTolerances views{tolerance.length, tolerance.length};
  const auto add = [&](double tol) {
    views.finest = std::min(views.finest, tol);
    views.coarsest = std::max(views.coarsest, tol);
  };
  for (double tol : stages.island_tolerance) add(tol);
  for (double tol : tolerance.island_lengths) add(tol);
  return views;
}

// Keeps a sweep (`at_reach(r)`: it run to r, scene units; `reach`: how far
// it runs) when its rays, followed as far as any view follows them, cross
// a changed face. Its own reach ends each ray's first hit in its own view;
// a coarser view stands further off, may pass that face and read the ray's
// hit beyond (witness_rays.h), a finer one may pass between faces: then
// the rays are followed to their bound in every view.
template <typename SweepAtReach>
void keep_if_crossing(const SweepAtReach& at_reach, double reach, const DecompositionStages& stages,
                      const SceneIndex& finest_view, double coarsest_tol, const std::vector<Aabb>& changed,
                      const AabbTree& changed_tree, double slack, std::vector<int>& near, std::vector<int>& scratch,
                      std::vector<FreeSpaceSweep>& kept) {
  FreeSpaceSweep sweep = at_reach(reach);
  if (crosses_changed(sweep, changed, changed_tree, slack, near)) {
    kept.push_back(std::move(sweep));
    return;
  }
  const double free_space_reach = stages.index_data.free_space_reach;
  if (finest_view.tol() == coarsest_tol || reach >= free_space_reach) return;
  const FreeSpaceSweep whole = at_reach(free_space_reach);
  if (!crosses_changed(whole, changed, changed_tree, slack, near)) return;
  const double followed =
      std::min(free_space_reach, first_hit_bound_in_every_view(finest_view, whole, coarsest_tol, scratch));
  if (followed > reach && crosses_changed(at_reach(followed), changed, changed_tree, slack, near))
    kept.push_back(std::move(sweep));
}

} // namespace

std::vector<std::uint64_t> face_hashes_of(const DecompositionStages& stages) {
  std::vector<std::uint64_t> hashes(stages.prepared.mesh.triangles.size());
  for (size_t f = 0; f < hashes.size(); ++f) hashes[f] = face_hash(stages, static_cast<int>(f));
  return hashes;
}

std::string scene_snapshot_bytes(const DecompositionStages& stages, const std::vector<std::uint64_t>& face_hashes,
                                 const std::vector<std::uint64_t>& cell_keys, const std::vector<std::string>& cells) {
  const MeshView& mesh = stages.prepared.mesh;
  LittleEndianWriter out;
  out.bytes.assign(kSnapshotMagic, sizeof kSnapshotMagic);
  out.u32(kSnapshotVersion);
  out.u64(settings_hash(stages));
  out.u32(static_cast<std::uint32_t>(cells.size()));
  for (size_t c = 0; c < cells.size(); ++c) {
    out.u64(cell_keys[c]);
    out.u64(fnv1a(reinterpret_cast<const unsigned char*>(cells[c].data()), cells[c].size()));
  }
  out.u32(static_cast<std::uint32_t>(mesh.triangles.size()));
  for (int f = 0; f < static_cast<int>(mesh.triangles.size()); ++f) {
    out.u64(face_hashes[f]);
    const Aabb box = face_box(mesh, f);
    for (int d = 0; d < 3; ++d) out.f64(box.min[d]);
    for (int d = 0; d < 3; ++d) out.f64(box.max[d]);
  }
  out.u64(hash_of(out));
  return out.bytes;
}

Result<SceneSnapshot> read_scene_snapshot(const std::string& bytes) {
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  const auto unreadable = [](const std::string& what) {
    return Status{StatusCode::unreadable_file, "scene snapshot: " + what};
  };
  if (bytes.size() < sizeof kSnapshotMagic + 4 + 8 || std::memcmp(data, kSnapshotMagic, sizeof kSnapshotMagic) != 0)
    return Status{StatusCode::unknown_format, "not a hullcover scene snapshot"};
  LittleEndianReader tail{data, bytes.size(), bytes.size() - 8};
  if (tail.u64() != fnv1a(data, bytes.size() - 8)) return unreadable("checksum mismatch");
  LittleEndianReader in{data, bytes.size() - 8, sizeof kSnapshotMagic};
  if (in.u32() != kSnapshotVersion) return Status{StatusCode::unknown_format, "scene snapshot of another version"};
  SceneSnapshot snapshot;
  snapshot.settings = in.u64();
  std::uint32_t n = in.u32();
  if (in.failed || n > kMostEntries || !in.has(static_cast<size_t>(n) * 16)) return unreadable("truncated");
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint64_t key = in.u64();
    snapshot.cell_checksums[key] = in.u64();
  }
  n = in.u32();
  if (in.failed || n > kMostEntries || !in.has(static_cast<size_t>(n) * 56)) return unreadable("truncated");
  snapshot.face_hashes.resize(n);
  snapshot.face_boxes.resize(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    snapshot.face_hashes[i] = in.u64();
    Aabb& box = snapshot.face_boxes[i];
    for (int d = 0; d < 3; ++d) box.min[d] = in.f64();
    for (int d = 0; d < 3; ++d) box.max[d] = in.f64();
    if (!box.min.allFinite() || !box.max.allFinite() || box.empty()) return unreadable("bad face box");
  }
  if (in.failed || in.at != in.size) return unreadable("trailing or missing bytes");
  return snapshot;
}

SceneChange scene_change_since(const DecompositionStages& stages, const std::vector<std::uint64_t>& hashes,
                               const SceneSnapshot& before) {
  SceneChange change;
  const PreparedSceneView& prepared = stages.prepared;
  const MeshView& mesh = prepared.mesh;
  // A user's free-space cap: rays are still followed past it to their first
  // hit, which may be a changed face no capped sweep crosses.
  if (before.settings != settings_hash(stages) || stages.index_data.agent_radius > 0.0 ||
      stages.index_data.max_deviation > 0.0 || stages.covering.free_space_capped)
    return change;
  const int faces = static_cast<int>(mesh.triangles.size());
  std::unordered_map<std::uint64_t, int> now_count, before_count;
  for (std::uint64_t h : hashes) ++now_count[h];
  for (std::uint64_t h : before.face_hashes) ++before_count[h];
  // Added faces, and removed ones (as many copies of a face as differ).
  std::vector<Aabb> changed;
  for (int f = 0; f < faces; ++f)
    if (before_count[hashes[f]]-- <= 0) changed.push_back(face_box(mesh, f));
  for (size_t i = 0; i < before.face_hashes.size(); ++i)
    if (now_count[before.face_hashes[i]]-- <= 0) changed.push_back(before.face_boxes[i]);
  change.everything = false;
  change.changed_faces = static_cast<int>(changed.size());
  change.slack = kSceneChangeSlackInTolerances * prepared.tolerance.largest_length();
  if (changed.empty()) return change;
  double longest_bar = stages.covering.bar_half_length;
  for (int island = 0; island < static_cast<int>(stages.prepared.islands.boxes.size()); ++island)
    longest_bar = std::max(longest_bar, island_bar_half_length(stages, island));
  for (const Aabb& box : changed) change.near_boxes.push_back(grown(box, longest_bar + change.slack));
  change.near_tree = AabbTree(change.near_boxes);
  if (stages.covering.options.conditions != ValidityMode::exact) return change;
  // This scene's sweeps that cross a changed face.
  const AabbTree changed_tree(changed);
  const SceneIndexData& index = stages.index_data;
  const ConnectivityView& c = prepared.connectivity;
  const ViewTolerances views = view_tolerances(stages);
  const SceneIndex finest_view(index, views.finest, prepared.tolerance.largest_island);
  std::vector<int> near, scratch;
  std::vector<Eigen::Vector3d> triangle(3);
  for (int f = 0; f < faces; ++f) {
    if (c.zero_area[f] || index.front_reach[f] <= 0.0) continue;
    triangle_corners(mesh, f, triangle);
    const double tol = prepared.face_tolerance(f);
    const auto at_reach = [&](double reach) { return front_space_sweep(triangle, index.face_normals[f], reach, tol); };
    keep_if_crossing(at_reach, index.front_reach[f], stages, finest_view, views.coarsest, changed, changed_tree,
                     change.slack, near, scratch, change.sweeps);
  }
  for (int e = 0; e < static_cast<int>(c.edges.size()); ++e) {
    if (index.open_edge_use[e] < 0) continue;
    const EdgeUse& use = c.edge_uses[index.open_edge_use[e]];
    const Eigen::Vector3i& t = mesh.triangles[use.face];
    const Eigen::Vector3d& p0 = mesh.positions[t[use.corner]];
    const Eigen::Vector3d& p1 = mesh.positions[t[(use.corner + 1) % 3]];
    const Eigen::Vector3d& inner = mesh.positions[t[(use.corner + 2) % 3]];
    const Eigen::Vector3d& n = index.face_normals[use.face];
    const double tol = prepared.face_tolerance(use.face);
    for (int fan = 0; fan < kOpeningFans; ++fan) {
      const auto at_reach = [&](double reach) { return opening_fan(p0, p1, inner, n, fan, reach, tol); };
      keep_if_crossing(at_reach, index.opening_reach[e][fan], stages, finest_view, views.coarsest, changed,
                       changed_tree, change.slack, near, scratch, change.sweeps);
    }
  }
  std::vector<Aabb> sweep_boxes;
  for (const FreeSpaceSweep& sweep : change.sweeps)
    sweep_boxes.push_back(grown(bounding_box_of(sweep.corners), change.slack));
  change.sweep_tree = AabbTree(sweep_boxes);
  return change;
}

bool patch_may_be_touched(const DecompositionStages& stages, const SceneChange& change, const Patch& patch,
                          const PatchHull& made) {
  if (change.everything) return true;
  if (change.changed_faces == 0) return false;
  const MeshView& mesh = stages.prepared.mesh;
  Aabb box;
  for (int f : patch.faces)
    for (int k = 0; k < 3; ++k) box.extend(mesh.positions[mesh.triangles[f][k]]);
  if (patch.solid)
    for (const Eigen::Vector3d& v : patch.solid->vertices) box.extend(v);
  for (const Eigen::Vector3d& v : made.hull.polytope.vertices) box.extend(v);
  // A planar patch's prism was sought down to the cap, and its bevels and
  // thickness read what lies there.
  if (patch.planar) box = grown(box, prism_cap_of(stages, patch));
  box = grown(box, change.slack);
  std::vector<int> near;
  change.near_tree.overlapping(box, near);
  if (!near.empty()) return true;
  change.sweep_tree.overlapping(box, near);
  for (int s : near)
    if (!sweep_misses_box(change.sweeps[s], box)) return true;
  return false;
}

} // namespace hullcover::detail
