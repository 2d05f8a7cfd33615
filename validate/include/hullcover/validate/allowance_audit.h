#pragma once
/// \file allowance_audit.h
/// The audit of a covering made with an allowance (`--agent-radius r`,
/// `--max-deviation E`; README "Agent-exact coverings"), by a route of its
/// own: it shares no proof with the decomposer (lib/covering's
/// loss_allowance.h cuts polytopes into cells; this walks the probe's rays).
///
/// Both checks run along the accessible-space probe's open rays
/// (accessible_space.h: from points of every face along its normal, and
/// beyond every open edge), and both decide each ray over ALL its points,
/// not at samples: distance to the mesh and distance to the hulls are
/// 1-Lipschitz along a ray, so an interval whose end values bound it away
/// from a violation holds none, and one that does not is halved. The
/// bisection stops at intervals no longer than tol (decided within tol) or
/// at kMaxEvaluationsPerRay, where the ray counts as undecided: a finding,
/// never a pass.
///
/// - max deviation: every point a hull takes from a ray (its stretches
///   deeper than tol inside a hull) must lie within E + tol of the mesh.
///   The farthest such point, within tol, and where it is, are reported.
/// - agent radius: every point c of a ray is a candidate ball centre; when
///   its clearance (distance to the nearest triangle) is at least r, the
///   ball of radius r around it is reachable space and must lie no deeper
///   than tol in any hull: c's distance to every hull at least r - tol.
///   With E set as well, both are judged (the two knobs combine as both
///   promises, as in the decomposer).
/// Ball centres lie on the probe's rays, so their spacing across rays is the
/// probe's resolution: a covering that takes reachable space only between
/// rays is not seen here, but by the proxies (behaviour_equivalence.h), which
/// run at radius r.

#include <Eigen/Core>

#include <optional>

namespace hullcover::validate {

/// How many distance evaluations one ray may use, by default, before it is
/// counted undecided (a finding): a bound on the work, never a pass.
/// Bisection stops at intervals of tol, so a ray needs at most 2 per tol of
/// its length near hulls (plus 2 per stretch): it runs out only past about
/// 2^17 tol of that length where every centre is clear yet near a hull,
/// which only enclosed space allows (a tall shaft beside a filled void). A
/// map's diagonal is about 10^5 of its own tol; a small map's ray crossing
/// a world of larger ones may need more. Each evaluation costs up to a
/// millisecond there, hence a bound at all.
inline constexpr int kMaxEvaluationsPerRay = 1 << 18;

/// What a covering was allowed to take beyond exact mode.
struct AllowanceOptions {
  std::optional<double> agent_radius;  ///< r, scene units, finite and > 2 tol; none: no agent check
  std::optional<double> max_deviation; ///< E, scene units, finite and > 0; none: no deviation bound
  /// The bound on one ray's distance evaluations (>= 2); past it the ray is
  /// undecided, a finding. Raise it to decide longer rays at more cost.
  int max_evaluations_per_ray = kMaxEvaluationsPerRay;
  /// Either knob set: the audit judges the allowance instead of exact mode.
  bool any() const { return agent_radius.has_value() || max_deviation.has_value(); }
};

/// A ball of radius r, clear of every triangle by r, reaching into a hull.
struct ReachPlace {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero(); ///< the ball's centre, scene coordinates
  int face = -1;                                    ///< the face whose ray it lies on; -1 for no place
  int hull = -1;                                    ///< the nearest hull
  double depth = 0.0;     ///< r minus its distance to the hull: how deep the ball reaches in, scene units
  double clearance = 0.0; ///< its distance to the nearest triangle (>= r), scene units
  bool opening = false;   ///< on an opening ray
};

/// A point of a probe ray.
struct RayPoint {
  Eigen::Vector3d point = Eigen::Vector3d::Zero(); ///< scene coordinates
  int face = -1;                                   ///< the face whose ray it lies on; -1 for no point
  bool opening = false;                            ///< on an opening ray
};

/// What the allowance audit found.
struct AllowanceReport {
  AllowanceOptions options; ///< the knobs judged
  /// The farthest point any hull takes from an open ray, as its distance
  /// from the mesh (scene units, an upper bound within tol of the true
  /// farthest), whatever the knobs: the deviation a user of the covering
  /// sees. 0 when nothing is lost.
  double max_lost_deviation = 0.0;
  Eigen::Vector3d farthest_point = Eigen::Vector3d::Zero(); ///< where (the lower end of that bound)
  int farthest_face = -1;                                   ///< the face whose ray it lies on; -1 when nothing is lost
  int farthest_hull = -1;                                   ///< the hull it lies in
  long lost_stretches = 0;                                  ///< stretches of open rays inside hulls, all judged
  long beyond_deviation = 0; ///< with E and no r: rays losing a point farther than E + tol (violations)
  long centre_rays = 0;      ///< with r: rays whose ball centres were decided
  long reach_lost = 0;       ///< with r: rays holding a reachable ball deeper than tol in a hull (violations)
  ReachPlace deepest_reach;  ///< the deepest such ball (hull -1 when none)
  /// With r: balls clear of the mesh that reach into a hull only where the
  /// strict definition's space is enclosed (the point they reach deepest
  /// lies on a front ray, parallel to the ball's own, that ends on the back
  /// of a face: under a one-sided table top). Exact mode may fill that
  /// space too; reported, allowed.
  long enclosed_balls = 0;
  long undecided = 0; ///< rays or stretches out of evaluations (counted as violations)
  /// Where the first undecided ray (in ray order) was given up: a point of
  /// the interval it was halving; face -1 when no ray is undecided.
  RayPoint first_undecided;

  /// No finding under the knobs set.
  bool clean() const { return beyond_deviation == 0 && reach_lost == 0 && undecided == 0; }
};

} // namespace hullcover::validate
