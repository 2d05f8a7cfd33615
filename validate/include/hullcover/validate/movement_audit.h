#pragma once
/// \file movement_audit.h
/// The audit of a movement covering (docs/definitions-and-proofs.md,
/// "Movement coverings"), by another route than the decomposer's: it finds
/// reachable agent centres on a lattice of its own (its own clearance
/// samples, its own standing test and flood), and asks the hulls through
/// the runtime (HullWorld) whether
///  - any reachable centre's ball of radius r sinks more than E + tol into
///    a hull (it sinks into no triangle: its clearance is at least r), and
///  - any agent touching a face at a reachable pose (its centre r + 2 tol
///    from the face) has no hull within r + E + 3 tol of its centre (its
///    contact vanished).
/// Sampled, not proven: a lattice of spacing s can miss a violation no
/// deeper than s * sqrt(3) / 2 beyond the slop between its points.

#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/covering/movement_options.h"
#include "hullcover/geometry/status.h"
#include "hullcover/mesh/prepared_mesh.h"

#include <Eigen/Core>

#include <functional>
#include <optional>
#include <vector>

namespace hullcover::validate {

/// The lattice spans at most this many points over the scene's box,
/// counted in whole blocks of 16^3 (about 6 bytes a block). The default
/// spacing is widened to fit, up to 0.7 x r (the widest that keeps its
/// flood out of walls); a scene that needs more is refused.
inline constexpr long long kMostAuditLatticePoints = 1LL << 36;
/// ... and holds at most this many one by one, a byte each (1 GiB): the
/// blocks near surfaces (open air, solid ground and, walking, space no
/// walker stands in cost nothing more). Past it the audit is refused.
inline constexpr long long kMostAuditLatticePointsHeld = 1LL << 30;
/// The default spacing, in radii.
inline constexpr double kDefaultAuditSpacingInRadii = 0.5;

/// A lower bound on the hulls of any covering that keeps the promise over
/// the audit's reach (docs/definitions-and-proofs.md, "A lower bound on the
/// hulls"): points of faces a reached agent touches (each lies in a hull),
/// pairwise parted by a reached centre nearer than r - E - 2 tol to the
/// segment between them (no hull holds both). Found greedily, so a bound,
/// not the least count.
struct MovementHullBound {
  int hulls_needed = 0;                ///< the points found: no covering has fewer hulls
  long long points_tried = 0;          ///< points of touched faces tried
  std::vector<Eigen::Vector3d> points; ///< the points, pairwise parted
};

/// The agent, as the covering was made for it (MovementOptions' meaning
/// and defaults), and the lattice.
struct MovementAuditOptions {
  MovementOptions agent;
  double spacing = 0.0; ///< lattice spacing, scene units; 0: kDefaultAuditSpacingInRadii x r
  /// Also bound the hulls any covering needs (movement_hull_bound), on the
  /// audit's own reach rather than a second one.
  bool hull_bound = false;
  /// Called now and then with the fraction of the work done (0..1, never
  /// decreasing): the reach, the centres, the touching poses, then the
  /// bound; always from the thread that called; may be empty.
  std::function<void(double)> progress;
};

/// What the audit found.
struct MovementAuditReport {
  double spacing = 0.0;            ///< the lattice spacing used
  double slop = 0.0, height = 0.0; ///< as resolved from the options
  long long lattice_points = 0;
  long long clear_points = 0;     ///< at clearance >= r (walking: of those near walkable faces and below them)
  long long reachable_points = 0; ///< of those, reachable
  long long sinking = 0;          ///< reachable centres sinking more than E + tol into a hull
  double deepest = 0.0;           ///< the deepest sinking of a reachable centre's ball into a hull
  Eigen::Vector3d deepest_at = Eigen::Vector3d::Zero();
  int deepest_hull = -1;
  long long touching_poses = 0; ///< reachable poses touching a face
  long long contacts_lost = 0;  ///< of those, with no hull within r + E + 3 tol
  Eigen::Vector3d first_lost_at = Eigen::Vector3d::Zero();
  /// With MovementAuditOptions::hull_bound: the bound.
  std::optional<MovementHullBound> hull_bound;
  /// No centre sinking deeper than the slop and no contact lost.
  bool clean() const { return sinking == 0 && contacts_lost == 0; }
};

/// Audits `hulls` against `scene` for the agent of `options`. Fails with
/// `invalid_argument` for options out of range or a seed too near the
/// triangles, as HullWorld::build does, and with the bound as
/// movement_hull_bound does.
Result<MovementAuditReport> audit_movement(const PreparedMesh& scene, const std::vector<bvh::RuntimeHull>& hulls,
                                           const MovementAuditOptions& options, int threads);

/// The bound for the agent of `options` over `scene`, on the audit's own
/// reach (the same lattice as audit_movement). Fails as audit_movement does
/// for options out of range, and with `invalid_argument` when the slop lies
/// within 2 tol of the radius (no room left to part two points).
Result<MovementHullBound> movement_hull_bound(const PreparedMesh& scene, const MovementAuditOptions& options,
                                              int threads);

} // namespace hullcover::validate
