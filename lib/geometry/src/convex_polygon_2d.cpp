#include "hullcover/geometry/convex_polygon_2d.h"

namespace hullcover {
namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// The part of `in` left of the line through p along `edge` (right of it
// when `keep_left` is false).
std::vector<Eigen::Vector2d> clip_to_side(const std::vector<Eigen::Vector2d>& in, const Eigen::Vector2d& p,
                                          const Eigen::Vector2d& edge, bool keep_left) {
  std::vector<Eigen::Vector2d> out;
  const double sign = keep_left ? 1.0 : -1.0;
  for (size_t i = 0, m = in.size(); i < m; ++i) {
    const Eigen::Vector2d &x = in[i], &y = in[(i + 1) % m];
    const double sx = sign * cross(edge, x - p), sy = sign * cross(edge, y - p);
    if (sx >= 0.0) out.push_back(x);
    if ((sx >= 0.0) != (sy >= 0.0)) out.push_back(x + (y - x) * (sx / (sx - sy)));
  }
  return out;
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
  std::vector<Eigen::Vector2d> out = a;
  for (size_t e = 0, n = b.size(); e < n && !out.empty(); ++e) out = clip_to_side(out, b[e], b[(e + 1) % n] - b[e], true);
  return out;
}

// What lies right of the cutter's first edge is one piece; of the rest,
// what lies right of its second edge is the next, and so on: what is left
// after every edge is inside the cutter.
std::vector<std::vector<Eigen::Vector2d>> subtract_convex_polygon(const std::vector<Eigen::Vector2d>& piece,
                                                                  const std::vector<Eigen::Vector2d>& cutter) {
  std::vector<std::vector<Eigen::Vector2d>> pieces;
  std::vector<Eigen::Vector2d> rest = piece;
  for (size_t e = 0, n = cutter.size(); e < n && rest.size() >= 3; ++e) {
    const Eigen::Vector2d &p = cutter[e], edge = cutter[(e + 1) % n] - cutter[e];
    std::vector<Eigen::Vector2d> outside = clip_to_side(rest, p, edge, false);
    if (outside.size() >= 3 && polygon_area(outside) > 0.0) pieces.push_back(std::move(outside));
    rest = clip_to_side(rest, p, edge, true);
  }
  if (cutter.size() < 3 && piece.size() >= 3) pieces = {piece};  // a cutter without area covers nothing
  return pieces;
}

} // namespace hullcover
