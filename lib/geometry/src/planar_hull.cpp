#include "hullcover/geometry/planar_hull.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <numeric>

namespace hullcover {

PlaneFrame PlaneFrame::from_normal(const Eigen::Vector3d& origin, const Eigen::Vector3d& unit_normal) {
  PlaneFrame f;
  f.origin = origin;
  f.normal = unit_normal;
  // Start from the world axis least aligned with the normal, for a
  // well-conditioned cross product.
  Eigen::Index axis = 0;
  unit_normal.cwiseAbs().minCoeff(&axis);
  f.u = unit_normal.cross(Eigen::Vector3d::Unit(axis)).normalized();
  f.v = unit_normal.cross(f.u);
  return f;
}

namespace {
double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Distance of p from the line through a and b (a != b).
double distance_to_line(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return std::abs(cross(a, b, p)) / (b - a).norm();
}
} // namespace

std::vector<int> convex_hull_2d(const std::vector<Eigen::Vector2d>& points, double tol) {
  if (points.size() < 3) return {};
  std::vector<int> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    if (points[a].y() != points[b].y()) return points[a].y() < points[b].y();
    if (points[a].x() != points[b].x()) return points[a].x() < points[b].x();
    return a < b;
  });
  // Andrew's monotone chain on the exact orientation (the tolerance is
  // applied afterwards: popping with a tolerance here can drop a true
  // extreme point when a later point is nearly collinear but behind it).
  std::vector<int> hull;
  hull.reserve(order.size() + 1);
  for (int pass = 0; pass < 2; ++pass) {
    const size_t chain_start = hull.size();
    for (int idx : order) {
      while (hull.size() >= chain_start + 2 &&
             cross(points[hull[hull.size() - 2]], points[hull.back()], points[idx]) <= 0.0)
        hull.pop_back();
      hull.push_back(idx);
    }
    hull.pop_back(); // the chain's last point starts the other chain
    std::reverse(order.begin(), order.end());
  }
  // Drop corners within tol of their neighbours or of the line through them;
  // each removal moves the boundary inward by at most tol.
  bool changed = true;
  while (changed && hull.size() >= 3) {
    changed = false;
    for (size_t i = 0; i < hull.size() && hull.size() >= 3; ++i) {
      const Eigen::Vector2d& prev = points[hull[(i + hull.size() - 1) % hull.size()]];
      const Eigen::Vector2d& here = points[hull[i]];
      const Eigen::Vector2d& next = points[hull[(i + 1) % hull.size()]];
      const bool duplicate = (here - prev).squaredNorm() <= tol * tol || (here - next).squaredNorm() <= tol * tol;
      if (duplicate || (next - prev).squaredNorm() <= tol * tol || distance_to_line(here, prev, next) <= tol) {
        hull.erase(hull.begin() + static_cast<long>(i));
        changed = true;
        --i;
      }
    }
  }
  if (hull.size() < 3) hull.clear();
  return hull;
}

Eigen::Vector3d centroid_of(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) c += p;
  return c / static_cast<double>(points.size());
}

std::vector<Plane> polygon_side_planes(const std::vector<Eigen::Vector3d>& corners, const Eigen::Vector3d& normal) {
  std::vector<Plane> planes;
  planes.reserve(corners.size());
  for (size_t i = 0; i < corners.size(); ++i) {
    const Eigen::Vector3d& a = corners[i];
    const Eigen::Vector3d& b = corners[(i + 1) % corners.size()];
    Plane p;
    p.normal = (b - a).cross(normal).normalized(); // counter-clockwise: edge x normal points out
    p.offset = p.normal.dot(a);
    planes.push_back(p);
  }
  return planes;
}

} // namespace hullcover

namespace hullcover {

std::pair<double, double> extent_along(const Eigen::Vector3d* positions, const std::vector<int>& vertex_ids,
                                       const Eigen::Vector3d& normal) {
  double low = normal.dot(positions[vertex_ids.front()]), high = low;
  for (int v : vertex_ids) {
    low = std::min(low, normal.dot(positions[v]));
    high = std::max(high, normal.dot(positions[v]));
  }
  return {low, high};
}

FlatPolygon make_flat_polygon(const Eigen::Vector3d* positions, const std::vector<int>& vertex_ids,
                              const Eigen::Vector3d& normal, double tol) {
  FlatPolygon polygon;
  if (vertex_ids.empty()) return polygon;
  // The middle of their slab: no point is farther from the plane than half
  // its width (a mean would leave a lone point up to the whole width off).
  const auto [low, high] = extent_along(positions, vertex_ids, normal);
  const double offset = 0.5 * (low + high);
  const PlaneFrame frame = PlaneFrame::from_normal(positions[vertex_ids.front()], normal);
  std::vector<Eigen::Vector2d> projected;
  projected.reserve(vertex_ids.size());
  for (int v : vertex_ids) projected.push_back(frame.to_plane(positions[v]));
  const std::vector<int> hull = convex_hull_2d(projected, tol);
  if (hull.size() < 3) return polygon;
  polygon.plane = {normal, offset};
  for (int i : hull) {
    const Eigen::Vector3d& p = positions[vertex_ids[i]];
    polygon.corners.push_back(p - (normal.dot(p) - offset) * normal);
    polygon.corner_vertices.push_back(vertex_ids[i]);
  }
  polygon.sides = polygon_side_planes(polygon.corners, normal);
  return polygon;
}

FlatPolygon flat_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  FlatPolygon triangle;
  triangle.corners = {a, b, c};
  triangle.corner_vertices = {-1, -1, -1};
  const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
  triangle.plane = {n, n.dot(a)};
  triangle.sides = polygon_side_planes(triangle.corners, n);
  return triangle;
}

bool meets_polygon_interior(const FlatPolygon& polygon, const std::vector<Eigen::Vector3d>& part, double tol) {
  std::vector<Eigen::Vector3d> on_plane = clip_polygon(part, polygon.plane, -tol);
  on_plane = clip_polygon(on_plane, polygon.plane.flipped(), -tol);
  return !clip_polygon_to_planes(std::move(on_plane), polygon.sides, tol).empty();
}

ConvexPolytope flat_polytope(const FlatPolygon& polygon, bool side_planes) {
  ConvexPolytope flat;
  flat.vertices = polygon.corners;
  flat.vertex_ids = polygon.corner_vertices;
  std::vector<int> front(polygon.corners.size());
  for (size_t i = 0; i < front.size(); ++i) front[i] = static_cast<int>(i);
  flat.facets = {front, std::vector<int>(front.rbegin(), front.rend())};
  flat.planes = {polygon.plane, polygon.plane.flipped()};
  if (side_planes) flat.planes.insert(flat.planes.end(), polygon.sides.begin(), polygon.sides.end());
  return flat;
}

} // namespace hullcover
