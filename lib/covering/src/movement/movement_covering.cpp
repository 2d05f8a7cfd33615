#include "hullcover/covering/movement_covering.h"

#include "movement/movement_groups.h"
#include "movement/movement_merging.h"
#include "movement/reach_grid.h"
#include "movement/region_tree.h"
#include "movement/scene_clearance.h"

#include "hullcover/covering/covering.h"
#include "hullcover/geometry/parallel_for.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <mutex>
#include <cstdio>
#include <cmath>
#include <string>

namespace hullcover {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

std::string length_text(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

// The agent of `o`, and the decomposer's own limits.
Result<AgentShape> resolve_agent(const MovementOptions& o, double tol) {
  if (o.max_hull_vertices < 8)
    return Status{StatusCode::invalid_argument, "max hull vertices must be at least 8 (a prism over a quad)"};
  if (o.threads < 0) return Status{StatusCode::invalid_argument, "threads must be >= 0 (0: every core)"};
  if (o.faces_per_region < 1) return Status{StatusCode::invalid_argument, "faces per region must be at least 1"};
  return resolve_agent_shape(o, tol);
}

Result<MovementCovering> decompose_checked(const PreparedMesh& prepared, const MovementOptions& options) {
  const double tol = prepared.tolerance.largest_length();
  Result<AgentShape> resolved = resolve_agent(options, tol);
  if (!resolved.ok()) return resolved.status();
  AgentShape agent = resolved.value();
  const int threads = threads_to_use(options.threads);
  const Mesh& mesh = prepared.mesh;
  MovementCovering result;
  MovementStatistics& stats = result.movement;
  stats.radius = agent.radius;
  stats.slop = agent.slop;
  stats.height = agent.height;
  stats.climb = agent.climb;

  const Clock::time_point start = Clock::now();
  const detail::SceneClearance clearance(mesh);
  for (const Eigen::Vector3d& seed : options.seeds) {
    if (!seed.allFinite()) return Status{StatusCode::invalid_argument, "a seed has a coordinate that is not a number"};
    const double d = clearance.nearest(seed, agent.radius).distance;
    if (d < agent.radius)
      return Status{StatusCode::invalid_argument,
                    "seed (" + length_text(seed.x()) + ", " + length_text(seed.y()) + ", " + length_text(seed.z()) +
                        ") is " + length_text(d) + " from the nearest triangle: an agent of radius " +
                        length_text(agent.radius) + " centred there would cut into the scene"};
  }
  std::vector<Eigen::Vector3d> seeds = options.seeds;
  if (seeds.empty()) seeds = detail::default_seeds(clearance, agent, tol);
  // Nothing to stand on: walking falls back to flying, through all clear space.
  if (seeds.empty()) agent.reach = AgentReach::fly;
  stats.reach = agent.reach;
  Result<detail::ReachGrid> grid = build_reach_grid(mesh, clearance, agent, seeds, !options.seeds.empty(), threads);
  if (!grid.ok()) return grid.status();
  stats.grid_cells = grid.value().cell_count();
  stats.reachable_cells = grid.value().reachable_count();
  stats.cell = grid.value().cell;
  stats.seeds = grid.value().seeds_used;

  const int face_count = static_cast<int>(mesh.triangles.size());
  std::vector<char> touched(face_count, 0);
  parallel_for(face_count, threads,
               [&](int f) { touched[f] = face_may_be_touched(grid.value(), clearance, agent, f); });
  std::vector<int> faces;
  for (int f = 0; f < face_count; ++f)
    if (touched[f]) faces.push_back(f);
  stats.touchable_faces = static_cast<int>(faces.size());
  stats.seconds_reach = seconds_since(start);
  if (options.progress) options.progress(0.05);

  // The exact covering's hulls are the first groups where they keep the
  // movement promise (they hold no free space a ray reaches, so walking
  // most do; flying, a hull behind a face a flyer reaches does not): the
  // merging starts from the exact grouping instead of single faces.
  // Without it (a scene exact mode refuses), every face starts alone.
  const Clock::time_point exact_start = Clock::now();
  DecomposeOptions exact;
  exact.threads = options.threads;
  exact.max_hull_vertices = options.max_hull_vertices;
  // Without the dissolving pass (emptying patches into their neighbours),
  // which is most of exact mode's time on levels of rooms: the movement
  // merging that follows joins about as much (the same hulls within 3% on
  // the shared levels, in 25-30% less time on the larger ones:
  // docs/results/agents.md).
  exact.dissolve = false;
  if (options.progress) exact.progress = [&](double done) { options.progress(0.05 + 0.05 * done); };
  std::vector<std::vector<int>> start_groups;
  if (Result<Covering> exact_covering = decompose(prepared, exact); exact_covering.ok())
    for (const CoveringHull& hull : exact_covering.value().hulls) start_groups.push_back(hull.faces);
  stats.seconds_exact = seconds_since(exact_start);
  if (options.progress) options.progress(0.1);

  const Clock::time_point merging = Clock::now();
  const detail::MovementContext context{mesh, clearance, grid.value(), agent, tol};
  // Regions merge on their own, at once; then each cut between two sets of
  // regions merges the pairs across it, once both sides are merged
  // (region_tree.h).
  const detail::RegionTree region_tree = detail::split_into_regions(mesh, faces, options.faces_per_region);
  const std::vector<int>& region_of_face = region_tree.region_of;
  const int regions = std::max(1, region_tree.regions);
  std::vector<std::vector<int>> region_faces(regions);
  std::vector<std::vector<std::vector<int>>> region_starts(regions);
  std::vector<int> region_of(face_count, -1);
  for (size_t i = 0; i < faces.size(); ++i) region_of[faces[i]] = region_of_face[i];
  for (std::vector<int>& group_faces : start_groups) {
    // A group goes whole to the region of its first touchable face.
    const auto first = std::find_if(group_faces.begin(), group_faces.end(), [&](int f) { return region_of[f] >= 0; });
    if (first == group_faces.end()) continue;
    const int region = region_of[*first];
    for (int f : group_faces)
      if (region_of[f] >= 0) region_of[f] = region;
    region_starts[region].push_back(std::move(group_faces));
  }
  for (int f : faces) region_faces[region_of[f]].push_back(f);
  std::vector<std::vector<detail::MovementGroup>> region_groups(regions);
  // Counts per region, then per join: candidates, undecided, merges.
  const std::vector<detail::RegionJoin>& joins = region_tree.joins;
  std::vector<std::array<long long, 3>> counts(regions + joins.size());
  std::mutex progress_mutex;
  size_t tasks_done = 0;
  const auto report = [&] {
    if (!options.progress) return;
    const std::lock_guard<std::mutex> lock(progress_mutex);
    options.progress(0.1 + 0.85 * static_cast<double>(++tasks_done) / static_cast<double>(counts.size()));
  };
  // A join's groups end up where its first region's were.
  detail::run_regions_and_joins(
      region_tree, threads,
      [&](int region) {
    detail::GroupProver prover;
    std::vector<detail::MovementGroup> groups = detail::starting_groups(
        context, region_faces[region], region_starts[region], options.max_hull_vertices, prover);
    detail::MovementMerger merger(context, prepared.connectivity, std::move(groups), {}, agent.radius,
                                  options.max_hull_vertices, prover);
    merger.merge({});
    counts[region] = {prover.candidates, prover.undecided, merger.merges()};
    region_groups[region] = merger.take_groups();
    report();
      },
      [&](int j) {
    const detail::RegionJoin& join = joins[j];
    std::vector<detail::MovementGroup> groups = std::move(region_groups[join.first]);
    std::vector<int> side(groups.size(), 0);
    for (detail::MovementGroup& g : region_groups[join.split]) groups.push_back(std::move(g));
    side.resize(groups.size(), 1);
    region_groups[join.split].clear();
    detail::GroupProver prover;
    detail::MovementMerger merger(context, prepared.connectivity, std::move(groups), side, agent.radius,
                                  options.max_hull_vertices, prover);
    merger.merge({});
    counts[regions + j] = {prover.candidates, prover.undecided, merger.merges()};
    region_groups[join.first] = merger.take_groups();
    report();
  });
  for (const std::array<long long, 3>& c : counts) {
    stats.candidates += c[0];
    stats.undecided += c[1];
    stats.merges += c[2];
  }
  // Every region's groups are now the first's: a group whose faces all
  // lie in other hulls is dropped.
  std::vector<detail::MovementGroup> groups = std::move(region_groups[0]);
  detail::drop_held_groups(context, groups);
  Covering& covering = result.covering;
  covering.hulls = detail::hulls_of_groups(mesh, tol, groups);
  stats.seconds_merging = seconds_since(merging);
  covering.tolerance = prepared.tolerance;
  covering.statistics.faces = face_count;
  covering.statistics.merges = static_cast<int>(stats.merges);
  covering.statistics.seconds_merging = stats.seconds_merging;
  covering.statistics.islands = static_cast<int>(prepared.islands.boxes.size());
  covering.statistics.cells = 1;
  covering.island_extents.assign(prepared.islands.boxes.size(), prepared.tolerance.largest_island);
  covering.cell_sizes.assign(prepared.islands.boxes.size(), 0.0);
  if (options.progress) options.progress(1.0);
  return result;
}

} // namespace

Result<MovementCovering> decompose_for_movement(const PreparedMesh& prepared, const MovementOptions& options) {
  // No exception may leave the library: out of memory, or a bug, comes back as a status.
  try {
    return decompose_checked(prepared, options);
  } catch (const std::exception& e) {
    return Status{StatusCode::internal_error, std::string("movement decomposition failed: ") + e.what()};
  }
}

} // namespace hullcover
