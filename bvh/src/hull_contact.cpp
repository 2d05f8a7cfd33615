#include "hullcover/bvh/hull_contact.h"

#include "nearest_edges.h"
#include "planes_ray_hit.h"
#include "separating_axes.h"
#include "surface_normals.h"

#include "hullcover/geometry/tolerances.h"
#include "hullcover/geometry/triangle_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hullcover::bvh {
namespace {

using detail::touching_distance;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Is q (on facet f's plane) inside its polygon?
bool inside_facet(const RuntimeHull& hull, int f, const Eigen::Vector3d& q) {
  const Eigen::Vector3d& n = hull.shape.planes[f].normal;
  const std::vector<int>& poly = hull.shape.facets[f];
  for (size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector3d& a = hull.shape.vertices[poly[i]];
    const Eigen::Vector3d& b = hull.shape.vertices[poly[(i + 1) % poly.size()]];
    if ((b - a).cross(n).dot(q - a) > 0.0) return false;
  }
  return true;
}

// Calls visit(a, b) with the ends of each edge of the hull once, until it
// returns true: its edge list, or for a hull made by hand without one its
// facets' sides (each then twice, which finds nothing else).
template <typename Visit>
void for_each_edge(const RuntimeHull& hull, Visit&& visit) {
  const std::vector<Eigen::Vector3d>& v = hull.shape.vertices;
  if (!hull.edges.empty()) {
    for (const auto& [a, b] : hull.edges)
      if (visit(v[a], v[b])) return;
    return;
  }
  for (const std::vector<int>& poly : hull.shape.facets)
    for (size_t i = 0; i < poly.size(); ++i)
      if (visit(v[poly[i]], v[poly[(i + 1) % poly.size()]])) return;
}

// The nearest of a hull's edges to a point or segment, by squared
// distance: one root at the end instead of one per edge. `offer` returns
// true once a pair within `good_enough` is found (the test a yes/no query
// stops at), decided on the root itself as the caller's comparison with a
// radius is.
struct NearestOfEdges {
  double squared;
  double good_enough;
  double good_enough_squared; // -1 when nothing is good enough
  bool won = false;
  Eigen::Vector3d on_hull = Eigen::Vector3d::Zero(), on_other = Eigen::Vector3d::Zero();

  NearestOfEdges(double distance_so_far, double enough)
      : squared(distance_so_far * distance_so_far), good_enough(enough),
        good_enough_squared(enough >= 0.0 ? enough * enough : -1.0) {}
  bool offer(double d2, const Eigen::Vector3d& hull_point, const Eigen::Vector3d& other_point) {
    if (d2 < squared) {
      squared = d2;
      on_hull = hull_point;
      on_other = other_point;
      won = true;
      return squared <= good_enough_squared && std::sqrt(squared) <= good_enough;
    }
    return false;
  }
};

// How far a signed distance from one of the hull's planes may be off by
// rounding: far below kTouchingFraction of the sizes entering it.
inline double signed_distance_slack(const RuntimeHull& hull, const Eigen::Vector3d& p) {
  return kTouchingFraction * (1.0 + hull.box.diagonal() + p.cwiseAbs().maxCoeff());
}

// The facet plane p is least deep behind (p inside the hull).
int nearest_facet(const RuntimeHull& hull, const Eigen::Vector3d& p) {
  return detail::least_deep_plane(hull.shape.planes.data(), static_cast<int>(hull.shape.facets.size()), p);
}

} // namespace

namespace detail {
FrontFacet front_facet(const RuntimeHull& hull, const Eigen::Vector3d& p) {
  FrontFacet front;
  const int facets = static_cast<int>(hull.shape.facets.size());
  for (int i = 0; i < static_cast<int>(hull.shape.planes.size()); ++i) {
    const double d = hull.shape.planes[i].signed_distance(p);
    front.outside = std::max(front.outside, d);
    if (i < facets) {
      front.runner_up = std::max(front.runner_up, std::min(d, front.distance)); // the lesser of the two goes on
      if (d > front.distance) {
        front.distance = d;
        front.facet = i;
      }
    }
  }
  return front;
}

ClosestPoints closest_to_point_outside(const RuntimeHull& hull, const Eigen::Vector3d& p, const FrontFacet& front,
                                       double good_enough) {
  // Every plane supports the hull, so the distance is at least the largest
  // facet distance; when p projects inside that facet, it is attained there.
  if (front.distance > 0.0) {
    const Eigen::Vector3d foot = p - front.distance * hull.shape.planes[front.facet].normal;
    if (inside_facet(hull, front.facet, foot)) return {(foot - p).norm(), foot, p};
  }
  // Else the closest point is p's foot inside another facet p is in front
  // of, or it is on an edge. A facet holding the foot has p at least as far
  // in front of it as of the front facet (the foot is a hull point, so p's
  // distance is at most that facet's; and at least every facet's): only
  // the front facet's ties, to rounding, can (two triangles of one face
  // can tie), so the others' polygons are not tested. Each edge is tested
  // once, including those whose facets both face away from p: they are
  // never nearer, and knowing which they are costs as much as testing them
  // (measured). Normals are unit only to kUnitNormalSlack, which scales
  // the distances compared.
  const double tied =
      front.distance - signed_distance_slack(hull, p) - 4.0 * kUnitNormalSlack * std::abs(front.distance);
  ClosestPoints best{kInfinity, p, p};
  // No other facet within the ties' reach (the usual case): none to test.
  const int facets = front.runner_up >= tied ? static_cast<int>(hull.shape.facets.size()) : 0;
  for (int f = 0; f < facets; ++f) {
    const Plane& other = hull.shape.planes[f];
    const double d = other.signed_distance(p);
    if (f == front.facet || !(d >= 0.0) || d < tied || d >= best.distance) continue;
    const Eigen::Vector3d q = p - d * other.normal;
    if (inside_facet(hull, f, q)) best = {(q - p).norm(), q, p};
    if (best.distance <= good_enough) return best;
  }
  NearestOfEdges nearest(best.distance, good_enough);
  for_each_edge(hull, [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    const Eigen::Vector3d c = closest_point_on_segment(p, a, b);
    return nearest.offer((c - p).squaredNorm(), c, p);
  });
  return nearest.won ? ClosestPoints{std::sqrt(nearest.squared), nearest.on_hull, nearest.on_other} : best;
}

bool segment_meets_hull(const RuntimeHull& hull, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                        Eigen::Vector3d& meet) {
  double enter, leave;
  if (!clip_segment_to_hull(hull, a, b, 0.0, enter, leave)) return false;
  meet = a + (b - a) * (0.5 * (enter + leave));
  return true;
}

ClosestPoints closest_to_segment_apart(const RuntimeHull& hull, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                       double good_enough) {
  // Apart: the closest hull point is an end point's projection inside a
  // facet that end is in front of, or on an edge (segment to edge covers
  // end point to edge). Signed distances are linear along the segment, so
  // a facet the segment's closest point is in front of has an end in front:
  // the facets no end is in front of add nothing. A segment in a flat
  // hull's plane, beside its rim, is in front of neither face and is
  // separated by a side alone, which has no facet: its closest points are
  // on an edge.
  // Each edge once, first: the segment-to-segment closest points are the
  // cost, and a yes/no query often stops at the first edge near enough.
  const SegmentTerms segment(a, b);
  ClosestPoints best{kInfinity, a, a};
  if (good_enough < 0.0 && !hull.edges.empty()) {
    // The nearest edge wanted (a contact): every edge, two at a time.
    const NearestEdge nearest = nearest_edge_to_segment(segment, hull.shape.vertices, hull.edges, kInfinity);
    if (nearest.edge >= 0) best = {std::sqrt(nearest.squared), nearest.on_edge, nearest.on_segment};
  } else {
    NearestOfEdges nearest(kInfinity, good_enough);
    for_each_edge(hull, [&](const Eigen::Vector3d& u, const Eigen::Vector3d& w) {
      const auto [on_segment, on_edge] = closest_points_of_segments(segment, u, w);
      return nearest.offer((on_segment - on_edge).squaredNorm(), on_edge, on_segment);
    });
    if (nearest.won) best = {std::sqrt(nearest.squared), nearest.on_hull, nearest.on_other};
  }
  for (int f = 0; f < static_cast<int>(hull.shape.facets.size()) && best.distance > good_enough; ++f) {
    const Plane& plane = hull.shape.planes[f];
    for (const Eigen::Vector3d* end : {&a, &b}) {
      const double d = plane.signed_distance(*end);
      if (!(d >= 0.0) || d >= best.distance) continue;
      const Eigen::Vector3d q = *end - d * plane.normal;
      if (inside_facet(hull, f, q)) best = {d, q, *end};
    }
  }
  return best;
}
std::optional<std::pair<double, Eigen::Vector3d>> capsule_axis_push(const RuntimeHull& hull, const Eigen::Vector3d& a,
                                                                    const Eigen::Vector3d& b) {
  const Eigen::Vector3d axis = b - a;
  const int directions = axis.norm() > touching_distance(hull) ? 1 : 0;
  return smallest_push(
      hull, [&](auto&& f) { return for_each_axis(hull, &axis, directions, f); },
      [&](const Eigen::Vector3d& w) {
    return std::make_pair(std::min(a.dot(w), b.dot(w)), std::max(a.dot(w), b.dot(w)));
      });
}
} // namespace detail

ClosestPoints closest_to_point(const RuntimeHull& hull, const Eigen::Vector3d& p) {
  const detail::FrontFacet front = detail::front_facet(hull, p);
  if (front.outside <= 0.0) return {0.0, p, p};
  return detail::closest_to_point_outside(hull, p, front, -1.0);
}

ClosestPoints closest_to_segment(const RuntimeHull& hull, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  Eigen::Vector3d meet;
  if (detail::segment_meets_hull(hull, a, b, meet)) return {0.0, meet, meet};
  return detail::closest_to_segment_apart(hull, a, b, -1.0);
}

namespace {
// `found`, turned to a surface facet where the hull point it was found at
// lies on a plane the surface runs on past (surface_normals.h): the facet
// through the point facing the normal most, or, inside a seam side's face,
// the surface facet the shape's core is least deep behind. `lowest(plane)`
// is the signed distance from the plane of the shape's core (a sphere's
// centre, a capsule's axis) at its lowest; the depth along the facet follows.
template <typename Lowest>
Contact on_surface(const RuntimeHull& hull, const Contact& found, double radius, Lowest&& lowest) {
  if (!detail::has_plane_off_surface(hull)) return found; // every plane is the surface's: no seam to turn from
  // Rounding in the signed distances grows with the coordinates' size too.
  const double near = signed_distance_slack(hull, found.point);
  const detail::SeamTurn turn = detail::surface_facet_for(hull, found.point, found.normal, near);
  if (!turn.at_seam) return found;
  int s = turn.facet;
  if (s < 0) {
    double best = -std::numeric_limits<double>::infinity();
    for (int f = 0; f < static_cast<int>(hull.shape.facets.size()); ++f)
      if (hull.plane_on_surface(f) && lowest(hull.shape.planes[f]) > best) {
        best = lowest(hull.shape.planes[f]);
        s = f;
      }
  }
  if (s < 0) return found;
  const Plane& facet = hull.shape.planes[s];
  return Contact{-1, found.point, facet.normal, std::max(0.0, radius - lowest(facet))};
}

// `push` (a separating-axis push of a shape that meets the hull) or, where
// the hull has seams, the smallest push out through one of the surface's
// own facets (along its outward normal only) instead: a shape across a seam
// is never pushed out of a seam side. `project(w)` gives the shape's extent
// along w.
template <typename Project>
std::pair<double, Eigen::Vector3d> push_through_surface(const RuntimeHull& hull,
                                                        const std::pair<double, Eigen::Vector3d>& push,
                                                        Project&& project) {
  if (!detail::has_plane_off_surface(hull)) return push;
  std::pair<double, Eigen::Vector3d> best = {kInfinity, push.second};
  for (int k = 0; k < static_cast<int>(hull.shape.facets.size()); ++k) {
    if (!hull.plane_on_surface(k)) continue;
    const Eigen::Vector3d& n = hull.shape.planes[k].normal;
    const double out = detail::hull_extent(hull, n).second - project(n).first;
    if (out < best.first) best = {std::max(0.0, out), n};
  }
  return std::isfinite(best.first) ? best : push;
}
} // namespace

std::optional<Contact> sphere_contact(const RuntimeHull& hull, const Eigen::Vector3d& centre, double radius) {
  const detail::FrontFacet front = detail::front_facet(hull, centre);
  if (front.outside > radius) return std::nullopt; // a plane separates them: the usual case, and cheap
  if (front.outside <= 0.0) {
    // Inside: out through the nearest facet the surface has.
    int f = front.facet;
    if (!hull.plane_on_surface(f))
      if (const int s = detail::least_deep_surface_facet(hull, centre); s >= 0) f = s;
    const Plane& plane = hull.shape.planes[f];
    const double below = plane.signed_distance(centre);
    return Contact{-1, centre - below * plane.normal, plane.normal, radius - below};
  }
  const ClosestPoints c = detail::closest_to_point_outside(hull, centre, front, -1.0);
  if (c.distance > radius) return std::nullopt;
  const Eigen::Vector3d normal = c.distance > touching_distance(hull)
                                     ? Eigen::Vector3d((centre - c.on_hull) / c.distance)
                                     : hull.shape.planes[front.facet].normal;
  return on_surface(hull, Contact{-1, c.on_hull, normal, radius - c.distance}, radius,
                    [&](const Plane& facet) { return facet.signed_distance(centre); });
}

std::optional<Contact> capsule_contact(const RuntimeHull& hull, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                       double radius) {
  if (detail::segment_clear_of_grown_planes(hull, a, b, radius)) return std::nullopt; // the usual case, and cheap
  // The axis meets the hull: the separating axes give depth and normal.
  // (When one separates them, the clip met only by rounding: the axis is
  // then as good as touching, and the closest points below tell.)
  Eigen::Vector3d meet;
  std::optional<std::pair<double, Eigen::Vector3d>> push;
  if (detail::segment_meets_hull(hull, a, b, meet) && (push = detail::capsule_axis_push(hull, a, b))) {
    const auto [depth, normal] = push_through_surface(hull, *push, [&](const Eigen::Vector3d& w) {
      return std::make_pair(std::min(a.dot(w), b.dot(w)), std::max(a.dot(w), b.dot(w)));
    });
    const Eigen::Vector3d deepest = a.dot(normal) < b.dot(normal) ? a : b;
    return Contact{-1, deepest + depth * normal, normal, depth + radius};
  }
  const ClosestPoints c = detail::closest_to_segment_apart(hull, a, b, -1.0);
  if (c.distance > radius) return std::nullopt;
  // Apart by no more than rounding: closest points that near are noise in
  // direction, so the facet the axis is most in front of gives the normal.
  const Eigen::Vector3d normal = c.distance > touching_distance(hull)
                                     ? Eigen::Vector3d((c.on_other - c.on_hull) / c.distance)
                                     : hull.shape.planes[nearest_facet(hull, c.on_other)].normal;
  return on_surface(hull, Contact{-1, c.on_hull, normal, radius - c.distance}, radius,
                    [&](const Plane& facet) { return std::min(facet.signed_distance(a), facet.signed_distance(b)); });
}

std::optional<Contact> box_contact(const RuntimeHull& hull, const Eigen::Isometry3d& pose,
                                   const Eigen::Vector3d& half_extents) {
  const Eigen::Matrix3d& r = pose.linear();
  const Eigen::Vector3d centre = pose.translation();
  const Eigen::Vector3d directions[3] = {r.col(0), r.col(1), r.col(2)};
  const auto push = detail::smallest_push(
      hull, [&](auto&& f) { return detail::for_each_axis(hull, directions, 3, f); },
      [&](const Eigen::Vector3d& w) { return detail::box_extent(pose, half_extents, w); });
  if (!push) return std::nullopt;
  const auto [depth, normal] = push_through_surface(
      hull, *push, [&](const Eigen::Vector3d& w) { return detail::box_extent(pose, half_extents, w); });
  // The box corner deepest along -normal, moved back onto the hull's surface.
  Eigen::Vector3d corner = centre;
  for (int k = 0; k < 3; ++k) corner -= (r.col(k).dot(normal) >= 0.0 ? 1.0 : -1.0) * half_extents[k] * r.col(k);
  return Contact{-1, corner + depth * normal, normal, depth};
}

std::optional<Contact> convex_contact(const RuntimeHull& hull, const RuntimeHull& shape) {
  const auto push = detail::smallest_push(
      hull, [&](auto&& f) { return detail::for_each_axis_between(hull, shape, f); },
      [&](const Eigen::Vector3d& w) { return detail::hull_extent(shape, w); });
  if (!push) return std::nullopt;
  const auto [depth, normal] =
      push_through_surface(hull, *push, [&](const Eigen::Vector3d& w) { return detail::hull_extent(shape, w); });
  Eigen::Vector3d deepest = shape.shape.vertices.front();
  for (const Eigen::Vector3d& v : shape.shape.vertices)
    if (v.dot(normal) < deepest.dot(normal)) deepest = v;
  return Contact{-1, deepest + depth * normal, normal, depth};
}

ClosestPoints closest_between(const RuntimeHull& hull, const RuntimeHull& shape) {
  if (convex_contact(hull, shape)) {
    // They meet: "distance 0" needs no exact common point, so the hull point
    // nearest one vertex of the shape (that vertex when it is inside) only
    // locates the meeting; it need not lie in the shape.
    const Eigen::Vector3d& p = shape.shape.vertices.front();
    const ClosestPoints c = closest_to_point(hull, p);
    return {0.0, c.on_hull, c.on_hull};
  }
  ClosestPoints best{kInfinity, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  for (const Eigen::Vector3d& v : shape.shape.vertices) {
    const ClosestPoints c = closest_to_point(hull, v);
    if (c.distance < best.distance) best = {c.distance, c.on_hull, v};
  }
  for (const Eigen::Vector3d& v : hull.shape.vertices) {
    const ClosestPoints c = closest_to_point(shape, v);
    if (c.distance < best.distance) best = {c.distance, v, c.on_hull};
  }
  for (const auto& [u, w] : hull.edges)
    for (const auto& [x, y] : shape.edges) {
      const auto [on_hull, on_shape] = closest_points_of_segments(hull.shape.vertices[u], hull.shape.vertices[w],
                                                                  shape.shape.vertices[x], shape.shape.vertices[y]);
      const double d = (on_hull - on_shape).norm();
      if (d < best.distance) best = {d, on_hull, on_shape};
    }
  return best;
}

RuntimeHull placed_box(const Eigen::Isometry3d& pose, const Eigen::Vector3d& half_extents) {
  ConvexPolytope box;
  for (int i = 0; i < 8; ++i)
    box.vertices.push_back(pose * Eigen::Vector3d(i & 1 ? half_extents.x() : -half_extents.x(),
                                                  i & 2 ? half_extents.y() : -half_extents.y(),
                                                  i & 4 ? half_extents.z() : -half_extents.z()));
  // Corner i has +x at bit 0, +y at bit 1, +z at bit 2; sides counter-clockwise from outside.
  static const int kSides[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  static const int kAxis[6] = {0, 0, 1, 1, 2, 2};
  for (int f = 0; f < 6; ++f) {
    box.facets.emplace_back(kSides[f], kSides[f] + 4);
    const Eigen::Vector3d n = pose.linear().col(kAxis[f]) * (f % 2 ? 1.0 : -1.0);
    box.planes.push_back({n, n.dot(pose.translation()) + half_extents[kAxis[f]]});
  }
  return make_runtime_hull(std::move(box), 0);
}

std::optional<RayHit> ray_hit(const RuntimeHull& hull, const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                              double max_t) {
  return detail::first_hit_on_planes(hull.shape.planes.data(), static_cast<int>(hull.shape.planes.size()),
                                     static_cast<int>(hull.shape.facets.size()), origin, direction, max_t);
}

} // namespace hullcover::bvh
