#include "hullcover/validate/movement_audit.h"

#include "agent_lattice.h"
#include "progress_span.h"

#include "hullcover/bvh/hull_world.h"
#include "hullcover/geometry/parallel_for.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

namespace hullcover::validate {
namespace {

using detail::AgentLattice;

using detail::AuditAgent;

Result<AuditAgent> resolve(const MovementOptions& o, double tol) {
  const Result<AgentShape> shape = resolve_agent_shape(o, tol);
  if (!shape.ok()) return shape.status();
  const AgentShape& s = shape.value();
  AuditAgent agent;
  agent.radius = s.radius;
  agent.slop = s.slop;
  agent.height = s.height;
  agent.climb = s.climb;
  agent.min_up_cosine = s.min_up_cosine;
  agent.up_axis = s.up_axis;
  agent.up_sign = s.up_sign;
  agent.walking = s.reach == AgentReach::walk;
  return agent;
}

// The definition's default seeds: r (and 2 tol) in front of each walkable
// face's centroid and of the middles between it and its corners, where clear.
std::vector<Eigen::Vector3d> definition_seeds(const detail::TriangleDistances& distances, const AuditAgent& agent,
                                              double tol) {
  const Mesh& mesh = distances.mesh;
  std::vector<Eigen::Vector3d> seeds;
  for (int f = 0; f < static_cast<int>(mesh.triangles.size()); ++f) {
    if (!detail::audit_walkable(mesh, agent, f)) continue;
    const Eigen::Vector3i& t = mesh.triangles[f];
    const Eigen::Vector3d &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
    const Eigen::Vector3d lift = (agent.radius + 2.0 * tol) * (b - a).cross(c - a).normalized();
    const Eigen::Vector3d g = (a + b + c) / 3.0;
    for (const Eigen::Vector3d& base :
         {g, Eigen::Vector3d(0.5 * (g + a)), Eigen::Vector3d(0.5 * (g + b)), Eigen::Vector3d(0.5 * (g + c))})
      if (distances.clearance(base + lift, agent.radius) >= agent.radius) seeds.push_back(base + lift);
  }
  return seeds;
}

// What one block of the lattice, or one face, found (added up in order).
struct Findings {
  long long clear = 0, reachable = 0, sinking = 0, touching = 0, lost = 0;
  Status failure; ///< a runtime query that failed (the audit then fails with it)
  double deepest = 0.0;
  Eigen::Vector3d deepest_at = Eigen::Vector3d::Zero();
  int deepest_hull = -1;
  Eigen::Vector3d first_lost_at = Eigen::Vector3d::Zero();
};

// The gap from point p to the nearest hull (0 inside one, within tol), and that hull.
Status gap_to_hulls(const bvh::HullWorld& world, const Eigen::Vector3d& p, double tol, double& gap, int& hull) {
  bvh::DistanceRequest request;
  request.shape = bvh::QueryShape::sphere(tol);
  request.pose.translation() = p;
  bvh::DistanceResult result;
  if (Status s = world.distance(request, result); !s.ok()) return s;
  hull = result.hull;
  gap = result.touching ? 0.0 : result.distance + tol;
  return Status::success();
}

} // namespace

namespace detail {

Result<AuditReach> audit_reach(const PreparedMesh& scene, const TriangleDistances& distances,
                               const MovementAuditOptions& options, int threads) {
  const double tol = scene.tolerance.largest_length();
  Result<AuditAgent> resolved = resolve(options.agent, tol);
  if (!resolved.ok()) return resolved.status();
  AuditAgent agent = resolved.value();
  const Mesh& mesh = scene.mesh;
  std::vector<Eigen::Vector3d> seeds = options.agent.seeds;
  for (const Eigen::Vector3d& s : seeds)
    if (!(distances.clearance(s, agent.radius) >= agent.radius))
      return Status{StatusCode::invalid_argument, "a seed lies nearer than the agent radius to the triangles"};
  if (seeds.empty()) seeds = definition_seeds(distances, agent, tol);
  if (seeds.empty()) agent.walking = false; // nothing to stand on: flying, everywhere clear

  Aabb box;
  for (const Eigen::Vector3d& p : mesh.positions) box.extend(p);
  box = grown(box, agent.radius);
  // Room above the highest walkable face for a walker's whole axis.
  if (agent.walking) {
    const double rise = std::min(agent.rise(), box.diagonal() + agent.radius);
    if (agent.up_sign > 0)
      box.max[agent.up_axis] += rise;
    else
      box.min[agent.up_axis] -= rise;
  }
  double spacing = options.spacing > 0.0 ? options.spacing : kDefaultAuditSpacingInRadii * agent.radius;
  const Eigen::Vector3d extent = box.max - box.min;
  // Counted in whole blocks: what the blocks' own numbers take.
  const auto block_points_at = [&](double s) {
    return (((extent / s).array().floor() + 1.0) / BlockBytes::kSide).ceil().prod() * BlockBytes::kCells;
  };
  const auto widest_axis_at = [&](double s) { return ((extent / s).array().floor() + 1.0).maxCoeff(); };
  const auto fits = [&](double s) {
    return block_points_at(s) <= static_cast<double>(kMostAuditLatticePoints) &&
           widest_axis_at(s) < static_cast<double>(kMostCellsAlongAnAxis);
  };
  const double widest = kWidestLatticeSpacingInRadii * agent.radius;
  if (options.spacing > widest)
    return Status{
        StatusCode::invalid_argument,
        "the lattice spacing must be at most " + std::to_string(kWidestLatticeSpacingInRadii) + " x the agent radius"};
  // The default spacing widens to fit; a given one is kept or refused.
  while (options.spacing <= 0.0 && !fits(spacing) && spacing < widest) spacing = std::min(widest, 1.25 * spacing);
  if (!fits(spacing)) {
    char count[32];
    std::snprintf(count, sizeof count, "%.3g", block_points_at(spacing));
    return Status{StatusCode::limit_exceeded, std::string("the movement audit's lattice would span ") + count +
                                                  " points in whole blocks of 16^3 (at most " +
                                                  std::to_string(kMostAuditLatticePoints) + ", and " +
                                                  std::to_string(kMostCellsAlongAnAxis - 1) +
                                                  " along an axis): a wider --lattice-spacing, or a part of the scene"};
  }
  Result<AgentLattice> reached =
      reach_lattice(distances, agent, box, spacing, seeds, tol, kMostAuditLatticePointsHeld, threads);
  if (!reached.ok()) return reached.status();
  AuditReach reach{agent, tol, std::move(reached.value())};
  BlockBytes& flags = reach.lattice.flags;
  if (options.agent.seeds.empty() && !agent.walking && seeds.empty())
    for (long long b = 0; b < flags.block_count(); ++b) {
      if (flags.uniform(b) && (flags.uniform_byte(b) & AgentLattice::kClearPoint))
        flags.uniform_byte(b) |= AgentLattice::kReachablePoint;
      if (std::uint8_t* held = flags.held(b))
        for (int c = 0; c < BlockBytes::kCells; ++c)
          if (held[c] & AgentLattice::kClearPoint) held[c] |= AgentLattice::kReachablePoint;
    }
  return reach;
}

} // namespace detail

namespace {

// Progress: the reports a stage makes, and the shares of the audit's time
// its stages take on the shared levels (the reach, the centres, the
// touching poses the rest), and of the whole when the bound is asked too
// (which takes longer than the audit on most of them).
constexpr int kAuditProgressSteps = 64;
constexpr double kReachShareOfAudit = 0.35, kCentresShareOfAudit = 0.25;
constexpr double kAuditShareWithBound = 0.3;

Result<MovementAuditReport> run(const PreparedMesh& scene, const std::vector<bvh::RuntimeHull>& hulls,
                                const MovementAuditOptions& options, int threads) {
  // Options out of range are refused before the hulls are indexed.
  const Result<AuditAgent> resolved = resolve(options.agent, scene.tolerance.largest_length());
  if (!resolved.ok()) return resolved.status();
  const Result<double> parting =
      detail::parting_reach(resolved.value().radius, resolved.value().slop, scene.tolerance.largest_length());
  if (options.hull_bound && !parting.ok()) return parting.status();
  Result<std::shared_ptr<const bvh::HullWorld>> built = bvh::HullWorld::build(hulls);
  if (!built.ok()) return built.status();
  const bvh::HullWorld& world = *built.value();
  const Mesh& mesh = scene.mesh;
  const detail::TriangleDistances distances(mesh);
  const double audit_share = options.hull_bound ? kAuditShareWithBound : 1.0;
  Result<detail::AuditReach> reached = detail::audit_reach(scene, distances, options, threads);
  if (!reached.ok()) return reached.status();
  if (options.progress) options.progress(audit_share * kReachShareOfAudit);
  const AuditAgent& agent = reached.value().agent;
  const double tol = reached.value().tol;
  const AgentLattice& lattice = reached.value().lattice;
  const BlockBytes& flags = lattice.flags;
  const double spacing = lattice.spacing;
  MovementAuditReport report;
  report.slop = agent.slop;
  report.height = agent.height;
  report.spacing = spacing;
  report.lattice_points = lattice.size();

  // Reachable centres: each ball of radius r sinks at most E + tol into the
  // hulls. Block by block (a block not examined holds no reachable point).
  const double r = agent.radius;
  // Tasks of kBlocksPerTask blocks, so the findings stay few on any box.
  constexpr long long kBlocksPerTask = 256;
  const long long tasks = (flags.block_count() + kBlocksPerTask - 1) / kBlocksPerTask;
  std::vector<Findings> slabs(static_cast<size_t>(tasks));
  const auto check_centres = [&](int task) {
    Findings& f = slabs[task];
    const long long last = std::min(flags.block_count(), (task + 1) * kBlocksPerTask);
    for (long long b = task * kBlocksPerTask; b < last; ++b) {
      if (!flags.classified(b)) continue;
      const Eigen::Vector3i lo = flags.block_at(b) * BlockBytes::kSide;
      const Eigen::Vector3i hi = (lo.array() + BlockBytes::kSide).min(lattice.dims.array());
      long long reachable = 0;
      for (int k = lo.z(); k < hi.z(); ++k)
        for (int j = lo.y(); j < hi.y(); ++j)
          for (int i = lo.x(); i < hi.x(); ++i) {
            f.clear += lattice.clear(i, j, k);
            reachable += lattice.clear(i, j, k) && lattice.reachable(i, j, k);
          }
      f.reachable += reachable;
      if (reachable == 0) continue;
      // The ball of r - E - tol at any point of the block lies in the ball
      // of r - E + (half the block's diagonal) at its middle (tol to spare
      // for rounding): when that touches no hull, no centre here sinks.
      const Eigen::Vector3d first = lattice.point(lo.x(), lo.y(), lo.z());
      const Eigen::Vector3d end = lattice.point(hi.x() - 1, hi.y() - 1, hi.z() - 1);
      bvh::OverlapRequest block_ball;
      block_ball.shape = bvh::QueryShape::sphere(r - agent.slop + 0.5 * (end - first).norm());
      block_ball.pose.translation() = 0.5 * (first + end);
      bvh::TouchResult block_touch;
      if (Status asked = world.touches(block_ball, block_touch); !asked.ok()) {
        f.failure = asked;
        return;
      }
      if (!block_touch.touching) continue;
      for (int k = lo.z(); k < hi.z(); ++k)
        for (int j = lo.y(); j < hi.y(); ++j)
          for (int i = lo.x(); i < hi.x(); ++i) {
            if (!lattice.clear(i, j, k) || !lattice.reachable(i, j, k)) continue;
            const Eigen::Vector3d p = lattice.point(i, j, k);
            // Sinking deeper than E + tol is a ball of radius r - E - tol touching
            // a hull: asked first (a walk that stops at the first hull), the
            // depth only of those that do.
            bvh::OverlapRequest ball;
            ball.shape = bvh::QueryShape::sphere(r - agent.slop - tol);
            ball.pose.translation() = p;
            bvh::TouchResult touch;
            if (Status asked = world.touches(ball, touch); !asked.ok()) {
              f.failure = asked;
              return;
            }
            if (!touch.touching) continue;
            int hull = -1;
            double gap = 0.0;
            if (Status asked = gap_to_hulls(world, p, tol, gap, hull); !asked.ok()) {
              f.failure = asked;
              return;
            }
            const double depth = r - gap;
            ++f.sinking;
            if (depth > f.deepest) {
              f.deepest = depth;
              f.deepest_at = p;
              f.deepest_hull = hull;
            }
          }
    }
  };
  parallel_for_reporting(
      static_cast<int>(tasks), threads, kAuditProgressSteps, check_centres,
      detail::progress_span(options.progress, audit_share * kReachShareOfAudit, audit_share * kCentresShareOfAudit));
  // Touching poses: over points of every face, on either side, r away,
  // where that face is the nearest and a reachable lattice cell holds it.
  std::vector<Findings> faces(mesh.triangles.size());
  const auto check_touching = [&](int face) {
    Findings& f = faces[face];
    detail::visit_touching_poses(lattice, distances, agent, tol, face, [&](const Eigen::Vector3d& pose) {
      ++f.touching;
      // Lost: a ball of r + E + 3 tol there touches no hull.
      bvh::OverlapRequest reach;
      reach.shape = bvh::QueryShape::sphere(r + agent.slop + 3.0 * tol);
      reach.pose.translation() = pose;
      bvh::TouchResult touch;
      if (Status asked = world.touches(reach, touch); !asked.ok()) {
        f.failure = asked;
        return false;
      }
      if (!touch.touching) {
        if (f.lost == 0) f.first_lost_at = pose;
        ++f.lost;
      }
      return true;
    });
  };
  const double poses_start = audit_share * (kReachShareOfAudit + kCentresShareOfAudit);
  parallel_for_reporting(static_cast<int>(mesh.triangles.size()), threads, kAuditProgressSteps, check_touching,
                         detail::progress_span(options.progress, poses_start, audit_share - poses_start));
  for (const std::vector<Findings>* part : {&slabs, &faces})
    for (const Findings& f : *part)
      if (!f.failure.ok()) return Status{StatusCode::internal_error, "a runtime query failed: " + f.failure.message()};
  for (const std::vector<Findings>* part : {&slabs, &faces})
    for (const Findings& f : *part) {
      report.clear_points += f.clear;
      report.reachable_points += f.reachable;
      report.sinking += f.sinking;
      if (f.deepest > report.deepest) {
        report.deepest = f.deepest;
        report.deepest_at = f.deepest_at;
        report.deepest_hull = f.deepest_hull;
      }
      report.touching_poses += f.touching;
      if (f.lost > 0 && report.contacts_lost == 0) report.first_lost_at = f.first_lost_at;
      report.contacts_lost += f.lost;
    }
  if (options.hull_bound)
    report.hull_bound =
        detail::hull_bound_on_reach(distances, reached.value(), parting.value(), threads,
                                    detail::progress_span(options.progress, audit_share, 1.0 - audit_share));
  return report;
}

} // namespace

Result<MovementAuditReport> audit_movement(const PreparedMesh& scene, const std::vector<bvh::RuntimeHull>& hulls,
                                           const MovementAuditOptions& options, int threads) {
  try {
    return run(scene, hulls, options, threads);
  } catch (const std::exception& e) {
    return Status{StatusCode::internal_error, std::string("movement audit failed: ") + e.what()};
  }
}

} // namespace hullcover::validate
