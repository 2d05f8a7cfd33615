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

/// How many times a region is cut along the shadow of a face its
/// witnesses met, at most.
inline constexpr int kShadowSplits = 5;

/// True when rays of `sweep` through convex `region` (a polygon on a facet
/// of `interior`, where they enter it) lose free space. Judged by witness
/// rays on a grid over the region, pulled in off its edges where the mesh's
/// own edges lie; a ray loses space when it lies inside the interior before
/// its first mesh hit and within the reach, unless (front space) that hit
/// is the back of a face. Where a face that kept witnesses from losing
/// space does not shadow the whole region, or a face met from the front
/// shadows part of an enclosed region, the region is cut along that shadow
/// and each piece judged again, `splits_left` times at most. Exact up to
/// that sampling. `scratch` is reused storage.
bool region_loses_space(const SceneIndex& index, const FreeSpaceSweep& sweep, const HullInterior& interior,
                        const std::vector<Eigen::Vector3d>& region, std::vector<int>& scratch,
                        int splits_left = kShadowSplits);

} // namespace hullcover::detail
