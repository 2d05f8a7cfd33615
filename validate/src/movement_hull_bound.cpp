#include "hullcover/validate/movement_audit.h"

#include "agent_lattice.h"
#include "progress_span.h"

#include "hullcover/geometry/parallel_for.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <exception>
#include <string>

namespace hullcover::validate {
namespace {

using detail::AgentLattice;

// Points of a segment are searched for a reachable centre this far apart,
// in lattice spacings: a centre beside the segment is found from the
// sample nearest its foot.
constexpr double kSegmentStepInSpacings = 0.5;
// Points nearer than this many radii count toward how many points share a
// hull with a point (farther ones rarely do, and cost a segment each).
constexpr double kNeighbourhoodInRadii = 8.0;
// An agent is posed this fraction of the reach short of it, against the
// rounding of its offset; the rounding of its coordinates is within the
// 2 tol kept below r - E.
constexpr double kPoseInsideReach = 1e-9;
// A segment is sampled on at most this many steps (a segment across a
// scene of 2^23 lattice spacings).
constexpr int kMostSegmentSteps = 1 << 24;
// Chosen points nearer than this many radii to a new one are asked first:
// a point that shares a hull with one of them usually shares it with a
// near one, and that is found without asking the far ones.
constexpr double kNearChosenInRadii = 4.0;
// The chosen points one task asks, when the threads ask the far ones.
constexpr int kChosenPerTask = 64;
// Progress: the reports a stage makes, and the stages' shares of the
// bound's time (on the shared levels: the touched faces a few percent, the
// sharing counts and the greedy choice each from a tenth to nine tenths).
constexpr int kBoundProgressSteps = 64;
constexpr double kTouchedFacesShare = 0.02, kSharingShare = 0.48;

// Whether a reachable centre lies nearer than `reach` to a point or a
// segment, sampled: a "no" may miss one, a "yes" never errs. At a point x,
// the nearest lattice point counts when it is reachable; else the agent is
// posed `reach` less a rounding margin from x, straight away
// from the nearest triangle, and counts when the audit would pose it there
// (clearance r or more, its lattice sample reachable).
struct ReachedNear {
  const AgentLattice& lattice;
  const detail::TriangleDistances& distances;
  const detail::AuditAgent& agent;
  double reach;

  bool near_point(const Eigen::Vector3d& x) const {
    // The lattice point nearest to x, when reachable and near enough: in
    // open space most samples are decided so, without a distance.
    Eigen::Vector3d nearest;
    if (lattice.nearest_reachable(x, nearest) && (nearest - x).norm() < reach) return true;
    const double r = agent.radius;
    // The nearest point of the triangles nearer than r to x; none (foot left
    // at x): x itself may be a centre. On a triangle, x is judged as a pose.
    Eigen::Vector3d foot = x;
    distances.nearest(x, r, foot);
    const Eigen::Vector3d away = x - foot;
    const bool clear_at_x = !(away.norm() > 0.0);
    const Eigen::Vector3d pose =
        clear_at_x ? x : Eigen::Vector3d(x + (reach * (1.0 - kPoseInsideReach)) * away.normalized());
    const bool reachable =
        agent.walking ? lattice.reachable_for_walker(pose, agent.up_axis, agent.up_sign) : lattice.reachable_near(pose);
    return reachable && distances.clearance(pose, r) >= r;
  }

  // The segment's samples in the order of halving: its middle first, where
  // the free space between two faces most often lies.
  bool near_segment(const Eigen::Vector3d& p, const Eigen::Vector3d& q) const {
    const double step = kSegmentStepInSpacings * lattice.spacing;
    const double length = (q - p).norm();
    // A power of 2 of steps, so that the halving's first sample is the middle.
    int steps = 1;
    while (steps < kMostSegmentSteps && steps * step < length) steps *= 2;
    const auto at = [&](int i) { return Eigen::Vector3d(p + (q - p) * (double(i) / steps)); };
    if (near_point(at(0))) return true;
    for (int s = steps / 2; s >= 1; s /= 2)
      for (int i = s; i <= steps; i += 2 * s)
        if (near_point(at(i))) return true;
    return near_point(at(steps));
  }
};

Result<MovementHullBound> run_bound(const PreparedMesh& scene, const MovementAuditOptions& options, int threads) {
  // The options refused before the reach is found.
  const double tol = scene.tolerance.largest_length();
  const Result<AgentShape> shape = resolve_agent_shape(options.agent, tol);
  if (!shape.ok()) return shape.status();
  const Result<double> parting = detail::parting_reach(shape.value().radius, shape.value().slop, tol);
  if (!parting.ok()) return parting.status();
  const detail::TriangleDistances distances(scene.mesh);
  // The reach's share of the progress, a guess: on the shared levels the
  // reach takes from a twentieth of the bound's time to more than all of it.
  constexpr double kReachShareAlone = 0.1;
  Result<detail::AuditReach> reach = detail::audit_reach(scene, distances, options, threads);
  if (!reach.ok()) return reach.status();
  if (options.progress) options.progress(kReachShareAlone);
  return detail::hull_bound_on_reach(distances, reach.value(), parting.value(), threads,
                                     detail::progress_span(options.progress, kReachShareAlone, 1.0 - kReachShareAlone));
}

} // namespace

namespace detail {

Result<double> parting_reach(double radius, double slop, double tol) {
  // Promise (1) keeps every reachable centre r - E away from every hull,
  // and the audit lets a ball sink E + tol: a hull holding two points (each
  // within tol of where the face puts it) keeps their segment r - E - 2 tol
  // from every reachable centre.
  const double parting = radius - slop - 2.0 * tol;
  if (!(parting > 0.0)) return Status{StatusCode::invalid_argument, "the slop leaves no room below the agent radius"};
  return parting;
}

MovementHullBound hull_bound_on_reach(const TriangleDistances& distances, const AuditReach& reach, double parting,
                                      int threads, const std::function<void(double)>& progress) {
  const Mesh& mesh = distances.mesh;
  const AuditAgent& agent = reach.agent;
  const double tol = reach.tol;
  const AgentLattice& lattice = reach.lattice;
  const ReachedNear near{lattice, distances, agent, parting};

  // Promise (2): every point of a face a reachable agent touches lies in a
  // hull. Touched, to the tolerance: the audit poses an agent touching it
  // (r + 2 tol away), and no other triangle is nearer than r + tol to that
  // pose, so the agent moved tol straight to the face stays clear, within
  // r + tol of it. Points of such a face: the centroid and the middles
  // between it and its corners (two points of one face never part: a
  // centre is at least r from it).
  std::vector<char> is_touched(mesh.triangles.size(), 0);
  const auto mark_touched = [&](int f) {
    detail::visit_touching_poses(lattice, distances, agent, tol, f, [&](const Eigen::Vector3d& pose) {
      const double clear = agent.radius + tol;
      is_touched[f] = distances.clearance(pose, clear) >= clear;
      return !is_touched[f];
    });
  };
  parallel_for_reporting(static_cast<int>(mesh.triangles.size()), threads, kBoundProgressSteps, mark_touched,
                         progress_span(progress, 0.0, kTouchedFacesShare));
  std::vector<Eigen::Vector3d> candidates;
  for (int f = 0; f < static_cast<int>(mesh.triangles.size()); ++f) {
    if (!is_touched[f]) continue;
    const Eigen::Vector3i& t = mesh.triangles[f];
    const Eigen::Vector3d &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
    const Eigen::Vector3d g = (a + b + c) / 3.0;
    for (const Eigen::Vector3d& x :
         {g, Eigen::Vector3d(0.5 * (g + a)), Eigen::Vector3d(0.5 * (g + b)), Eigen::Vector3d(0.5 * (g + c))})
      candidates.push_back(x);
  }
  // Greedy: a point joins when a reachable centre parts it from every point
  // already chosen. Points that share a hull with few others nearby come
  // first (a point in a corner, which shares one with both walls, would
  // shut out both); ties in an order fixed by a hash of their index.
  const double neighbourhood = kNeighbourhoodInRadii * agent.radius;
  std::vector<std::pair<std::uint64_t, int>> by_cell(candidates.size());
  const auto cell_of = [&](const Eigen::Vector3d& x) {
    return Eigen::Vector3i(((x - lattice.origin) / neighbourhood).array().floor().cast<int>());
  };
  const auto key_of = [](const Eigen::Vector3i& c) {
    return (std::uint64_t(std::uint32_t(c.x()) & 0x1fffff) << 42) |
           (std::uint64_t(std::uint32_t(c.y()) & 0x1fffff) << 21) | std::uint64_t(std::uint32_t(c.z()) & 0x1fffff);
  };
  for (size_t i = 0; i < candidates.size(); ++i) by_cell[i] = {key_of(cell_of(candidates[i])), static_cast<int>(i)};
  std::sort(by_cell.begin(), by_cell.end());
  std::vector<int> sharing(candidates.size(), 0);
  const auto count_sharing = [&](int i) {
    const Eigen::Vector3i c = cell_of(candidates[i]);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const std::uint64_t key = key_of(c + Eigen::Vector3i(dx, dy, dz));
          auto it = std::lower_bound(by_cell.begin(), by_cell.end(), std::make_pair(key, -1));
          for (; it != by_cell.end() && it->first == key; ++it)
            if (it->second != i && (candidates[it->second] - candidates[i]).norm() < neighbourhood &&
                !near.near_segment(candidates[i], candidates[it->second]))
              ++sharing[i];
        }
  };
  parallel_for_reporting(static_cast<int>(candidates.size()), threads, kBoundProgressSteps, count_sharing,
                         progress_span(progress, kTouchedFacesShare, kSharingShare));
  std::vector<int> order(candidates.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  const auto mixed = [](std::uint64_t x) {
    x ^= x >> 33;
    x *= 0xff51afd7ed558ccdULL;
    x ^= x >> 33;
    return x;
  };
  std::sort(order.begin(), order.end(), [&](int i, int j) {
    if (sharing[i] != sharing[j]) return sharing[i] < sharing[j];
    return mixed(i) < mixed(j);
  });

  MovementHullBound bound;
  bound.points_tried = static_cast<long long>(candidates.size());
  const double near_chosen = kNearChosenInRadii * agent.radius;
  std::vector<int> asked;
  const double greedy_start = kTouchedFacesShare + kSharingShare;
  const size_t report_every = std::max<size_t>(1, order.size() / kBoundProgressSteps);
  for (size_t n = 0; n < order.size(); ++n) {
    if (progress && n % report_every == 0) progress(greedy_start + (1.0 - greedy_start) * n / order.size());
    const int i = order[n];
    const Eigen::Vector3d& q = candidates[i];
    asked.clear();
    for (int k = 0; k < static_cast<int>(bound.points.size()); ++k)
      if ((bound.points[k] - q).squaredNorm() < near_chosen * near_chosen) asked.push_back(k);
    bool parted = true;
    for (int k : asked)
      if (!near.near_segment(bound.points[k], q)) {
        parted = false;
        break;
      }
    if (!parted) continue;
    // The farther points on the threads, in tasks of a few: whether q is
    // parted from all of them does not depend on which thread asks.
    const int chosen = static_cast<int>(bound.points.size());
    const int tasks = (chosen + kChosenPerTask - 1) / kChosenPerTask;
    std::atomic<bool> shares{false};
    parallel_for(tasks, tasks > 1 ? threads : 1, [&](int task) {
      const int last = std::min(chosen, (task + 1) * kChosenPerTask);
      for (int k = task * kChosenPerTask; k < last && !shares.load(std::memory_order_relaxed); ++k)
        if ((bound.points[k] - q).squaredNorm() >= near_chosen * near_chosen && !near.near_segment(bound.points[k], q))
          shares.store(true, std::memory_order_relaxed);
    });
    if (!shares.load()) bound.points.push_back(q);
  }
  bound.hulls_needed = static_cast<int>(bound.points.size());
  if (progress) progress(1.0);
  return bound;
}

} // namespace detail

Result<MovementHullBound> movement_hull_bound(const PreparedMesh& scene, const MovementAuditOptions& options,
                                              int threads) {
  try {
    return run_bound(scene, options, threads);
  } catch (const std::exception& e) {
    return Status{StatusCode::internal_error, std::string("movement hull bound failed: ") + e.what()};
  }
}

} // namespace hullcover::validate
