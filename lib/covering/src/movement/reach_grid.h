#pragma once
/// \file reach_grid.h
/// The reach grid: a superset, cell by cell, of the centres an agent can
/// occupy (docs/definitions-and-proofs.md, "Movement coverings"). A cell is
/// kept when it may hold a reachable centre; a cell left out holds none.
/// Exact where it matters: hulls are never judged on cells alone, only
/// cleared by them (movement_validity.h decides the rest with distances).

#include "movement/reach_cells.h"
#include "movement/scene_clearance.h"

#include "hullcover/covering/movement_options.h"

#include <cstdint>
#include <vector>

namespace hullcover::detail {

/// The reach grid of `mesh` for `agent`, from `seeds` (each already checked
/// to have clearance >= r; empty: all clear space, flying). Fails with
/// `limit_exceeded` when the grid would exceed kMostReachCells (or 2^21
/// cells along an axis) or kMostReachCellsHeld, and, when
/// `seeds_given` (the user's spawn points), with `invalid_argument` for a
/// seed no agent of this reach occupies; default seeds there are passed
/// over (a walkable face under a low ceiling).
Result<ReachGrid> build_reach_grid(const Mesh& mesh, const SceneClearance& clearance, const AgentShape& agent,
                                   const std::vector<Eigen::Vector3d>& seeds, bool seeds_given, int threads);

/// Whether face `face` may be touched by an agent: some reachable cell lies
/// within r of it (the cell's centre within r plus half its diagonal).
bool face_may_be_touched(const ReachGrid& grid, const SceneClearance& clearance, const AgentShape& agent, int face);

/// The default seeds: over each walkable face, the points r (and 2 tol)
/// in front of its centroid and of the middles between the centroid and
/// its corners, where their clearance is at least r.
std::vector<Eigen::Vector3d> default_seeds(const SceneClearance& clearance, const AgentShape& agent, double tol);

/// Whether triangle `face` is walkable for `agent` (its normal within the
/// slope of up). Zero-area faces are not.
bool is_walkable(const Mesh& mesh, const AgentShape& agent, int face);

} // namespace hullcover::detail
