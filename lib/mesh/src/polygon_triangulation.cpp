#include "polygon_triangulation.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace hullcover::detail {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Twice the signed area of the 2D triangle a, b, c: > 0 counter-clockwise.
double turn(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

// Whether p lies in the closed triangle a, b, c (counter-clockwise).
bool in_triangle(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                 const Eigen::Vector2d& c) {
  return turn(a, b, p) >= 0.0 && turn(b, c, p) >= 0.0 && turn(c, a, p) >= 0.0;
}

void fan(int first, const std::vector<int>& ring, std::vector<Eigen::Vector3i>& out) {
  for (size_t i = first + 1; i + 1 < ring.size(); ++i) out.emplace_back(ring[first], ring[i], ring[i + 1]);
}

} // namespace

Triangulation triangulate_polygon(const std::vector<Eigen::Vector3d>& corners, std::vector<Eigen::Vector3i>& out) {
  const int n = static_cast<int>(corners.size());
  std::vector<int> ring(n);
  for (int i = 0; i < n; ++i) ring[i] = i;
  // Newell's normal: the polygon's area vector, however it is bent; about
  // the first corner, so that it rounds at the polygon's size, not at its
  // distance from the origin.
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (int i = 1; i + 1 < n; ++i) normal += (corners[i] - corners[0]).cross(corners[i + 1] - corners[0]);
  int drop = 0;
  normal.cwiseAbs().maxCoeff(&drop);
  double extent2 = 0.0;
  for (const Eigen::Vector3d& c : corners) extent2 = std::max(extent2, (c - corners[0]).squaredNorm());
  const double straight = kStraightDeviationRelative * std::sqrt(extent2);
  if (!(std::abs(normal[drop]) > straight * std::sqrt(extent2))) {
    fan(0, ring, out);
    return Triangulation::fan;
  }
  // The plane's two other axes, ordered so that the polygon winds
  // counter-clockwise in them.
  int u = (drop + 1) % 3, v = (drop + 2) % 3;
  if (normal[drop] < 0.0) std::swap(u, v);
  std::vector<Eigen::Vector2d> flat(n);
  for (int i = 0; i < n; ++i)
    flat[i] = Eigen::Vector2d(corners[i][u], corners[i][v]) - Eigen::Vector2d(corners[0][u], corners[0][v]);

  // Convex: no corner turns the other way beyond rounding, and the
  // directions of its edges go round once (a pentagram turns one way but
  // goes round twice).
  bool convex = true;
  double winding = 0.0;
  for (int i = 0; i < n && convex; ++i) {
    const Eigen::Vector2d a = flat[(i + n - 1) % n], b = flat[i], c = flat[(i + 1) % n];
    convex = turn(a, b, c) >= -straight * (c - a).norm();
    const Eigen::Vector2d d0 = b - a, d1 = c - b;
    winding += std::atan2(d0.x() * d1.y() - d0.y() * d1.x(), d0.dot(d1));
  }
  if (convex && winding < 3.0 * kPi) {
    fan(0, ring, out);
    return Triangulation::fan;
  }
  if (n > kMostConcaveCorners) return Triangulation::too_large;

  // Ear clipping: cut off a convex corner whose triangle holds no other
  // corner, until three are left. The search for the next ear starts
  // beside the last one cut, where new ears appear.
  int from = 0;
  while (ring.size() > 3) {
    const int m = static_cast<int>(ring.size());
    int ear = -1;
    for (int k = 0; k < m && ear < 0; ++k) {
      const int i = (from + k) % m;
      const int a = ring[(i + m - 1) % m], b = ring[i], c = ring[(i + 1) % m];
      if (!(turn(flat[a], flat[b], flat[c]) > straight * (flat[c] - flat[a]).norm())) continue;
      bool empty = true;
      for (int j = 0; j < m && empty; ++j) {
        const int p = ring[j];
        if (p == a || p == b || p == c || flat[p] == flat[a] || flat[p] == flat[b] || flat[p] == flat[c]) continue;
        empty = !in_triangle(flat[p], flat[a], flat[b], flat[c]);
      }
      if (empty) ear = i;
    }
    // A self-crossing ring may run out of ears: the rest as a fan.
    if (ear < 0) break;
    out.emplace_back(ring[(ear + m - 1) % m], ring[ear], ring[(ear + 1) % m]);
    ring.erase(ring.begin() + ear);
    from = std::max(0, ear - 1);
  }
  fan(0, ring, out);
  return Triangulation::ears;
}

} // namespace hullcover::detail
