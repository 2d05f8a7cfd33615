#pragma once
// Witness rays: how the exact conditions (exact_conditions.h) judge a
// region of free space entering a hull, the way the audit's probe judges
// its rays. Internal to the decomposer.

#include "free_space_sweep.h"
#include "scene_index.h"

#include <vector>

namespace hullcover::detail {

/// The outward planes of the column that convex polygon `outline` sweeps
/// along unit `dir`; edges running along dir (their sine with it within
/// kParallelSine) bound nothing and give no plane.
std::vector<Plane> column_planes(const std::vector<Eigen::Vector3d>& outline, const Eigen::Vector3d& dir);

/// How many pieces one region may be cut into before it counts as losing
/// space: a bound on the work, where giving up is conservative.
inline constexpr int kMaxJudgedPieces = 1024;

/// A piece of a region no wider than this many tolerances is a sliver of
/// rounding: passed over, as it holds no ray apart from its neighbours'.
inline constexpr double kNegligibleWidthInTolerances = 1e-6;

/// True when rays of `sweep` through convex `region` (a polygon on a facet
/// of `interior`, where they enter it) lose free space: a ray loses space
/// when it lies inside the interior before its first mesh hit and within
/// the reach, unless its first hit beyond the entry is the back of every
/// face met there (enclosed space). Decided exactly, piece by piece: a
/// piece's middle ray names the face that keeps it; within that face's
/// shadow the face decides every ray at once (distances along the rays are
/// affine over a piece, so its corners decide), cutting the piece where
/// that changes; the rest of the region is judged the same way. With an
/// allowance (agent radius, max deviation), a piece whose rays lose space
/// loses none when piece_loss_allowed (loss_allowance.h) proves its loss
/// harmless. A region
/// not settled in kMaxJudgedPieces pieces counts as losing space. `scratch` is
/// reused storage.
bool region_loses_space(const SceneIndex& index, const FreeSpaceSweep& sweep, const HullInterior& interior,
                        const std::vector<Eigen::Vector3d>& region, std::vector<int>& scratch);

/// An upper bound on how far any ray of `sweep` runs from its base before
/// its first mesh hit, scene units; infinity when some ray may meet
/// nothing. Found like region_loses_space: a piece's middle ray names the
/// face it meets, which bounds every ray through its shadow (the farthest
/// corner of the piece, distances being affine); the rest is cut into
/// pieces judged the same way. Slivers are passed over, as region_loses_space
/// passes them; after kMaxJudgedPieces pieces the
/// bound is infinity. The free space the exact conditions keep ends there,
/// so a sweep need reach no farther.
double first_hit_bound(const SceneIndex& index, const FreeSpaceSweep& sweep, std::vector<int>& scratch);

/// An upper bound, scene units, on where each ray of `sweep` first meets
/// a face past its stand-off in EVERY view of a tolerance between
/// finest.tol() and `coarsest_tol` (>= it): a view stands off by a multiple
/// of its tolerance, meets faces within it, and passes faces it runs along
/// within it, so a coarser view can pass the face that ends a ray in the
/// sweep's own and read a hit beyond its reach. Infinity as
/// first_hit_bound. What a re-bake follows a sweep's rays to
/// (scene_change.h).
double first_hit_bound_in_every_view(const SceneIndex& finest, const FreeSpaceSweep& sweep, double coarsest_tol,
                                     std::vector<int>& scratch);

/// first_hit_bound over the rays of `sweep` through convex polygon `region`
/// (anywhere along them) only.
double first_hit_bound_over(const SceneIndex& index, const FreeSpaceSweep& sweep,
                            const std::vector<Eigen::Vector3d>& region, std::vector<int>& scratch);

} // namespace hullcover::detail
