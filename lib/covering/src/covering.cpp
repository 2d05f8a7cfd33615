#include "hullcover/covering/covering.h"

#include "hullcover/covering/merge_cells.h"
#include "hullcover/geometry/tolerances.h"
#include "hullcover/mesh/mesh_islands.h"

#include "cells/cell_merging.h"
#include "cells/local_frame.h"
#include "merging/patch_merging.h"
#include "validity/scene_index_build.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

namespace hullcover {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

Status check_options(const DecomposeOptions& o) {
  if (o.bar_half_length && !(std::isfinite(*o.bar_half_length) && *o.bar_half_length > 0.0))
    return {StatusCode::invalid_argument, "bar half-length must be a positive length"};
  if (o.free_space_reach && !(std::isfinite(*o.free_space_reach) && *o.free_space_reach > 0.0))
    return {StatusCode::invalid_argument, "free-space reach must be a positive length"};
  if (o.prism_thickness_cap && !(std::isfinite(*o.prism_thickness_cap) && *o.prism_thickness_cap >= 0.0))
    return {StatusCode::invalid_argument, "prism thickness cap must be a length >= 0"};
  if (o.near_merge_distance && !(std::isfinite(*o.near_merge_distance) && *o.near_merge_distance >= 0.0))
    return {StatusCode::invalid_argument, "near-merge distance must be a length >= 0"};
  if (o.agent_radius && !(std::isfinite(*o.agent_radius) && *o.agent_radius >= 0.0))
    return {StatusCode::invalid_argument, "agent radius must be a length >= 0"};
  if (o.max_deviation && !(std::isfinite(*o.max_deviation) && *o.max_deviation >= 0.0))
    return {StatusCode::invalid_argument, "max deviation must be a length >= 0"};
  if (has_allowance(o) && o.conditions != ValidityMode::exact)
    return {StatusCode::invalid_argument,
            "agent radius and max deviation relax exact mode: use them with exact conditions"};
  if (o.cell_size && !(std::isfinite(*o.cell_size) && *o.cell_size >= 0.0))
    return {StatusCode::invalid_argument, "cell size must be a length >= 0 (0: no cells)"};
  if (o.threads < 0) return {StatusCode::invalid_argument, "threads must be >= 0 (0: every core)"};
  if (o.order_tries < 1) return {StatusCode::invalid_argument, "order tries must be at least 1"};
  if (o.max_hull_vertices < 8)
    return {StatusCode::invalid_argument, "max hull vertices must be at least 8 (a prism over a quad)"};
  if (o.max_hull_triangles && *o.max_hull_triangles < kFewestTrianglesOfAHullLimit)
    return {StatusCode::invalid_argument, "max hull triangles must be at least 12 (a box)"};
  return Status::success();
}

} // namespace

namespace detail {

Result<std::unique_ptr<DecompositionStages>> prepare_stages(const PreparedSceneView& scene,
                                                            const DecomposeOptions& options, MadeStages* made) {
  if (Status s = check_options(options); !s.ok()) return s;
  const Eigen::Vector3d origin = local_frame_origin(scene);
  auto stages = origin.isZero() ? std::make_unique<DecompositionStages>(scene)
                                : std::make_unique<DecompositionStages>(
                                      std::make_unique<const PreparedMesh>(in_local_frame(scene, origin)), origin);
  const PreparedSceneView& prepared = stages->prepared;
  Covering& covering = stages->covering;
  covering.options = options;
  covering.tolerance = scene.tolerance; // the scene's zones, in its own frame
  // Default lengths scale with islands, not the whole world: each island's
  // near merges and prisms follow its own diagonal, so a map keeps its hulls
  // when laid beside others. The values kept in `covering` are the largest
  // island's (the prism cap is also how far any hull may reach).
  const double diagonal = prepared.tolerance.largest_island;
  const bool exact = options.conditions == ValidityMode::exact;
  covering.bar_half_length = options.bar_half_length.value_or(
      exact ? kExactBarHalfLengthInTolerances * prepared.tolerance.length : kDefaultBarHalfLengthRelative * diagonal);
  covering.prism_thickness_cap = options.prism_thickness_cap.value_or(kDefaultPrismCapRelative * diagonal);
  // Free space has no distance cap (docs/definitions-and-proofs.md) unless the user gives one.
  const double hull_margin = covering.prism_thickness_cap;
  covering.free_space_capped = options.free_space_reach.has_value();
  covering.free_space_reach = options.free_space_reach.value_or(uncapped_free_space_reach(prepared, hull_margin));
  covering.near_merge_distance =
      options.near_merge_distance.value_or(exact ? kDefaultNearMergeRelative * diagonal : 0.0);
  covering.dissolve = options.dissolve.value_or(exact);
  CoveringStatistics& stats = covering.statistics;
  stats.faces = static_cast<int>(prepared.mesh.triangles.size());

  const Clock::time_point start = Clock::now();
  stages->cells = made ? std::move(made->cells) : lay_out_cells(prepared, prepared.islands, options.cell_size);
  covering.island_extents.clear();
  for (const Aabb& box : prepared.islands.boxes)
    covering.island_extents.push_back(box.diagonal() > 0.0 ? box.diagonal() : prepared.tolerance.local_extent);
  // Each island's checks at its place's tolerance: its hulls lie in its box but
  // for prisms, which stop short of every zone of a smaller tolerance
  // (patch_hulls.cpp). The audit, judging each hull at its own box's
  // (PlaceTolerance), is then never stricter than the merge was.
  stages->island_tolerance = prepared.tolerance.island_lengths;
  // Patches never span islands unless the whole scene is one cell, so every
  // hull lies in its island's box grown by the prism cap: the sweeps need be
  // indexed only there.
  std::vector<Aabb> hull_zones;
  if (!(options.cell_size && *options.cell_size == 0.0))
    for (const Aabb& box : prepared.islands.boxes) hull_zones.push_back(grown(box, hull_margin));
  BarOptions bars;
  bars.half_length = covering.bar_half_length;
  bars.material_boundaries = options.keep_materials_apart;
  bars.mode = options.conditions;
  bars.free_space_reach = covering.free_space_reach;
  bars.hull_margin = hull_margin;
  bars.agent_radius = options.agent_radius.value_or(0.0);
  bars.max_deviation = options.max_deviation.value_or(0.0);
  bars.hull_zones = std::move(hull_zones);
  bars.threads = options.threads;
  for (int island = 0; island < static_cast<int>(prepared.islands.boxes.size()); ++island)
    bars.half_length_of_island.push_back(island_bar_half_length(*stages, island));
  if (made) {
    stages->index_data = std::move(made->index);
    stages->index_data.prepared = &prepared;
  } else {
    stages->index_data = build_scene_index(prepared, bars);
  }
  for (int island = 0; island < static_cast<int>(prepared.islands.boxes.size()); ++island) {
    stages->island_index.emplace_back(stages->index_data, stages->island_tolerance[island],
                                      covering.island_extents[island]);
    stages->island_index.back().place = prepared.tolerance.island_place[island];
  }
  stages->island_index.emplace_back(stages->index_data, prepared.tolerance.length, prepared.tolerance.largest_island);
  covering.cell_sizes = stages->cells.island_cell_size;
  stats.islands = static_cast<int>(prepared.islands.boxes.size());
  stats.cells = static_cast<int>(stages->cells.faces_of_cell.size());
  stats.seconds_index = seconds_since(start);
  return Result<std::unique_ptr<DecompositionStages>>(std::move(stages));
}

} // namespace detail

Result<Covering> decompose(const PreparedMesh& prepared, const DecomposeOptions& options) {
  // No exception may leave the library (a game server links it): out of
  // memory, or a bug, comes back as a status.
  try {
    Result<std::unique_ptr<detail::DecompositionStages>> stages = detail::prepare_stages(view_of(prepared), options);
    if (!stages.ok()) return stages.status();
    const Clock::time_point start = Clock::now();
    std::vector<detail::CellResult> results = detail::merge_cells(*stages.value(), threads_to_use(options.threads));
    return detail::finish_stages(*stages.value(), std::move(results), seconds_since(start));
  } catch (const std::exception& e) {
    return Status{StatusCode::internal_error, std::string("decomposition failed: ") + e.what()};
  }
}

} // namespace hullcover
