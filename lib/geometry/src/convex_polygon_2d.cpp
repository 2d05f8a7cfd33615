#include "hullcover/geometry/convex_polygon_2d.h"

namespace hullcover {
namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// The part of `in` left of the line through p along `edge` (right of it
// when `keep_left` is false), into `out` (not `in`; its storage reused).
void clip_to_side(const std::vector<Eigen::Vector2d>& in, const Eigen::Vector2d& p, const Eigen::Vector2d& edge,
                  bool keep_left, std::vector<Eigen::Vector2d>& out) {
  out.clear();
  const double sign = keep_left ? 1.0 : -1.0;
  for (size_t i = 0, m = in.size(); i < m; ++i) {
    const Eigen::Vector2d &x = in[i], &y = in[(i + 1) % m];
    const double sx = sign * cross(edge, x - p), sy = sign * cross(edge, y - p);
    if (sx >= 0.0) out.push_back(x);
    if ((sx >= 0.0) != (sy >= 0.0)) out.push_back(x + (y - x) * (sx / (sx - sy)));
  }
}

// Whether the line of some edge of `polygon` separates it from `other`:
// `polygon` on its inner side (left, some corner strictly), `other` on its
// outer side (on the line counts as outside). Checked on both, not taken
// from the winding: an edge clipping left as a rounding stub (a corner
// repeated, or two a hair apart) has a line through the polygon, or none.
bool separated_by_an_edge(const std::vector<Eigen::Vector2d>& polygon, const std::vector<Eigen::Vector2d>& other) {
  for (size_t e = 0, n = polygon.size(); e < n; ++e) {
    const Eigen::Vector2d &p = polygon[e], edge = polygon[(e + 1) % n] - polygon[e];
    bool other_outside = true;
    for (const Eigen::Vector2d& q : other) other_outside = other_outside && cross(edge, q - p) <= 0.0;
    if (!other_outside) continue;
    bool own_inside = true, own_strictly = false;
    for (const Eigen::Vector2d& q : polygon) {
      const double c = cross(edge, q - p);
      own_inside = own_inside && c >= 0.0;
      own_strictly = own_strictly || c > 0.0;
    }
    if (own_inside && own_strictly) return true;
  }
  return false;
}

} // namespace

double polygon_area(const std::vector<Eigen::Vector2d>& corners) {
  // Measured from the first corner: products of coordinates far from the
  // origin would cancel to rounding dust larger than a small piece's area.
  double twice = 0.0;
  for (size_t i = 1, n = corners.size(); n >= 3 && i + 1 < n; ++i)
    twice += cross(corners[i] - corners[0], corners[i + 1] - corners[0]);
  return 0.5 * twice;
}

double polygon_perimeter(const std::vector<Eigen::Vector2d>& corners) {
  double length = 0.0;
  for (size_t i = 0, n = corners.size(); n >= 2 && i < n; ++i) length += (corners[(i + 1) % n] - corners[i]).norm();
  return length;
}

// Sutherland-Hodgman: `a` clipped by the half-plane left of every edge of
// convex `b`.
std::vector<Eigen::Vector2d> intersect_convex_polygons(const std::vector<Eigen::Vector2d>& a,
                                                       const std::vector<Eigen::Vector2d>& b) {
  std::vector<Eigen::Vector2d> out = a, spare;
  for (size_t e = 0, n = b.size(); e < n && !out.empty(); ++e) {
    clip_to_side(out, b[e], b[(e + 1) % n] - b[e], true, spare);
    out.swap(spare);
  }
  return out;
}

// What lies right of the cutter's first edge is one piece; of the rest,
// what lies right of its second edge is the next, and so on: what is left
// after every edge is inside the cutter.
bool convex_polygons_apart(const std::vector<Eigen::Vector2d>& piece, const std::vector<Eigen::Vector2d>& cutter) {
  return piece.size() >= 3 &&
         (cutter.size() < 3 || separated_by_an_edge(cutter, piece) || separated_by_an_edge(piece, cutter));
}

void subtract_overlapping_convex_polygon(const std::vector<Eigen::Vector2d>& piece,
                                         const std::vector<Eigen::Vector2d>& cutter,
                                         std::vector<std::vector<Eigen::Vector2d>>& pieces,
                                         PolygonSubtractionStorage& storage) {
  std::vector<Eigen::Vector2d>& rest = storage.rest;
  std::vector<Eigen::Vector2d>& inside = storage.inside;
  rest = piece;
  for (size_t e = 0, n = cutter.size(); e < n && rest.size() >= 3; ++e) {
    const Eigen::Vector2d &p = cutter[e], edge = cutter[(e + 1) % n] - cutter[e];
    pieces.emplace_back();
    clip_to_side(rest, p, edge, false, pieces.back());
    if (pieces.back().size() < 3 || !(polygon_area(pieces.back()) > 0.0)) pieces.pop_back();
    clip_to_side(rest, p, edge, true, inside);
    rest.swap(inside);
  }
}

std::vector<std::vector<Eigen::Vector2d>> subtract_convex_polygon(const std::vector<Eigen::Vector2d>& piece,
                                                                  const std::vector<Eigen::Vector2d>& cutter) {
  // Apart (an edge of either separates them): the piece comes back whole.
  // Cut along the cutter's edges regardless, a piece straddling the line of
  // an edge that does not separate them would break into pieces for
  // nothing, and a coverage test subtracting hundreds of faces multiplies
  // them (Red Eclipse's keystone2k spent 80% of its bake there).
  if (convex_polygons_apart(piece, cutter)) return {piece};
  std::vector<std::vector<Eigen::Vector2d>> pieces;
  PolygonSubtractionStorage storage;
  subtract_overlapping_convex_polygon(piece, cutter, pieces, storage);
  return pieces;
}

} // namespace hullcover
