#pragma once
/// \file triangle_distance.h
/// The nearest point of a triangle to a point: what "clearance from the
/// mesh" means for the agent-radius and max-deviation allowances and their
/// audit.

#include <Eigen/Core>

namespace hullcover {

/// The point of triangle a, b, c nearest to `p` (a degenerate triangle
/// gives the nearest point of its three sides). Scene units; cannot fail.
Eigen::Vector3d closest_point_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                          const Eigen::Vector3d& c);

/// The point of segment a-b nearest to `p` (`a` when a = b).
Eigen::Vector3d closest_point_on_segment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b);

} // namespace hullcover
