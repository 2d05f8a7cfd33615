#pragma once
/// \file hull_contact.h
/// Exact narrow phase of a query shape against one convex hull, from the
/// hull's own facet planes (FCL 0.7's contacts on fcl::Convex come from
/// libccd's MPR and are often wrong in depth and normal; its EPA can abort
/// the process: see docs/design.md).
///
/// Normal convention, on every path: the contact normal is a unit vector
/// pointing OUT of the world hull, towards the query shape; moving the
/// shape by `depth * normal` separates it (to touching). `point` lies on the
/// hull's surface.
///
/// Penetration is found by the separating-axis test over every axis the
/// Minkowski difference can have (hull face normals, the shape's face
/// normals, and cross products of their edge directions), so depth and
/// normal are exact, not iterated. One exception, for spheres and capsules
/// on hulls with seam flags (RuntimeHull::surface_planes): where the
/// contact lies on a plane the surface runs on past, the normal is the
/// surface facet's there and the depth is measured along it, so the
/// contact still separates but is not the smallest push.

#include "hullcover/bvh/query_types.h"
#include "hullcover/bvh/runtime_hull.h"

#include <Eigen/Geometry>

#include <optional>

namespace hullcover::bvh {

/// Distance from `p` to the hull (0 inside) and the closest hull point.
ClosestPoints closest_to_point(const RuntimeHull& hull, const Eigen::Vector3d& p);

/// Distance from segment a-b to the hull (0 when they meet).
ClosestPoints closest_to_segment(const RuntimeHull& hull, const Eigen::Vector3d& a, const Eigen::Vector3d& b);

/// Sphere (centre, radius > 0) against the hull: a contact when they
/// overlap or touch, nothing when apart.
std::optional<Contact> sphere_contact(const RuntimeHull& hull, const Eigen::Vector3d& centre, double radius);

/// Capsule (segment a-b, radius > 0) against the hull.
std::optional<Contact> capsule_contact(const RuntimeHull& hull, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                       double radius);

/// Box (`pose` of its centre, half extents > 0) against the hull.
std::optional<Contact> box_contact(const RuntimeHull& hull, const Eigen::Isometry3d& pose,
                                   const Eigen::Vector3d& half_extents);

/// Convex shape (as a closed runtime hull already placed in the world)
/// against the hull: separating axes over both shapes' face normals and
/// every pair of edge directions. Cost grows with edges x edges.
std::optional<Contact> convex_contact(const RuntimeHull& hull, const RuntimeHull& shape);

/// The yes/no forms of the four contacts above: true exactly when the
/// matching *_contact gives a contact (overlapping or touching), as they
/// make every decision alike, but without computing depth or normal, and
/// without allocating. Most pairs a query meets are settled by one plane.
bool sphere_touches(const RuntimeHull& hull, const Eigen::Vector3d& centre, double radius);
/// Capsule (segment a-b, radius > 0); see sphere_touches.
bool capsule_touches(const RuntimeHull& hull, const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius);
/// Box (`pose` of its centre, half extents > 0); see sphere_touches.
bool box_touches(const RuntimeHull& hull, const Eigen::Isometry3d& pose, const Eigen::Vector3d& half_extents);
/// Convex shape placed in the world; see sphere_touches.
bool convex_touches(const RuntimeHull& hull, const RuntimeHull& shape);

/// Distance between the hull and a closed convex shape placed in the world
/// (0 when they meet), exactly: the smallest over vertex-to-hull,
/// hull-vertex-to-shape and edge-to-edge closest points. (FCL 0.7's GJK
/// distance between a box and an fcl::Convex was measured here to
/// overestimate by up to 27% at a few metres, which would let a sweep
/// tunnel.)
ClosestPoints closest_between(const RuntimeHull& hull, const RuntimeHull& shape);

/// A box (centre pose, half extents) as a closed runtime hull in the world.
RuntimeHull placed_box(const Eigen::Isometry3d& pose, const Eigen::Vector3d& half_extents);

/// First hit of the ray origin + t * direction (unit), 0 <= t <= max_t.
/// A ray starting inside the hull hits at t = 0 with the normal of the
/// nearest facet.
std::optional<RayHit> ray_hit(const RuntimeHull& hull, const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                              double max_t);

} // namespace hullcover::bvh
