#include "validity/loss_allowance.h"

#include "validity/first_hit_bound.h"
#include "validity/shadow_pieces.h"

#include "hullcover/geometry/planar_hull.h"
#include "hullcover/geometry/triangle_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hullcover::detail {
namespace {

// A box of the proof: centre and half extents.
struct Cell {
  Eigen::Vector3d centre;
  Eigen::Vector3d half;
  double half_diagonal() const { return half.norm(); }
};

// The distance from `p` to the nearest triangle, or `limit` when none is
// nearer (limit > 0). A proof's cell far from its lost point looks up as
// far as that point; the tree's nearest-first walk then asks only the
// triangles nearer than the nearest met so far, not all within the limit.
double clearance_below(const SceneIndex& index, const Eigen::Vector3d& p, double limit) {
  const MeshView& mesh = index.mesh();
  return std::sqrt(index.face_tree.nearest_to_point(p, limit, [&](int f) {
    const auto& t = mesh.triangles[f];
    return (closest_point_on_triangle(p, mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]) - p)
        .squaredNorm();
  }));
}

// A lower bound on the distance from `p` to the polytope (0 inside it):
// its largest signed distance to a plane of it.
double distance_below(const std::vector<Plane>& planes, const Eigen::Vector3d& p) {
  return std::max(0.0, deepest_signed_distance(planes, p));
}

// What a cell of a proof comes to.
enum class CellVerdict { proved, outside, counterexample, open };

// Runs a proof over `box`: `judge` settles each cell or leaves it open (to
// be halved). True when every cell is proved or outside within the budget.
template <typename Judge>
bool prove_over(const Aabb& box, double smallest, Judge&& judge) {
  if (box.empty()) return true;
  std::vector<Cell> pending = {{0.5 * (box.min + box.max), 0.5 * (box.max - box.min)}};
  int budget = kMaxAllowanceCells;
  while (!pending.empty()) {
    const Cell cell = pending.back();
    pending.pop_back();
    if (--budget < 0) return false;
    switch (judge(cell)) {
      case CellVerdict::proved:
      case CellVerdict::outside: continue;
      case CellVerdict::counterexample: return false;
      case CellVerdict::open: break;
    }
    // A cell no wider than the tolerance still open sits where the loss
    // meets what is allowed: the tolerance is all the margin a proof has.
    if (cell.half_diagonal() <= smallest) return false;
    // Halve along the longest side, so cells stay near cubes.
    int axis = 0;
    cell.half.maxCoeff(&axis);
    Cell low = cell, high = cell;
    low.half[axis] *= 0.5;
    high.half[axis] *= 0.5;
    low.centre[axis] -= low.half[axis];
    high.centre[axis] += high.half[axis];
    pending.push_back(high);
    pending.push_back(low);
  }
  return true;
}

// Every point of the polytope within max_deviation of a triangle.
bool within_deviation(const SceneIndex& index, const std::vector<Plane>& lost, const Aabb& box) {
  const double limit = index.max_deviation;
  return prove_over(box, index.tol(), [&](const Cell& cell) {
    const double h = cell.half_diagonal();
    const double outside = distance_below(lost, cell.centre);
    if (outside > h) return CellVerdict::outside;
    const double clearance = clearance_below(index, cell.centre, limit + h);
    if (clearance + h <= limit) return CellVerdict::proved;
    if (outside <= 0.0 && clearance > limit) return CellVerdict::counterexample;
    return CellVerdict::open;
  });
}

// No ball of radius agent_radius that touches no triangle reaches into the
// polytope: every point within that radius of it has clearance below it.
bool out_of_agents_reach(const SceneIndex& index, const std::vector<Plane>& lost, const Aabb& box,
                         const Eigen::Vector3d& lost_point) {
  const double r = index.agent_radius;
  return prove_over(grown(box, r), index.tol(), [&](const Cell& cell) {
    const double h = cell.half_diagonal();
    const double outside = distance_below(lost, cell.centre);
    if (outside >= r + h) return CellVerdict::outside;
    // Looked up as far as the lost point, to see whether an empty ball
    // around the centre holds it (a refusal, so rounding here is harmless).
    const double limit = std::max(r, (lost_point - cell.centre).norm());
    const double clearance = clearance_below(index, cell.centre, limit);
    if (clearance + h < r) return CellVerdict::proved;
    if (clearance >= r) {
      // The ball of radius `clearance` around the centre touches nothing,
      // and neither does any ball of radius r inside it: one holds the lost
      // point when that lies within it, or one holds a point of the
      // polytope when the centre does.
      if (outside <= 0.0) return CellVerdict::counterexample;
      if ((lost_point - cell.centre).norm() < clearance) return CellVerdict::counterexample;
    }
    return CellVerdict::open;
  });
}

} // namespace

bool loss_allowed(const SceneIndex& index, const std::vector<Plane>& lost, const Aabb& box,
                  const Eigen::Vector3d& lost_point, bool within_deviation_known) {
  if (!index.has_allowance()) return false;
  if (index.max_deviation > 0.0 && !within_deviation_known && !within_deviation(index, lost, box)) return false;
  return !(index.agent_radius > 0.0) || out_of_agents_reach(index, lost, box, lost_point);
}

// An upper bound on how far from the sweep's base, along its rays, the rays
// through `region` stay inside the interior: each ray has left it once it
// crosses any plane it leaves through, where the distance is affine over
// the region (so its largest value is at a corner); the nearest such plane
// bounds them all.
double farthest_inside(const FreeSpaceSweep& sweep, const HullInterior& interior,
                       const std::vector<Eigen::Vector3d>& region) {
  const Eigen::Vector3d& dir = sweep.direction;
  double bound = std::numeric_limits<double>::infinity();
  for (const Plane& plane : interior.planes) {
    const double rate = plane.normal.dot(dir);
    if (!(rate > 0.0)) continue;
    double farthest = -std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& p : region)
      farthest = std::max(farthest, -sweep.start.signed_distance(p) - plane.signed_distance(p) / rate);
    bound = std::min(bound, farthest);
  }
  return bound;
}

bool piece_loss_allowed(const SceneIndex& index, const FreeSpaceSweep& sweep, const HullInterior& interior,
                        const std::vector<Eigen::Vector3d>& region, std::vector<int>& scratch) {
  if (!index.has_allowance()) return false;
  // Every ray starts on its base, a face or an open edge of the mesh (grown
  // by tol, as rays meet faces): a point t along it lies within t + tol of
  // the mesh. So a loss no farther along its rays than max_deviation - tol
  // is allowed without a proof.
  const double tol = index.tol();
  bool within_deviation_known =
      index.max_deviation > 0.0 && farthest_inside(sweep, interior, region) + tol <= index.max_deviation;
  if (within_deviation_known && !(index.agent_radius > 0.0)) return true;
  const Eigen::Vector3d& dir = sweep.direction;
  // Rays start on the base (a face crossing the hull starts its rays
  // inside it): nothing behind the base is theirs.
  std::vector<Plane> lost = interior.planes;
  lost.push_back(sweep.start);
  for (const Plane& side : column_planes(region, dir)) lost.push_back(side);
  Aabb box;
  for (const std::vector<Eigen::Vector3d>& facet : interior.facets)
    for (const Eigen::Vector3d& v : facet) box.extend(v);
  const double reach = std::min(sweep.reach, first_hit_bound_over(index, sweep, region, scratch));
  if (std::isfinite(reach)) {
    // Along a ray, the distance from its base is -start.signed_distance:
    // at most `reach`.
    lost.push_back({-sweep.start.normal, reach - sweep.start.offset});
    Aabb column;
    for (const Eigen::Vector3d& p : region) {
      column.extend(p);
      column.extend(p + (sweep.start.signed_distance(p) + reach) * dir);
    }
    box.min = box.min.cwiseMax(column.min);
    box.max = box.max.cwiseMin(column.max);
    within_deviation_known |= index.max_deviation > 0.0 && reach + tol <= index.max_deviation;
    if (within_deviation_known && !(index.agent_radius > 0.0)) return true;
  }
  return loss_allowed(index, lost, box, centroid_of(region), within_deviation_known);
}

} // namespace hullcover::detail
