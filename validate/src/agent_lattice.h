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

#include <cstdint>
#include <vector>

namespace hullcover::validate::detail {

/// Distances to the scene's triangles.
struct TriangleDistances {
  const Mesh& mesh;
  AabbTree tree;
  explicit TriangleDistances(const Mesh& m);
  /// Distance from p to the nearest triangle, or `limit` when none is nearer.
  double clearance(const Eigen::Vector3d& p, double limit) const;
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
  /// Whether the lattice point nearest to `p` is reachable.
  bool reachable_nearest(const Eigen::Vector3d& p) const;
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

} // namespace hullcover::validate::detail
