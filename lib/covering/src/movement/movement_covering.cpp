#include "hullcover/covering/movement_covering.h"

#include "movement/movement_merging.h"
#include "movement/reach_grid.h"
#include "movement/scene_clearance.h"

#include "hullcover/geometry/parallel_for.h"

#include <chrono>
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

  const Clock::time_point merging = Clock::now();
  const detail::MovementContext context{mesh, clearance, grid.value(), agent, tol};
  detail::MovementMerger merger(context, prepared.connectivity, faces, agent.radius, options.max_hull_vertices, stats,
                                options.progress);
  merger.run();
  Covering& covering = result.covering;
  covering.hulls = merger.hulls();
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
