#pragma once
/// \file agent_lattice.h
/// The movement audit's own reach: a lattice of points at clearance r or
/// more, found with the audit's own clearance samples, standing test and
/// flood: the reachable centres the definition names, sampled (the
/// decomposer's reach grid is a superset of them, cell by cell). Every
/// point it reaches is a reachable centre; passages narrower than the
/// lattice resolves may leave some out.

#include "audit_agent.h"

#include "hullcover/covering/movement_options.h"
#include "hullcover/geometry/aabb_tree.h"
#include "hullcover/geometry/block_bytes.h"
#include "hullcover/geometry/mesh.h"
#include "hullcover/geometry/status.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

namespace hullcover {
struct PreparedMesh;
namespace validate {
struct MovementAuditOptions;
struct MovementHullBound;
} // namespace validate
} // namespace hullcover

namespace hullcover::validate::detail {

/// Distances to the scene's triangles.
struct TriangleDistances {
  const Mesh& mesh;
  AabbTree tree;
  explicit TriangleDistances(const Mesh& m);
  /// Distance from p to the nearest triangle, or `limit` when none is nearer.
  double clearance(const Eigen::Vector3d& p, double limit) const;
  /// The same, and the nearest triangle's point nearest to p in `foot`
  /// (left as it was when no triangle is nearer than `limit`).
  double nearest(const Eigen::Vector3d& p, double limit, Eigen::Vector3d& foot) const;
};

/// The lattice's points, a byte each in blocks (block_bytes.h): a block of
/// open air or solid ground is one byte, and, walking, blocks no walker
/// reaches are never examined.
struct AgentLattice {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  double spacing = 0.0;
  Eigen::Vector3i dims = Eigen::Vector3i::Zero();
  /// Per point, bits: kClearPoint (clearance >= r at the point itself) and
  /// kReachablePoint (a reachable centre); the others are the flood's own.
  /// A point in a block not examined reads 0.
  BlockBytes flags{Eigen::Vector3i::Zero()};
  static constexpr std::uint8_t kClearPoint = 1;
  static constexpr std::uint8_t kReachablePoint = 2;
  bool clear(int i, int j, int k) const { return flags.get(i, j, k) & kClearPoint; }
  bool reachable(int i, int j, int k) const { return flags.get(i, j, k) & kReachablePoint; }
  Eigen::Vector3d point(int i, int j, int k) const { return origin + Eigen::Vector3d(i, j, k) * spacing; }
  long long size() const { return static_cast<long long>(dims.x()) * dims.y() * dims.z(); }
  /// Whether one of the 8 lattice points around `p` is reachable: for a
  /// point `p` at clearance r or more, it is then reachable itself (the two,
  /// less than 2 r apart and both clear, have no surface between them).
  bool reachable_near(const Eigen::Vector3d& p) const;
  /// Whether the whole lattice coordinates `at` name a point of the
  /// lattice (a NaN names none).
  bool holds(const Eigen::Vector3d& at) const;
  /// Whether the lattice point nearest to `p` is reachable; that point in
  /// `nearest` (left as it was when `p` lies off the lattice).
  bool nearest_reachable(const Eigen::Vector3d& p, Eigen::Vector3d& nearest) const;
  /// Whether the audit counts a walker at `p` (a point at clearance r or
  /// more): the lattice point nearest to it is reachable, or one of the 4
  /// around it on the level above it (along `up_axis`, `up_sign`) is. That
  /// point may stand up to a spacing across from `p`, off the column a fall
  /// keeps to: this widens the sampled reach by a spacing across, on the
  /// strict side (a contact may be asked of a face a walker only passes
  /// within a spacing of), so that a pose beside a wall or over a floor is
  /// judged whatever the lattice's offset from them, where the nearest point
  /// alone lies nearer than r to the face for the whole face when that
  /// offset is unlucky. Not the 8 around it: standing ends at a height.
  bool reachable_for_walker(const Eigen::Vector3d& p, int up_axis, double up_sign) const;
};

/// Whether face `f` is walkable for `agent`.
bool audit_walkable(const Mesh& mesh, const AuditAgent& agent, int f);

/// Widest spacing, in radii: finer than the agent, so that standing and
/// headroom are sampled several times along its height and across it.
inline constexpr double kWidestLatticeSpacingInRadii = 0.7;

/// The lattice of `spacing` (at most kWidestLatticeSpacingInRadii x r)
/// over `box`, flooded from `seeds` (each a point at clearance >= r). A
/// block of points is judged whole only when the clearance at its middle
/// decides every point with `tol` to spare (1-Lipschitz), else point by
/// point. Fails with `limit_exceeded` past `most_held` points held one by one.
Result<AgentLattice> reach_lattice(const TriangleDistances& distances, const AuditAgent& agent, const Aabb& box,
                                   double spacing, const std::vector<Eigen::Vector3d>& seeds, double tol,
                                   long long most_held, int threads);

/// A face is sampled on at most this many steps a side (about 2 x 10^5
/// poses).
inline constexpr int kMostFaceSampleSteps = 640;

/// The audit's poses touching face `face`: over a triangular lattice of the
/// lattice's spacing on it (at most kMostFaceSampleSteps a side), the points
/// r + 2 tol along its normal, on either side, at clearance r or more, whose
/// lattice samples say it is reachable (a flyer moves from a reachable point
/// to any clear point near it, so one of the 8 around; a walker's by
/// AgentLattice::reachable_for_walker). Calls
/// `visit(pose)` on each until it returns false.
template <class Visit>
void visit_touching_poses(const AgentLattice& lattice, const TriangleDistances& distances, const AuditAgent& agent,
                          double tol, int face, Visit&& visit) {
  const Mesh& mesh = distances.mesh;
  const Eigen::Vector3i& t = mesh.triangles[face];
  const Eigen::Vector3d &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
  const Eigen::Vector3d n = (b - a).cross(c - a);
  if (!(n.norm() > 0.0)) return;
  const Eigen::Vector3d unit = n.normalized();
  const double r = agent.radius;
  // The side count capped so a long sliver cannot ask for billions.
  const double longest = std::max({(b - a).norm(), (c - a).norm(), (c - b).norm()});
  const int steps =
      static_cast<int>(std::clamp(std::ceil(longest / lattice.spacing), 1.0, double(kMostFaceSampleSteps)));
  for (int u = 0; u <= steps; ++u)
    for (int v = 0; u + v <= steps; ++v) {
      const double s = (u + 1.0 / 3.0) / (steps + 1.0), w = (v + 1.0 / 3.0) / (steps + 1.0);
      const Eigen::Vector3d on_face = a + s * (b - a) + w * (c - a);
      for (double side : {1.0, -1.0}) {
        const Eigen::Vector3d pose = on_face + side * (r + 2.0 * tol) * unit;
        const bool reachable = agent.walking ? lattice.reachable_for_walker(pose, agent.up_axis, agent.up_sign)
                                             : lattice.reachable_near(pose);
        if (distances.clearance(pose, r) < r || !reachable) continue;
        if (!visit(pose)) return;
      }
    }
}

/// The audit's reach for `options` over `scene`: the agent resolved (a
/// walker with nothing to stand on flies), the lattice spanning the scene's
/// box grown by r (walking: and up by climb + H - r) at the given spacing or
/// the default widened to fit, flooded from the given seeds or the
/// definition's (with neither, every clear point is reachable).
struct AuditReach {
  AuditAgent agent;
  double tol = 0.0;
  AgentLattice lattice;
};
Result<AuditReach> audit_reach(const PreparedMesh& scene, const TriangleDistances& distances,
                               const MovementAuditOptions& options, int threads);

/// How near a reached centre must come to the segment between two points
/// of touched faces to part them (movement_hull_bound): r - E - 2 tol.
/// Fails with `invalid_argument` when that leaves no room above 0.
Result<double> parting_reach(double radius, double slop, double tol);

/// The hull bound over a reach already found, `parting` from parting_reach:
/// movement_hull_bound's work, which audit_movement shares. Reports its
/// fraction done to `progress` (may be empty) from the calling thread.
MovementHullBound hull_bound_on_reach(const TriangleDistances& distances, const AuditReach& reach, double parting,
                                      int threads, const std::function<void(double)>& progress);

} // namespace hullcover::validate::detail
