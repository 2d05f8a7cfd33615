#include "hullcover/covering/covering.h"

#include "hullcover/geometry/tolerances.h"

#include "planar_prism.h"
#include "patch_merging.h"
#include "surface_facets.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

namespace hullcover {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

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
    return {StatusCode::invalid_argument, "agent radius and max deviation relax exact mode: use them with exact conditions"};
  if (o.order_tries < 1) return {StatusCode::invalid_argument, "order tries must be at least 1"};
  if (o.max_hull_vertices < 8)
    return {StatusCode::invalid_argument, "max hull vertices must be at least 8 (a prism over a quad)"};
  if (o.max_hull_triangles && *o.max_hull_triangles < kFewestTrianglesOfAHullLimit)
    return {StatusCode::invalid_argument, "max hull triangles must be at least 12 (a box)"};
  return Status::success();
}

// The solid for a planar patch: the thickest allowed beveled prism,
// re-checked as a solid against conditions 1 and 3, flat if that fails.
CoveringHull planar_hull(const SceneIndex& index, const detail::PatchMerger& merger, int patch_id,
                         const detail::Patch& patch, double cap, ConvexHullBuilder& hulls, std::vector<int>& scratch) {
  CoveringHull hull;
  hull.planar = true;
  const FlatPolygon polygon =
      make_flat_polygon(index.mesh().positions, detail::vertices_of_faces(index.mesh(), patch.faces),
                        patch.area_vector.normalized(), index.tol());
  const auto in_patch = [&](int f) { return merger.in_patch(f, patch_id); };
  const std::vector<Plane> sides = beveled_side_planes(index, polygon, in_patch, scratch);
  hull.thickness = allowed_prism_thickness(index, polygon, sides, in_patch, cap, scratch);
  hull.polytope = prism_polytope(polygon, sides, hull.thickness, index.tol(), hulls);
  if (hull.thickness > 0.0 && check_solid_hull(index, hull.polytope, scratch) != Validity::valid) {
    hull.thickness = 0.0;
    hull.polytope = prism_polytope(polygon, sides, hull.thickness, index.tol(), hulls);
  }
  return hull;
}

Result<Covering> decompose_unchecked(const PreparedMesh& prepared, const DecomposeOptions& options);

} // namespace

Result<Covering> decompose(const PreparedMesh& prepared, const DecomposeOptions& options) {
  // No exception may leave the library (a game server links it): out of
  // memory, or a bug, comes back as a status.
  try {
    return decompose_unchecked(prepared, options);
  } catch (const std::exception& e) {
    return Status{StatusCode::internal_error, std::string("decomposition failed: ") + e.what()};
  }
}

namespace {
Result<Covering> decompose_unchecked(const PreparedMesh& prepared, const DecomposeOptions& options) {
  if (Status s = check_options(options); !s.ok()) return s;
  Covering covering;
  covering.options = options;
  covering.tolerance = prepared.tolerance;
  const double diagonal = prepared.tolerance.diagonal;
  const bool exact = options.conditions == ValidityMode::exact;
  covering.bar_half_length = options.bar_half_length.value_or(
      exact ? kExactBarHalfLengthInTolerances * prepared.tolerance.length : kDefaultBarHalfLengthRelative * diagonal);
  covering.prism_thickness_cap = options.prism_thickness_cap.value_or(kDefaultPrismCapRelative * diagonal);
  // Free space has no distance cap (DESIGN.md) unless the user gives one.
  const double hull_margin = covering.prism_thickness_cap;
  covering.free_space_capped = options.free_space_reach.has_value();
  covering.free_space_reach = options.free_space_reach.value_or(uncapped_free_space_reach(prepared, hull_margin));
  covering.near_merge_distance =
      options.near_merge_distance.value_or(exact ? kDefaultNearMergeRelative * diagonal : 0.0);
  covering.dissolve = options.dissolve.value_or(exact);
  CoveringStatistics& stats = covering.statistics;
  stats.faces = static_cast<int>(prepared.mesh.triangles.size());

  Clock::time_point start = Clock::now();
  const SceneIndex index =
      build_scene_index(prepared, {covering.bar_half_length, options.keep_materials_apart, options.conditions,
                                   covering.free_space_reach, hull_margin, options.agent_radius.value_or(0.0),
                                   options.max_deviation.value_or(0.0)});
  stats.seconds_index = seconds_since(start);

  start = Clock::now();
  // Each try keeps its own options and statistics: the merger refers to them.
  struct Try {
    DecomposeOptions options;
    CoveringStatistics statistics;
    std::unique_ptr<detail::PatchMerger> merger;
    int hulls = 0;
  };
  std::unique_ptr<Try> kept;
  for (int attempt = 0; attempt < options.order_tries; ++attempt) {
    auto run = std::make_unique<Try>();
    run->options = options;
    run->options.dissolve = covering.dissolve;
    if (attempt > 0) {
      run->options.order = MergeOrder::random;
      run->options.seed = options.seed + static_cast<std::uint64_t>(attempt - 1);
    }
    if (options.progress)
      run->options.progress = [&options, attempt](double fraction) {
        options.progress((attempt + fraction) / options.order_tries);
      };
    run->statistics = stats;
    run->merger = std::make_unique<detail::PatchMerger>(index, run->options, covering.near_merge_distance,
                                                        run->statistics);
    run->merger->run();
    for (const detail::Patch& patch : run->merger->patches()) run->hulls += patch.alive;
    if (!kept || run->hulls < kept->hulls) {
      run->statistics.kept_try = attempt;
      kept = std::move(run);
    }
  }
  stats = kept->statistics;
  stats.order_tries = options.order_tries;
  const detail::PatchMerger& merger = *kept->merger;
  stats.seconds_merging = seconds_since(start);

  start = Clock::now();
  std::vector<int> scratch;
  ConvexHullBuilder output_hulls;
  const std::vector<detail::Patch>& patches = merger.patches();
  for (int id = 0; id < static_cast<int>(patches.size()); ++id) {
    const detail::Patch& patch = patches[id];
    if (!patch.alive) continue;
    CoveringHull hull;
    if (patch.planar) {
      hull = planar_hull(index, merger, id, patch, covering.prism_thickness_cap, output_hulls, scratch);
      stats.prisms_made_flat += hull.thickness == 0.0;
    } else {
      // Rebuild once with Qhull: hulls grown during merging keep the
      // triangles they grew by, Qhull merges coplanar facets into polygons.
      std::vector<Eigen::Vector3d> points;
      for (int v : patch.hull_vertices) points.push_back(prepared.mesh.positions[v]);
      Result<ConvexPolytope> rebuilt = output_hulls.build(points, patch.hull_vertices);
      ++stats.qhull_calls;
      // The hull validated during merging may differ from the rebuilt one by
      // up to tol (points within tol of it were not added): the rebuilt hull
      // is kept only if it passes the same checks.
      const bool rebuilt_valid = rebuilt.ok() && check_solid_hull(index, rebuilt.value(), scratch) == Validity::valid;
      hull.polytope = rebuilt_valid ? std::move(rebuilt).value() : *patch.solid;
      stats.solids_kept_as_grown += !rebuilt_valid;
    }
    hull.faces = patch.faces;
    std::sort(hull.faces.begin(), hull.faces.end());
    hull.material = patch.material;
    hull.volume = polytope_volume(hull.polytope);
    hull.surface_planes = detail::surface_planes(index, hull.polytope, scratch);
    covering.hulls.push_back(std::move(hull));
  }
  std::sort(covering.hulls.begin(), covering.hulls.end(),
            [](const CoveringHull& x, const CoveringHull& y) { return x.faces.front() < y.faces.front(); });
  stats.seconds_output = seconds_since(start);
  if (options.progress) options.progress(1.0);
  return covering;
}

} // namespace

} // namespace hullcover
