// The yes/no tests: each takes the same decisions, in the same arithmetic,
// as its contact in hull_contact.cpp, and stops as soon as the answer is
// known.

#include "hullcover/bvh/hull_contact.h"

#include "separating_axes.h"

namespace hullcover::bvh {

bool sphere_touches(const RuntimeHull& hull, const Eigen::Vector3d& centre, double radius) {
  const detail::FrontFacet front = detail::front_facet(hull, centre);
  if (front.outside > radius) return false;
  if (front.outside <= 0.0) return true;
  return detail::closest_to_point_outside(hull, centre, front, radius).distance <= radius;
}

bool capsule_touches(const RuntimeHull& hull, const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius) {
  if (detail::segment_clear_of_grown_planes(hull, a, b, radius)) return false;
  Eigen::Vector3d meet;
  // As capsule_contact: a clip that meets only by rounding falls through.
  if (detail::segment_meets_hull(hull, a, b, meet) && detail::capsule_axis_push(hull, a, b)) return true;
  return detail::closest_to_segment_apart(hull, a, b, radius).distance <= radius;
}

bool box_touches(const RuntimeHull& hull, const Eigen::Isometry3d& pose, const Eigen::Vector3d& half_extents) {
  const Eigen::Matrix3d& r = pose.linear();
  const Eigen::Vector3d directions[3] = {r.col(0), r.col(1), r.col(2)};
  return detail::no_separating_axis(
      hull, [&](auto&& f) { return detail::for_each_axis(hull, directions, 3, f); },
      [&](const Eigen::Vector3d& w) { return detail::box_extent(pose, half_extents, w); });
}

bool convex_touches(const RuntimeHull& hull, const RuntimeHull& shape) {
  return detail::no_separating_axis(
      hull, [&](auto&& f) { return detail::for_each_axis_between(hull, shape, f); },
      [&](const Eigen::Vector3d& w) { return detail::hull_extent(shape, w); });
}

} // namespace hullcover::bvh
