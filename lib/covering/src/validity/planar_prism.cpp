#include "validity/planar_prism.h"

#include <limits>

#include "validity/validity_conditions.h"

#include "hullcover/geometry/triangle_distance.h"

#include <Eigen/Geometry>

#include <algorithm>

namespace hullcover {
namespace {

// A bevel clears the face it avoids by this factor on its slope.
constexpr double kBevelClearance = 1.05;
// Halvings tried when the beveled sides meet above the wanted bottom.
constexpr int kBottomRetries = 8;

// Depth below the polygon's plane (positive behind the front).
double depth_below(const FlatPolygon& polygon, const Eigen::Vector3d& p) { return -polygon.plane.signed_distance(p); }

double distance_to_segment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return (closest_point_on_segment(p, a, b) - p).norm();
}

} // namespace

std::vector<Plane> beveled_side_planes(const SceneIndex& index, const FlatPolygon& polygon,
                                       const std::function<bool(int)>& in_patch, std::vector<int>& scratch) {
  const double tol = index.tol();
  const MeshView& mesh = index.mesh();
  const Eigen::Vector3d& n = polygon.plane.normal;
  std::vector<Plane> sides = polygon.sides;
  const size_t count = polygon.corners.size();
  for (size_t i = 0; i < count; ++i) {
    const Eigen::Vector3d& a = polygon.corners[i];
    const Eigen::Vector3d& b = polygon.corners[(i + 1) % count];
    const Eigen::Vector3d& out = polygon.sides[i].normal;
    Aabb edge_box;
    edge_box.extend(a);
    edge_box.extend(b);
    scratch.clear();
    index.face_tree.overlapping(grown(edge_box, tol), scratch);
    double slope = 0.0; // inward run per unit depth the side must exceed
    for (int f : scratch) {
      if (in_patch(f)) continue;
      bool touches = false;
      for (int k = 0; k < 3; ++k) touches |= distance_to_segment(mesh.positions[mesh.triangles[f][k]], a, b) <= tol;
      if (!touches) continue;
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d d = mesh.positions[mesh.triangles[f][k]] - a;
        const double depth = -n.dot(d), inward = -out.dot(d);
        if (depth > tol && inward > 0.0) slope = std::max(slope, kBevelClearance * (inward + tol) / depth);
      }
    }
    slope = std::min(slope, kMaxBevelSlope);
    if (slope == 0.0) continue;
    Plane tilted;
    tilted.normal = (out - slope * n).normalized();
    tilted.offset = tilted.normal.dot(a);
    sides[i] = tilted;
  }
  return sides;
}

namespace {
constexpr double kNever = std::numeric_limits<double>::infinity();
} // namespace

double depth_before_box(const FlatPolygon& polygon, const Aabb& box) {
  const Aabb own = bounding_box_of(polygon.corners);
  const Eigen::Vector3d down = -polygon.plane.normal;
  // The prism's box meets `box` once every axis's interval does; along an
  // axis the interval grows from the polygon's toward `down`.
  double depth = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    double meets = 0.0;
    if (box.min[axis] > own.max[axis])
      meets = down[axis] > 0.0 ? (box.min[axis] - own.max[axis]) / down[axis] : kNever;
    else if (box.max[axis] < own.min[axis])
      meets = down[axis] < 0.0 ? (own.min[axis] - box.max[axis]) / -down[axis] : kNever;
    depth = std::max(depth, meets);
  }
  return depth;
}

double allowed_prism_thickness(const SceneIndex& index, const FlatPolygon& polygon, const std::vector<Plane>& sides,
                               const std::function<bool(int)>& in_patch, double cap, std::vector<int>& scratch) {
  const double tol = index.tol();
  const MeshView& mesh = index.mesh();
  const Eigen::Vector3d& n = polygon.plane.normal;
  Aabb region = bounding_box_of(polygon.corners);
  for (const Eigen::Vector3d& c : polygon.corners) region.extend(c - cap * n);
  region = grown(region, tol);

  double thickness = cap;
  scratch.clear();
  index.face_tree.overlapping(region, scratch);
  // Across an edge whose two faces wind opposite ways, "behind" this patch
  // is the other face's front: a prism would fill its free space (a flipped
  // triangle in a floor would grow a prism up into the room). Flat instead.
  const ConnectivityView& connectivity = index.prepared->connectivity;
  for (int f : scratch) {
    if (!in_patch(f)) continue;
    for (int k = 0; k < 3; ++k) {
      const int e = connectivity.face_edges[f][k];
      if (e >= 0 && connectivity.edges[e].kind == EdgeKind::orientation_conflict) return 0.0;
    }
  }
  std::vector<Eigen::Vector3d> triangle(3);
  for (int f : scratch) {
    if (in_patch(f)) continue;
    triangle_corners(mesh, f, triangle);
    const std::vector<Eigen::Vector3d> part = clip_polygon_to_planes(triangle, sides, tol);
    if (part.empty()) continue;
    double shallowest = depth_below(polygon, part[0]), deepest = shallowest;
    for (const Eigen::Vector3d& p : part) {
      shallowest = std::min(shallowest, depth_below(polygon, p));
      deepest = std::max(deepest, depth_below(polygon, p));
    }
    if (deepest < -tol) continue; // wholly in front of the polygon
    if (deepest <= tol) {
      // Lies on the polygon: harmless unless it faces into the prism (the
      // back of a double-sided wall), whose front space a prism would fill.
      if (index.face_normals[f].dot(n) < 0.0) return 0.0;
      continue;
    }
    thickness = std::min(thickness, std::max(shallowest, 0.0));
  }

  scratch.clear();
  index.bars_overlapping(region, scratch);
  for (int b : scratch) {
    const BoundaryBar& bar = index.bars[b];
    const std::vector<Eigen::Vector3d> segment = clip_polygon_to_planes(bar.outline(), sides, tol);
    if (segment.empty()) continue;
    double shallowest = depth_below(polygon, segment[0]), deepest = shallowest;
    for (const Eigen::Vector3d& p : segment) {
      shallowest = std::min(shallowest, depth_below(polygon, p));
      deepest = std::max(deepest, depth_below(polygon, p));
    }
    if (deepest > tol) thickness = std::min(thickness, std::max(shallowest, 0.0));
  }
  return thickness < kMinPrismThicknessInTolerances * tol ? 0.0 : thickness;
}

ConvexPolytope prism_polytope(const FlatPolygon& polygon, const std::vector<Plane>& sides, double& thickness,
                              double tol, ConvexHullBuilder& hulls) {
  // A patch whose faces span no polygon (a cached cell's bytes may claim
  // one: fuzz_cell_result) has no bottom to build: its flat polytope, as
  // empty as the polygon, which matches no kept hull.
  if (polygon.corners.size() < 3) {
    thickness = 0.0;
    return flat_polytope(polygon, true);
  }
  const Eigen::Vector3d& n = polygon.plane.normal;
  for (int attempt = 0; thickness > 0.0 && attempt <= kBottomRetries; ++attempt, thickness *= 0.5) {
    std::vector<Eigen::Vector3d> bottom;
    for (const Eigen::Vector3d& c : polygon.corners) bottom.push_back(c - thickness * n);
    for (const Plane& side : sides) bottom = clip_polygon(bottom, side, 0.0);
    // Clipping leaves points on edges and near-duplicates; keep corners only,
    // so the hull gets no sliver facets.
    const PlaneFrame frame = PlaneFrame::from_normal(polygon.corners.front(), n);
    std::vector<Eigen::Vector2d> flat;
    for (const Eigen::Vector3d& p : bottom) flat.push_back(frame.to_plane(p));
    const std::vector<int> corners = convex_hull_2d(flat, tol);
    if (corners.size() < 3) continue;
    std::vector<Eigen::Vector3d> points = polygon.corners;
    std::vector<int> ids = polygon.corner_vertices;
    for (int c : corners) points.push_back(bottom[c]);
    ids.resize(points.size(), -1);
    Result<ConvexPolytope> prism = hulls.build(points, ids);
    if (prism.ok() && prism.value().facets.size() >= 4) return std::move(prism).value();
  }
  thickness = 0.0;
  return flat_polytope(polygon, true);
}

} // namespace hullcover
