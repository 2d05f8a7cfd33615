#pragma once
// The order in which the pieces of one screen cell are painted (see
// facet_painter.h): pieces whose planes cross where they overlap are split
// along the crossing, then every piece is painted after those it hides.

#include "polygon_clipping.h"

#include <functional>
#include <vector>

namespace hullcover::app::render {

/// One piece of a cell being ordered.
struct CellPiece {
  std::vector<ImageCorner> polygon; ///< convex, image pixels
  unsigned source = 0;              ///< the painter's piece it is (a part of)
  double key = 0.0;                 ///< depth at its centre, scene units: the order when nothing else decides
};

/// What the ordering asks of the painter about a piece's plane.
struct PieceDepths {
  /// Depth of the plane of piece `source` on the ray through image point
  /// (x, y), scene units, less the allowance of a facet drawn over its
  /// coplanar neighbours; infinity when the ray runs parallel to it.
  std::function<double(unsigned source, double x, double y)> depth_at;
  /// The rank of piece `source` (among equal depths, higher on top).
  std::function<unsigned(unsigned source)> rank;
  double same_depth = 0.0; ///< depths closer than this tie (scene units)
};

/// Splits pieces of `cell` whose planes cross inside their overlap along the
/// crossing (where the two planes are at one depth: a straight line on the
/// image, inverse depth being affine there), so that each part lies wholly
/// in front of or behind the other piece. Stops growing at `max_pieces`.
void split_crossing_pieces(std::vector<CellPiece>& cell, const PieceDepths& depths, size_t max_pieces);

/// Reorders `cell` so that every piece comes after the pieces it hides
/// where they overlap, equal depths by rank (Kahn's algorithm, preferring
/// the farthest key; a cycle is broken at the farthest key left).
void order_cell_pieces(std::vector<CellPiece>& cell, const PieceDepths& depths);

} // namespace hullcover::app::render
