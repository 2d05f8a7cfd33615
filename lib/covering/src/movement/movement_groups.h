#pragma once
/// \file movement_groups.h
/// A group of faces and the hull of their corners, as the movement
/// merging keeps it, and the groups it starts from: a hull of the exact
/// covering's faces where that hull keeps the movement covering's promise
/// (movement_validity.h), every other face alone.

#include "movement/movement_validity.h"

#include "hullcover/covering/convex_hull_3d.h"
#include "hullcover/covering/movement_options.h"

#include <vector>

namespace hullcover::detail {

struct MovementGroup {
  std::vector<int> faces;   ///< mesh faces, ascending
  std::vector<int> corners; ///< mesh vertex ids of its hull's corners, ascending
  ConvexPolytope hull;
  bool flat = true;
  Aabb box; ///< of the hull
  double area = 0.0;
  Eigen::Vector3d area_vector = Eigen::Vector3d::Zero(); ///< sum of face normals x areas
  double boundary = 0.0;                                 ///< length of its faces' outline (edges not shared within it)
};

/// Builds `group.hull` from `group.corners` (and area_vector, or
/// `fallback_normal`, for a flat one), then keeps as corners the hull's
/// own; false when no hull of at most `max_hull_vertices` is made.
bool make_group_hull(const MovementContext& context, int max_hull_vertices, const Eigen::Vector3d& fallback_normal,
                     ConvexHullBuilder& builder, MovementGroup& group);

/// Where the proofs of one thread keep their scratch and counts.
struct GroupProver {
  ConvexHullBuilder builder;
  UncoveredBoundary boundary;
  long long candidates = 0; ///< hulls proven
  long long undecided = 0;  ///< proofs out of budget
};

/// The groups to merge from: the faces of `faces` (ascending) in each of
/// `start_groups` (the exact covering's hulls' faces, each ascending) as one
/// group where the hull of their corners keeps the promise, and every other
/// face of `faces` with an area alone (a face alone is the scene's own
/// surface). In the order of `start_groups`, then of `faces`.
std::vector<MovementGroup> starting_groups(const MovementContext& context, const std::vector<int>& faces,
                                           const std::vector<std::vector<int>>& start_groups, int max_hull_vertices,
                                           GroupProver& prover);

} // namespace hullcover::detail
