#pragma once
/// \file loss_allowance.h
/// The free space a covering may take beyond exact mode, when the user asks
/// (README "Agent-exact coverings"). Exact mode rejects a hull as
/// soon as one witness ray (witness_rays.h) finds free space inside it. With
/// an allowance, the space that piece of rays can lose is first bounded by a
/// convex polytope L (every point a ray of the piece has inside the hull
/// before its first mesh hit lies in L), and the loss is allowed when every
/// point of L is proved harmless:
///
///  - agent radius r: no ball of radius r that touches no triangle reaches
///    into L. Such a ball's centre c has clearance (distance to the nearest
///    triangle) >= r and lies within r of L; so L is harmless when every
///    point within r of L has clearance < r.
///  - max deviation E: every point of L lies within E of some triangle.
///
/// Both are proved by cutting the box to check into cells: a cell whose
/// centre has clearance d and whose half-diagonal is h holds only points of
/// clearance <= d + h (clearance is 1-Lipschitz), and one whose centre lies
/// at least h + r outside a plane of L holds no point within r of L. A cell
/// neither proves is halved; after kMaxAllowanceCells cells, at a cell no
/// wider than tol still open, or at a centre that is itself a
/// counterexample, the loss is not allowed. Conservative,
/// never optimistic: an allowed loss is proved, a refused one may not be
/// harmful (L is larger than the loss; a ball counted as reaching in may sit
/// in enclosed space).

#include "validity/free_space_sweep.h"
#include "validity/scene_index.h"

#include <vector>

namespace hullcover::detail {

/// How many cells one proof may visit before it gives up (and the loss is
/// refused): a bound on the work, where giving up is conservative.
inline constexpr int kMaxAllowanceCells = 128;

/// True when the user's allowance covers every point of the convex
/// polytope `lost` (the points behind every plane of it, all within `box`):
/// with both knobs set, both must (each is a promise the user relies on:
/// agents of radius r lose nothing, and no loss lies farther than E).
/// `within_deviation_known` skips the E proof when the caller has already
/// bounded the loss within E. `lost_point` is a point known to be lost (a
/// counterexample found near it ends the proof early). False when no
/// allowance is set.
bool loss_allowed(const SceneIndex& index, const std::vector<Plane>& lost, const Aabb& box,
                  const Eigen::Vector3d& lost_point, bool within_deviation_known = false);

/// With an allowance: true when the free space the rays of `sweep` through
/// convex `region` (on a facet of `interior`, where they enter it) can lose
/// is allowed. That space lies inside the interior, within the region's
/// column along the sweep, and no farther from the rays' base than their
/// first mesh hit, which first_hit_bound_over (witness_rays.h) bounds over
/// the region. False without an allowance.
bool piece_loss_allowed(const SceneIndex& index, const FreeSpaceSweep& sweep, const HullInterior& interior,
                        const std::vector<Eigen::Vector3d>& region, std::vector<int>& scratch);

} // namespace hullcover::detail
