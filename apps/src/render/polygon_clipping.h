#pragma once
// Clipping convex polygons, in space (at the camera's near depth) and on
// the image (to screen cells, and to each other to find where two pieces
// overlap), keeping track of which edges are the original polygon's
// outline: an edge made by a cut is not.

#include <Eigen/Core>

#include <cmath>
#include <vector>

namespace hullcover::app::render {

/// A polygon corner in space, with the flag of the edge leaving it.
struct SpaceCorner {
  Eigen::Vector3d p; ///< scene units
  bool outline;      ///< the edge to the next corner lies on the original polygon's outline
};

/// A polygon corner on the image, with the flag of the edge leaving it.
struct ImageCorner {
  double x, y;  ///< pixels
  bool outline; ///< the edge to the next corner lies on the original polygon's outline
};

/// The point a fraction `t` of the way from `a` to `b`, on no outline.
inline SpaceCorner between(const SpaceCorner& a, const SpaceCorner& b, double t) {
  return {a.p + t * (b.p - a.p), false};
}
inline ImageCorner between(const ImageCorner& a, const ImageCorner& b, double t) {
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), false};
}

/// Sutherland-Hodgman: `out` becomes the part of convex `polygon` where
/// `value(corner)` <= 0 (a linear function). An edge of the result keeps
/// its outline flag when it is part of an edge of `polygon`, and has none
/// when it runs along the cut.
template <typename Corner, typename Value>
void clip(const std::vector<Corner>& polygon, const Value& value, std::vector<Corner>& out) {
  out.clear();
  const size_t n = polygon.size();
  for (size_t i = 0; i < n; ++i) {
    const Corner& a = polygon[i];
    const Corner& b = polygon[(i + 1) % n];
    const double va = value(a), vb = value(b);
    if (va <= 0.0) out.push_back(a);
    if ((va <= 0.0) != (vb <= 0.0)) {
      Corner cut = between(a, b, va / (va - vb));
      cut.outline = va > 0.0 && a.outline; // entering: the rest of the edge is the polygon's
      out.push_back(cut);
    }
  }
}

/// Twice the signed area of an image polygon, pixels squared; its sign is
/// the polygon's winding.
inline double doubled_signed_area(const std::vector<ImageCorner>& polygon) {
  double sum = 0.0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const ImageCorner& a = polygon[i];
    const ImageCorner& b = polygon[(i + 1) % polygon.size()];
    sum += a.x * b.y - b.x * a.y;
  }
  return sum;
}

/// The overlap of two convex image polygons (either winding): `a` clipped
/// by the inner side of each edge of `b`. Empty when `b` has no area.
inline std::vector<ImageCorner> convex_overlap(const std::vector<ImageCorner>& a, const std::vector<ImageCorner>& b) {
  const double orientation = doubled_signed_area(b);
  std::vector<ImageCorner> result = a, next;
  if (orientation == 0.0) return {};
  for (size_t i = 0; i < b.size() && result.size() >= 3; ++i) {
    const ImageCorner& p = b[i];
    const ImageCorner& q = b[(i + 1) % b.size()];
    // Positive on the outer side of edge p-q for either winding.
    clip(
        result,
        [&](const ImageCorner& c) {
      return -std::copysign(1.0, orientation) * ((q.x - p.x) * (c.y - p.y) - (q.y - p.y) * (c.x - p.x));
        },
        next);
    result.swap(next);
  }
  if (result.size() < 3) result.clear();
  return result;
}

} // namespace hullcover::app::render
