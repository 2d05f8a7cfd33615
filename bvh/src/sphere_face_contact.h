#pragma once
// The contact of a sphere whose centre lies in front of one facet, nearer
// than its radius, with its foot on that facet inside the hull (private to
// bvh/): what the packed planes' float test certifies (packed_planes.h).

#include "hullcover/bvh/query_types.h"

#include <optional>

namespace hullcover::bvh::detail {

/// sphere_contact(hull, centre, radius), given that `facet` is the facet
/// the centre is farthest in front of (by more than rounding) and that its
/// foot on it is inside the facet: the same contact, bit for bit, without
/// the search for that facet and the test of the foot. Falls back to
/// sphere_contact where the arithmetic does not bear the premise out.
std::optional<Contact> sphere_contact_in_front_of(const RuntimeHull& hull, const Eigen::Vector3d& centre, double radius,
                                                  int facet);

} // namespace hullcover::bvh::detail
