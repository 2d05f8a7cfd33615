#pragma once
// The hull a finished patch becomes (paper 4.3, "Convex hull output"): a
// prism under a planar patch, the Qhull rebuild of a solid one. Each cell
// makes its patches' hulls as soon as it is merged (so a cell result, moved
// between processes or kept in the cell cache, carries them); the finish
// makes hulls again only for patches the seam pass changed.

#include "hullcover/covering/convex_hull_3d.h"
#include "hullcover/covering/covering_types.h"

#include "merging/patch_merging.h"

#include <vector>

namespace hullcover::detail {

struct DecompositionStages;

/// A patch's hull, with what the statistics count of its making.
struct PatchHull {
  CoveringHull hull; ///< `cell` is left 0: the finish sets it
  /// A solid patch whose Qhull rebuild failed its checks: the hull is the
  /// solid as grown during merging.
  bool kept_as_grown = false;
};

/// The prism cap of `patch`: the user's, else the largest island's among
/// its faces' (kDefaultPrismCapRelative times its diagonal), scene units.
double prism_cap_of(const DecompositionStages& stages, const Patch& patch);

/// The hull of patch `id` of `merger`, checked on `index` (the view the
/// patch was merged with). `builder` and `scratch` are reused storage.
/// Deterministic: the same patch in the same scene gives the same hull,
/// bit for bit, whichever merger holds it. Throws only std::bad_alloc.
PatchHull make_patch_hull(const DecompositionStages& stages, const SceneIndex& index, const PatchMerger& merger, int id,
                          ConvexHullBuilder& builder, std::vector<int>& scratch);

/// Adds to `stats` what making `made` counted: a Qhull call per solid, a
/// prism made flat, a solid kept as grown.
void count_hull_making(CoveringStatistics& stats, const PatchHull& made);

/// Whether two hulls are the same, bit for bit (polytope, thickness,
/// volume, surface planes, faces, material).
bool same_hull(const PatchHull& a, const PatchHull& b);

} // namespace hullcover::detail
