#pragma once
/// \file movement_validity.h
/// Whether a candidate hull keeps the movement covering's promise: no
/// reachable agent centre comes within r - E of it
/// (docs/definitions-and-proofs.md, "Movement coverings").
///
/// The proof, for a hull H that holds its faces:
///  1. every point of H's boundary that lies on no face of its own (the
///     uncovered boundary, uncovered_boundary.h) is proven at least r - E
///     from every reachable centre: within E of one triangle (then a centre
///     nearer than r - E would be nearer than r to that triangle), or of
///     one of two triangles on either side of a plane between them, or by
///     halving boxes of the space around it until each holds no reachable
///     centre (the reach grid clears it, or a triangle lies within r - tol / 8
///     of all of it, by its corners) or lies too far;
///  2. points of the boundary on faces are at least r from every centre;
///  3. H shrunk by r - E holds no reachable centre (the same halving).
/// A centre outside H is then at least r - E from it (its nearest point of
/// H is on the boundary); a centre inside H would be nearer than r - E to
/// the boundary or inside the shrunk hull. Neither can be.

#include "movement/movement_context.h"
#include "movement/uncovered_boundary.h"

#include <cstddef>
#include <vector>

namespace hullcover::detail {

/// The halving proofs of one hull give up after this many boxes (plus the
/// next), the
/// candidate is then refused (counted as undecided), never accepted on a
/// guess.
inline constexpr int kMostProofBoxes = 1 << 17;
/// ... and this many more per r^2 of uncovered boundary,
inline constexpr double kProofBoxesPerSquareRadius = 64.0;
/// ... and never more than this,
inline constexpr int kMostProofBoxesOfAHull = 1 << 18;
/// ... or at a box whose half-diagonal is below the slop times this,
inline constexpr double kSmallestProofBoxInSlops = 1.0 / 16.0;
/// ... or tol times this, if less: a box narrower than the gap between the
/// clearing and the witness thresholds below is always decided, but where
/// the reach grid's cells part it.
inline constexpr double kSmallestProofBoxInTols = 0.5;
/// A region's first box is along the region (a piece's column along the
/// piece's normal and its longest side, a side's along the side), widened
/// by this many tol on every side beyond the rounding of its corners.
inline constexpr double kProofBoxPaddingInTols = 1.0 / 64.0;
/// A box is cleared when every point of it lies nearer to a triangle than r
/// less this many tol: an agent's centre is at least r from every triangle,
/// and the margin is far above a distance's rounding. A point at clearance
/// r - tol or more is a witness, so the two leave a gap of 7/8 tol, and a
/// region that just touches where a centre may be (an agent resting on a
/// floor, exactly r - E under a hull) is decided by a witness, never
/// searched down to the smallest box.
inline constexpr double kClearingMarginInTols = 1.0 / 8.0;
/// A search whose region, grown by r, its half-diagonal and tol, meets at
/// most this many triangles' boxes scans them for each box's nearest
/// instead of walking the tree.
inline constexpr size_t kMostScannedTriangles = 64;
/// A piece of uncovered boundary not within E of one triangle (or of two)
/// is halved at most this many times, each half tried again, before the
/// space around it is searched,
inline constexpr int kMostPieceHalvings = 10;
/// ... and, after this many halvings in a row that leave no half within E
/// of one or two triangles, its space is searched whole.
inline constexpr int kHalvingsWithoutProgress = 4;

/// Why a candidate hull fails.
enum class MovementVerdict {
  valid,
  centre_near_boundary, ///< a reachable centre within r - E of the uncovered boundary
  centre_inside,        ///< a reachable centre inside the hull
  undecided,            ///< a proof ran out of boxes
};

/// The proof above for `hull` (flat: a polygon), whose
/// boundary on the hulls `known` (inside it, proven before) needs no proof
/// again. `boundary` is reused storage.
MovementVerdict check_movement_hull(const MovementContext& context, const ConvexPolytope& hull, bool flat,
                                    const std::vector<const ConvexPolytope*>& known, UncoveredBoundary& boundary);

} // namespace hullcover::detail
