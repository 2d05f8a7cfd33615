#pragma once
// Witness rays: how the exact conditions (exact_conditions.h) judge a
// region of free space entering a hull, the way the audit's probe judges
// its rays. Internal to the decomposer.

#include "validity/free_space_sweep.h"
#include "validity/scene_index.h"
#include "validity/shadow_pieces.h"

#include <vector>

namespace hullcover::detail {

/// Storage region_loses_space and the exact checks around it reuse from
/// call to call: one is made for each hull check and serves every sweep
/// and piece that check judges, so that their hot path allocates only the
/// pieces it cuts. Never shared between threads; nothing in it carries
/// meaning from one call to the next.
struct SweepJudgeStorage {
  /// A piece waiting to be judged (settling_face -1), or one inside a
  /// face's shadow for that face to settle.
  struct Piece {
    std::vector<Eigen::Vector3d> corners;
    int settling_face = -1;
    bool enclosed = false;
  };
  /// The judge's stack of pieces still to judge.
  std::vector<Piece> pending;
  std::vector<int> faces; ///< tree look-ups
  std::vector<int> near;  ///< faces near a piece's column
  /// A piece cut along its deciding face's shadow.
  ShadowSplit split;
  /// A piece cut along the shadow of a face met from the front between the
  /// entry and the settling face: settle_by_face leaves it here for the
  /// judge to stack.
  ShadowSplit near_split;
  /// One face's corners.
  std::vector<Eigen::Vector3d> triangle = std::vector<Eigen::Vector3d>(3);
  /// Polygons sweep_enters_hull cuts on the way to a region.
  std::vector<Eigen::Vector3d> part, through, spare;
};

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
/// not settled in kMaxJudgedPieces pieces counts as losing space. `storage`
/// is reused storage (its `part`, `through` and `spare` are left alone, so
/// `region` may be one of them).
bool region_loses_space(const SceneIndex& index, const FreeSpaceSweep& sweep, const HullInterior& interior,
                        const std::vector<Eigen::Vector3d>& region, SweepJudgeStorage& storage);

} // namespace hullcover::detail
