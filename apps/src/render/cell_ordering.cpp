#include "cell_ordering.h"

#include <algorithm>
#include <cmath>

namespace hullcover::app::render {
namespace {

// Two pieces whose overlap on the image is smaller than this (pixels
// squared) only touch along an edge: their order does not matter.
constexpr double kLeastOverlapArea = 0.01;

// Where `a` and `b` overlap by an area, or nothing.
std::vector<ImageCorner> area_overlap(const CellPiece& a, const CellPiece& b) {
  std::vector<ImageCorner> overlap = convex_overlap(a.polygon, b.polygon);
  if (!overlap.empty() && std::abs(doubled_signed_area(overlap)) < 2.0 * kLeastOverlapArea) overlap.clear();
  return overlap;
}

// -1 when `a` must be painted before `b` (it lies behind where they
// overlap), 1 for the reverse, 0 when they do not overlap or tie at one rank.
int occlusion_order(const CellPiece& a, const CellPiece& b, const PieceDepths& depths) {
  const std::vector<ImageCorner> overlap = area_overlap(a, b);
  if (overlap.empty()) return 0;
  double x = 0.0, y = 0.0;
  for (const ImageCorner& c : overlap) {
    x += c.x / overlap.size();
    y += c.y / overlap.size();
  }
  double da = depths.depth_at(a.source, x, y), db = depths.depth_at(b.source, x, y);
  if (!std::isfinite(da) || !std::isfinite(db)) {
    da = a.key;
    db = b.key;
  }
  if (std::abs(da - db) <= depths.same_depth) {
    const unsigned ra = depths.rank(a.source), rb = depths.rank(b.source);
    return ra == rb ? 0 : (ra < rb ? -1 : 1);
  }
  return da > db ? -1 : 1;
}

// Inverse depth of `piece`'s plane at `c`: affine on the image, so its
// differences vanish along straight lines (0 for a plane seen edge-on).
double inverse_depth(const CellPiece& piece, const ImageCorner& c, const PieceDepths& depths) {
  const double d = depths.depth_at(piece.source, c.x, c.y);
  return std::isfinite(d) && d != 0.0 ? 1.0 / d : 0.0;
}

// True when the planes of `a` and `b` change order inside their overlap by
// more than the tie distance either way.
bool planes_cross(const CellPiece& a, const CellPiece& b, const PieceDepths& depths) {
  const std::vector<ImageCorner> overlap = area_overlap(a, b);
  bool a_behind = false, a_in_front = false;
  for (const ImageCorner& c : overlap) {
    const double difference = depths.depth_at(a.source, c.x, c.y) - depths.depth_at(b.source, c.x, c.y);
    if (!std::isfinite(difference)) return false;
    a_behind = a_behind || difference > depths.same_depth;
    a_in_front = a_in_front || difference < -depths.same_depth;
  }
  return a_behind && a_in_front;
}

} // namespace

void split_crossing_pieces(std::vector<CellPiece>& cell, const PieceDepths& depths, size_t max_pieces) {
  std::vector<ImageCorner> behind, in_front;
  for (size_t i = 0; i < cell.size(); ++i)
    for (size_t j = 0; j < cell.size() && cell.size() < max_pieces; ++j) {
      if (i == j || !planes_cross(cell[i], cell[j], depths)) continue;
      const CellPiece& other = cell[j];
      const auto difference = [&](const ImageCorner& c) {
        return inverse_depth(cell[i], c, depths) - inverse_depth(other, c, depths);
      };
      clip(cell[i].polygon, difference, behind); // smaller inverse depth: farther
      clip(
          cell[i].polygon, [&](const ImageCorner& c) { return -difference(c); }, in_front);
      if (behind.size() < 3 || in_front.size() < 3) continue; // the crossing only grazes it
      CellPiece second{in_front, cell[i].source, cell[i].key};
      cell[i].polygon = behind;
      cell.push_back(std::move(second));
    }
}

void order_cell_pieces(std::vector<CellPiece>& cell, const PieceDepths& depths) {
  const size_t n = cell.size();
  if (n < 2) return;
  std::stable_sort(cell.begin(), cell.end(), [](const CellPiece& a, const CellPiece& b) { return a.key > b.key; });
  std::vector<std::vector<size_t>> after(n); // after[i]: pieces painted after i
  std::vector<int> waiting(n, 0);            // predecessors not yet painted
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j) {
      const int order = occlusion_order(cell[i], cell[j], depths);
      if (order < 0) {
        after[i].push_back(j);
        ++waiting[j];
      } else if (order > 0) {
        after[j].push_back(i);
        ++waiting[i];
      }
    }
  std::vector<CellPiece> ordered;
  ordered.reserve(n);
  std::vector<bool> painted(n, false);
  while (ordered.size() < n) {
    size_t pick = n;
    for (size_t i = 0; i < n && pick == n; ++i)
      if (!painted[i] && waiting[i] == 0) pick = i;
    for (size_t i = 0; i < n && pick == n; ++i) // a cycle: the farthest left
      if (!painted[i]) pick = i;
    painted[pick] = true;
    ordered.push_back(cell[pick]);
    for (size_t j : after[pick]) --waiting[j];
  }
  cell.swap(ordered);
}

} // namespace hullcover::app::render
