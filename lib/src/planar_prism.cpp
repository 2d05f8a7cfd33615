#include "hullcover/lib/planar_prism.h"

#include "hullcover/lib/validity_conditions.h"

#include <algorithm>

namespace hullcover {
namespace {

// A prism thinner than this many tolerances is no thicker than the noise of
// the data: it is made flat instead.
constexpr double kMinThicknessInTolerances = 2.0;

// Depth below the polygon's plane (positive behind the front).
double depth_below(const FlatPolygon& polygon, const Eigen::Vector3d& p) { return -polygon.plane.signed_distance(p); }

// The part of a convex polygon inside the polygon's column (its side planes
// shrunk by tol); empty when it misses.
std::vector<Eigen::Vector3d> clip_to_column(std::vector<Eigen::Vector3d> part, const FlatPolygon& polygon, double tol) {
  for (const Plane& side : polygon.sides) {
    if (part.empty()) break;
    part = clip_polygon(part, side, tol);
  }
  return part;
}

} // namespace

ConvexPolytope prism_polytope(const FlatPolygon& polygon, double thickness) {
  ConvexPolytope prism;
  const int n = static_cast<int>(polygon.corners.size());
  prism.vertices = polygon.corners;
  prism.vertex_ids = polygon.corner_vertices;
  std::vector<int> top(n), bottom(n);
  for (int i = 0; i < n; ++i) top[i] = i;
  const Plane& front = polygon.plane;
  Plane back{-front.normal, -(front.offset - thickness)};
  if (thickness > 0.0) {
    for (int i = 0; i < n; ++i) {
      prism.vertices.push_back(polygon.corners[i] - thickness * front.normal);
      prism.vertex_ids.push_back(-1);
    }
    // The bottom corner under top corner i is n + i; the back facet runs
    // backwards so it is counter-clockwise seen from behind.
    for (int i = 0; i < n; ++i) bottom[i] = n + (n - 1 - i);
  } else {
    for (int i = 0; i < n; ++i) bottom[i] = n - 1 - i;
  }
  prism.facets.push_back(top);
  prism.planes.push_back(front);
  prism.facets.push_back(bottom);
  prism.planes.push_back(back);
  if (thickness > 0.0) {
    for (int i = 0; i < n; ++i) {
      const int j = (i + 1) % n;
      prism.facets.push_back({i, n + i, n + j, j});
      prism.planes.push_back(polygon.sides[i]);
    }
  } else {
    prism.planes.insert(prism.planes.end(), polygon.sides.begin(), polygon.sides.end());
  }
  return prism;
}

double allowed_prism_thickness(const SceneIndex& index, const FlatPolygon& polygon,
                               const std::function<bool(int)>& in_patch, double cap, std::vector<int>& scratch) {
  const double tol = index.tol();
  const Mesh& mesh = index.mesh();
  const Eigen::Vector3d& n = polygon.plane.normal;
  Aabb region = bounding_box_of(polygon.corners);
  for (const Eigen::Vector3d& c : polygon.corners) region.extend(c - cap * n);
  region = grown(region, tol);

  double thickness = cap;
  scratch.clear();
  index.face_tree.overlapping(region, scratch);
  std::vector<Eigen::Vector3d> triangle(3);
  for (int f : scratch) {
    if (in_patch(f)) continue;
    for (int k = 0; k < 3; ++k) triangle[k] = mesh.positions[mesh.triangles[f][k]];
    const std::vector<Eigen::Vector3d> part = clip_to_column(triangle, polygon, tol);
    if (part.empty()) continue;
    double shallowest = depth_below(polygon, part[0]), deepest = shallowest;
    for (const Eigen::Vector3d& p : part) {
      shallowest = std::min(shallowest, depth_below(polygon, p));
      deepest = std::max(deepest, depth_below(polygon, p));
    }
    if (deepest < -tol) continue;  // wholly in front of the polygon
    if (deepest <= tol) {
      // Lies on the polygon: harmless unless it faces into the prism (the
      // back of a double-sided wall), whose front space a prism would fill.
      if (index.face_normals[f].dot(n) < 0.0) return 0.0;
      continue;
    }
    thickness = std::min(thickness, std::max(shallowest, 0.0));
  }

  scratch.clear();
  index.bar_tree.overlapping(region, scratch);
  for (int b : scratch) {
    const BoundaryBar& bar = index.bars[b];
    std::vector<Eigen::Vector3d> segment = {bar.a, bar.b};
    segment = clip_to_column(segment, polygon, tol);
    if (segment.empty()) continue;
    double shallowest = depth_below(polygon, segment[0]), deepest = shallowest;
    for (const Eigen::Vector3d& p : segment) {
      shallowest = std::min(shallowest, depth_below(polygon, p));
      deepest = std::max(deepest, depth_below(polygon, p));
    }
    if (deepest > tol) thickness = std::min(thickness, std::max(shallowest, 0.0));
  }
  return thickness < kMinThicknessInTolerances * tol ? 0.0 : thickness;
}

} // namespace hullcover
