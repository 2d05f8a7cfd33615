#include "recheck_geometry.h"

#include "hullcover/geometry/tolerances.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hullcover::validate::recheck {
namespace {

// Not a tolerance: a segment whose direction has less than this (in scene
// units) along a plane's normal runs along the plane (in practice the slope
// is then exactly 0: a real one is many orders larger). Its side is the
// start's; dividing by the slope would give 0/0 for a start on the plane.
constexpr double kParallelSlope = 1e-300;

// Spatial hash of a grid cell.
long long cell_key(long long i, long long j, long long k) {
  return (i * 73856093LL) ^ (j * 19349663LL) ^ (k * 83492791LL);
}

// The plane Newell's method fits to `poly`, about its first corner (so it
// rounds at the polygon's size, not at its distance from the origin); `fallback`
// when the polygon has no area to fit to: narrower than kParallelSine of its
// length (a facet whose corners all lie on one line, which a hull's
// description may hold), whose fitted normal would be rounding noise.
HalfSpace newell_plane(const std::vector<Eigen::Vector3d>& poly, const HalfSpace& fallback) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero(), centre = Eigen::Vector3d::Zero();
  double diameter2 = 0.0;
  for (size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector3d a = poly[i] - poly.front();
    const Eigen::Vector3d b = poly[(i + 1) % poly.size()] - poly.front();
    n += a.cross(b);
    centre += a;
    diameter2 = std::max(diameter2, a.squaredNorm());
  }
  if (!(n.norm() > kParallelSine * diameter2)) return fallback;
  centre = centre / static_cast<double>(poly.size()) + poly.front();
  n.normalize();
  return {n, n.dot(centre)};
}

// Outward in-plane half-spaces of polygon `poly` (front normal `normal`).
std::vector<HalfSpace> polygon_sides(const std::vector<Eigen::Vector3d>& poly, const Eigen::Vector3d& normal) {
  std::vector<HalfSpace> sides;
  for (size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector3d e = poly[(i + 1) % poly.size()] - poly[i];
    const Eigen::Vector3d out = e.cross(normal).normalized();
    sides.push_back({out, out.dot(poly[i])});
  }
  return sides;
}

} // namespace

CheckedHull make_checked(const HullUnderCheck& hull) {
  CheckedHull c;
  const auto& V = hull.shape->vertices;
  c.lo = c.hi = V.front();
  for (const auto& p : V) {
    c.lo = c.lo.cwiseMin(p);
    c.hi = c.hi.cwiseMax(p);
  }
  std::vector<Eigen::Vector3d> poly;
  for (const auto& facet : hull.shape->facets) {
    poly.clear();
    for (int v : facet) poly.push_back(V[v]);
    // The hull's own plane stands in for a facet with no area to fit; in a
    // description without planes such a facet bounds nothing (an infinite
    // offset), which can only make the hull larger: the cautious side.
    const size_t f = c.facets.size();
    const HalfSpace given = f < hull.shape->planes.size()
                                ? HalfSpace{hull.shape->planes[f].normal, hull.shape->planes[f].offset}
                                : HalfSpace{Eigen::Vector3d::Zero(), std::numeric_limits<double>::infinity()};
    c.facets.push_back(newell_plane(poly, given));
  }
  c.flat = hull.flat;
  if (c.flat) {
    c.front = c.facets.front();
    poly.clear();
    for (int v : hull.shape->facets.front()) poly.push_back(V[v]);
    c.sides = polygon_sides(poly, c.front.n);
    // A point is on a flat hull when it is on its plane AND within its sides.
    c.facets.insert(c.facets.end(), c.sides.begin(), c.sides.end());
  }
  return c;
}

double depth_inside(const std::vector<HalfSpace>& hs, const Eigen::Vector3d& p) {
  double worst = INFINITY;
  for (const HalfSpace& h : hs) worst = std::min(worst, h.d - h.n.dot(p));
  return worst;
}

bool segment_deeper_than(const std::vector<HalfSpace>& hs, const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                         double tol) {
  // Clip the parameter interval [0, 1] to each shrunk half-space.
  double lo = 0.0, hi = 1.0;
  const Eigen::Vector3d d = q - p;
  for (const HalfSpace& h : hs) {
    // need h.n.(p + t d) <= h.d - tol
    const double slope = h.n.dot(d);
    const double room = h.d - tol - h.n.dot(p);
    if (std::abs(slope) < kParallelSlope) {
      if (room <= 0.0) return false;
      continue;
    }
    const double t = room / slope;
    if (slope > 0.0)
      hi = std::min(hi, t);
    else
      lo = std::max(lo, t);
    if (lo >= hi) return false;
  }
  return lo < hi;
}

bool segment_crosses_flat(const CheckedHull& c, const Eigen::Vector3d& p, const Eigen::Vector3d& q, double tol) {
  const double dp = c.front.n.dot(p) - c.front.d, dq = c.front.n.dot(q) - c.front.d;
  if (std::abs(dp - dq) <= tol) return false; // runs along the plane
  if ((dp > tol && dq > tol) || (dp < -tol && dq < -tol)) return false;
  const Eigen::Vector3d x = p + (q - p) * (dp / (dp - dq));
  return depth_inside(c.sides, x) > tol;
}

Eigen::Vector3i CandidateGrid::at(const Eigen::Vector3d& p) const {
  return ((p - origin) / cell).array().floor().cast<int>();
}

void CandidateGrid::insert(int id, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  const Eigen::Vector3i a = at(lo), b = at(hi);
  for (int i = a.x(); i <= b.x(); ++i)
    for (int j = a.y(); j <= b.y(); ++j)
      for (int k = a.z(); k <= b.z(); ++k) cells[cell_key(i, j, k)].push_back(id);
}

std::vector<int> CandidateGrid::query(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) const {
  std::vector<int> out;
  const Eigen::Vector3i a = at(lo), b = at(hi);
  for (int i = a.x(); i <= b.x(); ++i)
    for (int j = a.y(); j <= b.y(); ++j)
      for (int k = a.z(); k <= b.z(); ++k) {
        const auto it = cells.find(cell_key(i, j, k));
        if (it != cells.end()) out.insert(out.end(), it->second.begin(), it->second.end());
      }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

} // namespace hullcover::validate::recheck
