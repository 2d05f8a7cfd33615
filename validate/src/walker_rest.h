#pragma once
/// \file walker_rest.h
/// Where a walker at a point rests on a walkable face, for the movement
/// audit's standing test (agent_lattice.cpp): the part of the face within
/// its height range, the distance to it across up, and the lowest point of
/// it under the walker's circle.

#include "audit_agent.h"

#include "hullcover/geometry/mesh.h"

#include <Eigen/Core>

#include <vector>

namespace hullcover::validate::detail {

/// The part of triangle `f` whose height, as up measures it, lies in
/// [low, high]: where a walker standing at height `high` may rest.
std::vector<Eigen::Vector3d> face_in_slab(const Mesh& mesh, const AuditAgent& agent, int f, double low, double high);

/// The 2D distance, across up, from p to convex `polygon` (face_in_slab);
/// infinity when it is empty.
double across_distance(const AuditAgent& agent, const std::vector<Eigen::Vector3d>& polygon, const Eigen::Vector3d& p);

/// The lowest height, as up measures it, of the part of `polygon` (a face
/// in its slab) within r across up of p: the lowest point a walker at p
/// may rest on. Infinity when there is none.
double lowest_rest_near(const AuditAgent& agent, const std::vector<Eigen::Vector3d>& polygon, const Eigen::Vector3d& p);

} // namespace hullcover::validate::detail
