#include "segment_in_hull.h"

#include "hullcover/geometry/tolerances.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hullcover::validate::probe {
namespace {

// Halvings of the stretch while looking for where the deepest point lies:
// 64 take any double interval down to adjacent values, after which the two
// planes active there give the exact crossing.
constexpr int kHalvings = 64;

// Depth behind plane i at distance t along the segment: a_i - b_i t.
struct DepthLine {
  double a = 0.0, b = 0.0;
  double at(double t) const { return a - b * t; }
};

// The lowest of `lines` at t (+infinity for none), and which one it is.
double lowest(const std::vector<DepthLine>& lines, double t, int& which) {
  double low = std::numeric_limits<double>::infinity();
  which = -1;
  for (int i = 0; i < static_cast<int>(lines.size()); ++i)
    if (lines[i].at(t) < low) low = lines[i].at(t), which = i;
  return low;
}

// max over t in [lo, hi] of min over all lines, which is concave and
// piecewise linear: the lines falling with t (b > 0) bound it from one side,
// the rising ones (b < 0) from the other, the flat ones everywhere. Its top
// lies where the lowest falling line crosses the lowest rising one (or at
// an end); halving brackets that crossing, then the two lines active there
// give it exactly. Returns the depth and sets `at`.
double deepest_over(const std::vector<DepthLine>& falling, const std::vector<DepthLine>& rising, double flat, double lo,
                    double hi, double& at) {
  int f = -1, r = -1;
  const auto gap = [&](double t) { return lowest(falling, t, f) - lowest(rising, t, r); };
  const auto depth = [&](double t) { return std::min({lowest(falling, t, f), lowest(rising, t, r), flat}); };
  if (falling.empty()) return depth(at = hi); // never falls: deepest at the end
  if (rising.empty()) return depth(at = lo);  // never rises: deepest at the start
  if (gap(lo) <= 0.0) return depth(at = lo);  // the falling lines are already the lower ones
  if (gap(hi) >= 0.0) return depth(at = hi);  // the rising lines are still the lower ones
  double a = lo, b = hi;
  for (int i = 0; i < kHalvings && b - a > 0.0; ++i) {
    const double mid = 0.5 * (a + b);
    if (mid <= a || mid >= b) break;
    (gap(mid) > 0.0 ? a : b) = mid;
  }
  gap(0.5 * (a + b)); // sets f and r: the lines active at the crossing
  const DepthLine& down = falling[f];
  const DepthLine& up = rising[r];
  const double crossing = std::clamp((down.a - up.a) / (down.b - up.b), a, b);
  double best = depth(at = a);
  for (double t : {crossing, b})
    if (const double d = depth(t); d > best) best = d, at = t;
  return best;
}

} // namespace

std::optional<InsideStretch> stretch_inside(const std::vector<Plane>& planes, const Eigen::Vector3d& start,
                                            const Eigen::Vector3d& dir, double length, double tol) {
  double lo = 0.0, hi = length;
  std::vector<DepthLine> falling, rising;
  double flat = std::numeric_limits<double>::infinity();
  for (const Plane& plane : planes) {
    const DepthLine line{plane.offset - plane.normal.dot(start), plane.normal.dot(dir)};
    // Deeper than tol behind this plane: line.a - line.b t > tol.
    const double room = line.a - tol;
    if (line.b > 0.0) {
      hi = std::min(hi, room / line.b);
      falling.push_back(line);
    } else if (line.b < 0.0) {
      lo = std::max(lo, room / line.b);
      rising.push_back(line);
    } else {
      if (room <= 0.0) return std::nullopt;
      flat = std::min(flat, line.a);
    }
    if (lo >= hi) return std::nullopt;
  }
  InsideStretch stretch;
  stretch.from = lo;
  stretch.to = hi;
  stretch.depth = deepest_over(falling, rising, flat, lo, hi, stretch.deepest_at);
  // Deeper than tol by more than the rounding of the depths themselves: a
  // ray from an open edge along the middle plane of a slab 2 tol thick lies
  // exactly tol deep, and rounding gave such rays stretches of 1e-14 on
  // pandora once rays were judged from their origin.
  double magnitude = start.norm() + length;
  for (const Plane& plane : planes) magnitude = std::max(magnitude, std::abs(plane.offset));
  const double rounding = kRoundingErrorsPerPlaneTest * std::numeric_limits<double>::epsilon() * magnitude;
  if (!(stretch.depth > tol + rounding)) return std::nullopt;
  return stretch;
}

} // namespace hullcover::validate::probe
