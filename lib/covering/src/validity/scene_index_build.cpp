#include "validity/scene_index_build.h"

#include "validity/first_hit_bound.h"
#include "hullcover/geometry/parallel_for.h"
#include "hullcover/geometry/tolerances.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace hullcover {
namespace {

Aabb box_of(std::initializer_list<Eigen::Vector3d> points) {
  Aabb box;
  for (const Eigen::Vector3d& p : points) box.extend(p);
  return box;
}

void add_bar(const SceneIndexData& index, std::vector<BoundaryBar>& bars, int edge, int face, double half_length) {
  const MeshEdge& e = index.prepared->connectivity.edges[edge];
  const Eigen::Vector3d& p0 = index.prepared->mesh.positions[e.v0];
  const Eigen::Vector3d& p1 = index.prepared->mesh.positions[e.v1];
  const Eigen::Vector3d offset = half_length * index.face_normals[face];
  if (index.mode == ValidityMode::exact) {
    bars.push_back({p0 - offset, p0 + offset, p1 - p0, edge, face});
  } else {
    const Eigen::Vector3d mid = 0.5 * (p0 + p1);
    bars.push_back({mid - offset, mid + offset, Eigen::Vector3d::Zero(), edge, face});
  }
}

// `box` within `bounds` (empty when they do not meet).
Aabb clipped(const Aabb& box, const Aabb& bounds) {
  Aabb out;
  out.min = box.min.cwiseMax(bounds.min);
  out.max = box.max.cwiseMin(bounds.max);
  return out;
}

// Where a sweep's base moved along it meets `zone`: the box of the stretch
// of the sweep whose moving base box (grown by tol: a sweep keeps points
// within tol of its sides and start) overlaps the zone, grown by tol and
// clipped to the zone (empty when it never does). A superset of the sweep's
// part in the zone: the moving base lies in its moving box.
Aabb sweep_part_in(const FreeSpaceSweep& sweep, const Aabb& zone, double tol) {
  Aabb base, moved;
  for (const Eigen::Vector3d& p : sweep.base) base.extend(p);
  const Eigen::Vector3d along = sweep.reach * sweep.direction;
  base = grown(base, tol);
  double enter = 0.0, leave = 1.0; // fractions of the sweep
  for (int axis = 0; axis < 3; ++axis) {
    const double d = along[axis];
    if (d == 0.0) {
      if (base.max[axis] < zone.min[axis] || base.min[axis] > zone.max[axis]) return Aabb{};
      continue;
    }
    double a = (zone.min[axis] - base.max[axis]) / d, b = (zone.max[axis] - base.min[axis]) / d;
    if (a > b) std::swap(a, b);
    enter = std::max(enter, a);
    leave = std::min(leave, b);
  }
  if (!(enter <= leave)) return Aabb{};
  moved.extend(base.min + enter * along);
  moved.extend(base.max + enter * along);
  moved.extend(base.min + leave * along);
  moved.extend(base.max + leave * along);
  return clipped(grown(moved, tol), zone);
}

// Adds `item`'s box once per hull zone its sweep crosses.
void add_sweep_boxes(const FreeSpaceSweep& sweep, int item, const std::vector<Aabb>& zones, const AabbTree& zone_tree,
                     double tol, std::vector<int>& near, std::vector<Aabb>& boxes, std::vector<int>& items) {
  Aabb whole;
  for (const Eigen::Vector3d& corner : sweep.corners) whole.extend(corner);
  near.clear();
  // Subtrees of zones the swept box misses are passed over whole: a long
  // sweep (an opening fan that escapes the scene) crosses the boxes of many
  // far zones while passing through few of them.
  const auto missed = [&](const Aabb& region) { return sweep_part_in(sweep, region, tol).empty(); };
  zone_tree.any_overlapping_pruned(grown(whole, tol), missed, [&](int z) {
    near.push_back(z);
    return false;
  });
  std::sort(near.begin(), near.end());
  for (int z : near) {
    const Aabb part = sweep_part_in(sweep, zones[z], tol);
    if (part.empty()) continue;
    boxes.push_back(part);
    items.push_back(item);
  }
}

// How far every face's front sweep and every open edge's fans run, and
// their boxes, per hull zone they cross: the trees the exact conditions
// look up.
// Each face's (each open edge's) sweeps at the tolerance of its island.
void index_sweeps(SceneIndexData& index, double hull_margin, const std::vector<Aabb>& hull_zones, int threads) {
  const PreparedSceneView& prepared = *index.prepared;
  const MeshView& mesh = prepared.mesh;
  const ConnectivityView& c = prepared.connectivity;
  const double reach = index.free_space_reach;
  const double largest_tol = prepared.tolerance.largest_length();
  std::vector<Aabb> zones;
  for (const Aabb& zone : hull_zones) zones.push_back(grown(zone, largest_tol));
  if (zones.empty()) zones.push_back(grown(referenced_bounding_box(mesh), hull_margin + largest_tol));
  const AabbTree zone_tree(zones);
  // The reaches, each face's and edge's alone, on `threads` threads; the
  // boxes then in order, so the trees do not depend on the thread count.
  std::vector<double> front_reach(mesh.triangles.size(), 0.0);
  parallel_for(static_cast<int>(mesh.triangles.size()), threads, [&](int f) {
    if (c.zero_area[f]) return;
    const double tol = prepared.face_tolerance(f);
    const SceneIndex at_face(index, tol, prepared.tolerance.largest_island);
    std::vector<Eigen::Vector3d> corners(3);
    std::vector<int> own_scratch;
    triangle_corners(mesh, f, corners);
    const FreeSpaceSweep full = front_space_sweep(corners, index.face_normals[f], reach, tol);
    front_reach[f] = std::min(reach, detail::first_hit_bound(at_face, full, own_scratch));
  });
  std::vector<std::array<double, kOpeningFans>> opening_reach(c.edges.size());
  parallel_for(static_cast<int>(c.edges.size()), threads, [&](int e) {
    if (index.open_edge_use[e] < 0) return;
    const EdgeUse& use = c.edge_uses[index.open_edge_use[e]];
    const double tol = prepared.face_tolerance(use.face);
    const SceneIndex at_edge(index, tol, prepared.tolerance.largest_island);
    const Eigen::Vector3i& t = mesh.triangles[use.face];
    std::vector<int> own_scratch;
    for (int fan = 0; fan < kOpeningFans; ++fan) {
      const FreeSpaceSweep full =
          opening_fan(mesh.positions[t[use.corner]], mesh.positions[t[(use.corner + 1) % 3]],
                      mesh.positions[t[(use.corner + 2) % 3]], index.face_normals[use.face], fan, reach, tol);
      opening_reach[e][fan] = std::min(reach, detail::first_hit_bound(at_edge, full, own_scratch));
    }
  });
  index.front_reach = std::move(front_reach);
  index.opening_reach = std::move(opening_reach);
  // The two sweep trees, each from its boxes in face or edge order, side by
  // side: each job writes only its own tree and item list.
  parallel_for(2, threads, [&](int job) {
    std::vector<int> near;
    std::vector<Aabb> boxes;
    if (job == 0) {
      std::vector<int> sweep_faces;
      std::vector<Eigen::Vector3d> triangle(3);
      for (int f = 0; f < static_cast<int>(mesh.triangles.size()); ++f) {
        if (c.zero_area[f]) continue;
        const double tol = prepared.face_tolerance(f);
        triangle_corners(mesh, f, triangle);
        const FreeSpaceSweep sweep = front_space_sweep(triangle, index.face_normals[f], index.front_reach[f], tol);
        add_sweep_boxes(sweep, f, zones, zone_tree, tol, near, boxes, sweep_faces);
      }
      index.front_sweep_tree = AabbTree(boxes);
      index.front_sweep_face = std::move(sweep_faces);
      return;
    }
    std::vector<int> sweep_edges;
    for (int e = 0; e < static_cast<int>(c.edges.size()); ++e) {
      if (index.open_edge_use[e] < 0) continue;
      const EdgeUse& use = c.edge_uses[index.open_edge_use[e]];
      const double tol = prepared.face_tolerance(use.face);
      const Eigen::Vector3i& t = mesh.triangles[use.face];
      const Eigen::Vector3d& p0 = mesh.positions[t[use.corner]];
      const Eigen::Vector3d& p1 = mesh.positions[t[(use.corner + 1) % 3]];
      const Eigen::Vector3d& inner = mesh.positions[t[(use.corner + 2) % 3]];
      // The three fans together, each cut to the zones it crosses; an edge
      // with parts of several fans in one zone keeps one box there.
      std::vector<Aabb> fan_boxes;
      std::vector<int> fan_items;
      for (int fan = 0; fan < kOpeningFans; ++fan) {
        const Eigen::Vector3d& n = index.face_normals[use.face];
        const FreeSpaceSweep sweep = opening_fan(p0, p1, inner, n, fan, index.opening_reach[e][fan], tol);
        add_sweep_boxes(sweep, e, zones, zone_tree, tol, near, fan_boxes, fan_items);
      }
      Aabb box;
      for (const Aabb& part : fan_boxes) box.extend(part.min), box.extend(part.max);
      // One box over the fans' parts is the simplest superset; kept per zone
      // only when the parts lie in several zones far apart.
      if (fan_boxes.size() <= 1 || zones.size() == 1) {
        if (box.empty()) continue;
        boxes.push_back(box);
        sweep_edges.push_back(e);
        continue;
      }
      for (const Aabb& part : fan_boxes) {
        boxes.push_back(part);
        sweep_edges.push_back(e);
      }
    }
    index.opening_sweep_tree = AabbTree(boxes);
    index.opening_sweep_edge = std::move(sweep_edges);
  });
}

} // namespace

SceneIndexData build_scene_index(const PreparedSceneView& prepared, const BarOptions& options) {
  SceneIndexData index;
  index.prepared = &prepared;
  index.mode = options.mode;
  index.free_space_reach = options.free_space_reach;
  index.agent_radius = options.agent_radius;
  index.max_deviation = options.max_deviation;
  std::vector<int> open_edge_use(prepared.connectivity.edges.size(), -1);
  std::vector<BoundaryBar> bars;
  const MeshView& mesh = prepared.mesh;
  const ConnectivityView& c = prepared.connectivity;
  const int face_count = static_cast<int>(mesh.triangles.size());
  const auto half_length = [&](int face) {
    return options.half_length_of_island.empty() ? options.half_length
                                                 : options.half_length_of_island[prepared.islands.island_of_face[face]];
  };

  std::vector<Eigen::Vector3d> face_normals(face_count, Eigen::Vector3d::Zero());
  std::vector<double> face_areas(face_count, 0.0);
  for (int f = 0; f < face_count; ++f) {
    const Eigen::Vector3d area_vector = triangle_area_vector(mesh, f);
    face_areas[f] = 0.5 * area_vector.norm();
    if (!c.zero_area[f]) face_normals[f] = area_vector.normalized();
  }
  index.face_normals = std::move(face_normals);
  index.face_areas = std::move(face_areas);

  for (int e = 0; e < static_cast<int>(c.edges.size()); ++e) {
    const MeshEdge& edge = c.edges[e];
    if (edge.kind == EdgeKind::boundary) {
      const int face = c.edge_uses[edge.first_use].face;
      if (c.zero_area[face]) continue;
      add_bar(index, bars, e, face, half_length(face));
      open_edge_use[e] = edge.first_use;
    } else if (options.mode == ValidityMode::exact && is_fold_edge(prepared, e)) {
      add_bar(index, bars, e, c.edge_uses[edge.first_use].face, half_length(c.edge_uses[edge.first_use].face));
      open_edge_use[e] = edge.first_use;
    } else if (options.material_boundaries && edge.kind == EdgeKind::manifold) {
      const int f0 = c.edge_uses[edge.first_use].face, f1 = c.edge_uses[edge.first_use + 1].face;
      if (mesh.material_ids[f0] == mesh.material_ids[f1]) continue;
      for (int face : {f0, f1})
        if (!c.zero_area[face]) add_bar(index, bars, e, face, half_length(face));
    }
  }
  index.open_edge_use = std::move(open_edge_use);
  index.bars = std::move(bars);

  // The four element trees are independent, so they are built side by side
  // on the bake's threads (a re-bake after a small edit spends much of its
  // time indexing); a tree is the same whichever thread builds it. The
  // largest, the edges', goes first.
  const int threads = threads_to_use(options.threads);
  parallel_for(4, threads, [&](int tree) {
    std::vector<Aabb> boxes;
    if (tree == 0) {
      boxes.reserve(c.edges.size());
      for (const MeshEdge& e : c.edges) boxes.push_back(box_of({mesh.positions[e.v0], mesh.positions[e.v1]}));
      index.edge_tree = AabbTree(boxes);
    } else if (tree == 1) {
      boxes.reserve(mesh.triangles.size());
      for (const Eigen::Vector3i& t : mesh.triangles)
        boxes.push_back(box_of({mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]}));
      index.face_tree = AabbTree(boxes);
    } else if (tree == 2) {
      boxes.reserve(mesh.positions.size());
      for (const Eigen::Vector3d& p : mesh.positions) boxes.push_back(box_of({p}));
      index.vertex_tree = AabbTree(boxes);
    } else {
      const double piece_length = prepared.tolerance.diagonal / kBarPiecesPerDiagonal;
      std::vector<int> bar_of_piece;
      for (int b = 0; b < static_cast<int>(index.bars.size()); ++b) {
        const BoundaryBar& bar = index.bars[b];
        const int pieces = std::max(1, static_cast<int>(std::ceil((bar.b - bar.a).norm() / piece_length)));
        for (int k = 0; k < pieces; ++k) {
          const Eigen::Vector3d from = bar.a + (bar.b - bar.a) * (static_cast<double>(k) / pieces);
          const Eigen::Vector3d to = bar.a + (bar.b - bar.a) * (static_cast<double>(k + 1) / pieces);
          boxes.push_back(box_of({from, to, from + bar.along, to + bar.along}));
          bar_of_piece.push_back(b);
        }
      }
      index.bar_tree = AabbTree(boxes);
      index.bar_of_piece = std::move(bar_of_piece);
    }
  });
  if (index.mode == ValidityMode::exact) index_sweeps(index, options.hull_margin, options.hull_zones, threads);
  return index;
}

} // namespace hullcover
