#pragma once
// How far a sweep's rays run before they first meet a face: where the free
// space the exact conditions keep ends, so a sweep need reach no farther
// (scene_index.h), and how far a re-bake follows a sweep's rays to see
// whether an edit crosses them (scene_change.h). Decided like the witness
// rays (witness_rays.h), piece by piece. Internal to the decomposer.

#include "validity/scene_index.h"

#include <vector>

namespace hullcover::detail {

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
