// `hullcover decompose IN -o OUT.obj`: the convex hull covering of a scene.

#include "help_numbers.h"
#include "hullcover/geometry/tolerances.h"
#include "number_checks.h"
#include "commands.h"
#include "movement_cli.h"
#include "export/collider_export.h"
#include "scene_loading.h"
#include "terminal_progress.h"

#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/bvh/runtime_file.h"
#include "hullcover/covering/cell_cache.h"
#include "hullcover/covering/covering_export.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <thread>

namespace hullcover::app {
namespace {

struct DecomposeCommandOptions {
  std::string input;
  std::string obj_path;
  std::string json_path;
  std::string world_path;
  std::string cell_cache;
  std::optional<double> tolerance;
  ImportLimits limits;
  std::string order = "compact";
  std::string conditions = "exact";
  std::string dissolve; // "", "on" or "off"
  DecomposeOptions decompose;
  ColliderExportOptions exported; // with --format, -o is an engine export
  MovementCliOptions movement;    // with --agent-reach, a movement covering
  bool quiet = false;
};

// The movement covering (--agent-reach) of `scene`, or nothing after a
// message on stderr.
std::optional<MovementCovering> decompose_movement(const DecomposeCommandOptions& o, const LoadedScene& scene,
                                                   TerminalProgress& bar) {
  const double radius = o.decompose.agent_radius.value_or(0.0);
  if (o.decompose.max_deviation || !o.cell_cache.empty()) {
    std::fprintf(stderr, "hullcover: error: --agent-reach takes neither --max-deviation nor --cell-cache\n");
    return std::nullopt;
  }
  std::optional<MovementOptions> options = movement_options_from(o.movement, radius);
  if (!options) return std::nullopt;
  options->threads = o.decompose.threads;
  options->max_hull_vertices = o.decompose.max_hull_vertices;
  if (bar.enabled()) options->progress = [&bar](double fraction) { bar.update(fraction); };
  Result<MovementCovering> made = decompose_for_movement(scene.prepared, *options);
  bar.finish();
  if (!made.ok()) {
    std::fprintf(stderr, "hullcover: error: %s\n", made.status().message().c_str());
    return std::nullopt;
  }
  return std::move(made).value();
}

int run_decompose(DecomposeCommandOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const std::optional<LoadedScene> scene = load_scene(o.input, o.tolerance, o.limits);
  if (!scene) return kExitBadInput;
  o.decompose.order = o.order == "random" ? MergeOrder::random : MergeOrder::compact;
  o.decompose.conditions = o.conditions == "paper" ? ValidityMode::paper : ValidityMode::exact;
  if (!o.dissolve.empty()) o.decompose.dissolve = o.dissolve == "on";
  TerminalProgress bar("decomposing (merges at most)", o.quiet);
  std::optional<MovementCovering> movement;
  std::optional<Covering> made;
  CellCacheReport cache;
  if (const std::string stray = option_without_reach(o.movement); !stray.empty()) {
    std::fprintf(stderr, "hullcover: error: %s needs --agent-reach walk or fly\n", stray.c_str());
    return kExitBadInput;
  }
  if (!o.movement.reach.empty() && !o.decompose.agent_radius) {
    std::fprintf(stderr, "hullcover: error: --agent-reach needs --agent-radius (0 gives the exact covering)\n");
    return kExitBadInput;
  }
  // A movement covering for agents of radius 0 is the exact covering.
  if (!o.movement.reach.empty() && *o.decompose.agent_radius > 0.0) {
    movement = decompose_movement(o, *scene, bar);
    if (!movement) return kExitBadInput;
    made = std::move(movement->covering);
  } else {
    if (bar.enabled()) o.decompose.progress = [&bar](double fraction) { bar.update(fraction); };
    Result<Covering> covering = o.cell_cache.empty()
                                    ? decompose(scene->prepared, o.decompose)
                                    : decompose_with_cell_cache(scene->prepared, o.decompose, o.cell_cache, cache);
    bar.finish();
    if (!covering.ok()) {
      std::fprintf(stderr, "hullcover: error: %s\n", covering.status().message().c_str());
      return kExitBadInput;
    }
    made = std::move(covering).value();
  }
  const Covering& c = *made;
  std::string exported;
  if (o.exported.format.empty()) {
    if (Status s = write_covering_obj(c, o.obj_path); !s.ok()) {
      std::fprintf(stderr, "hullcover: error: %s\n", s.message().c_str());
      return kExitBadInput;
    }
  } else {
    const Result<ColliderExportReport> report =
        export_colliders(bvh::runtime_hulls(c), c.tolerance.length, &scene->prepared.mesh, o.exported, o.obj_path);
    if (!report.ok()) {
      std::fprintf(stderr, "hullcover: error: %s\n", report.status().message().c_str());
      return kExitBadInput;
    }
    exported = describe_export(report.value(), o.obj_path);
  }
  if (!o.world_path.empty()) {
    if (Status s = bvh::write_covering_runtime_file(c, o.world_path); !s.ok()) {
      std::fprintf(stderr, "hullcover: error: %s\n", s.message().c_str());
      return kExitBadInput;
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!o.json_path.empty()) {
    const nlohmann::json extra = {{"input", o.input}, {"seconds_including_import", seconds}};
    if (Status s = write_covering_json(c, extra, o.json_path); !s.ok()) {
      std::fprintf(stderr, "hullcover: error: %s\n", s.message().c_str());
      return kExitBadInput;
    }
  }
  const int faces = c.statistics.faces;
  const double reduction = faces > 0 ? 1.0 - static_cast<double>(c.hulls.size()) / faces : 0.0;
  std::printf("%s: %d faces -> %zu hulls (%.1f%% fewer, %.3f hulls/face), %.3f s (merging %.3f s)\n", o.input.c_str(),
              faces, c.hulls.size(), 100.0 * reduction, faces > 0 ? static_cast<double>(c.hulls.size()) / faces : 0.0,
              seconds, c.statistics.seconds_merging);
  std::printf("  tolerance %.6g%s, bar half-length %.6g, prism cap %.6g, order %s, conditions %s\n", c.tolerance.length,
              c.tolerance.largest_length() > c.tolerance.length ? " (the smallest place's)" : "", c.bar_half_length,
              c.prism_thickness_cap, o.order.c_str(), o.conditions.c_str());
  std::printf("  %d island%s, %d cell%s, threads %d\n", c.statistics.islands, c.statistics.islands == 1 ? "" : "s",
              c.statistics.cells, c.statistics.cells == 1 ? "" : "s",
              o.decompose.threads > 0 ? o.decompose.threads
                                      : std::max(1, static_cast<int>(std::thread::hardware_concurrency())));
  if (c.statistics.order_tries > 1) {
    const std::string kept = c.statistics.kept_try == 0
                                 ? std::string("the first (") + o.order + ")"
                                 : "random seed " + std::to_string(o.decompose.seed + c.statistics.kept_try - 1);
    std::printf("  %d merge orders tried, kept %s\n", c.statistics.order_tries, kept.c_str());
  }
  if (movement) {
    const MovementStatistics& m = movement->movement;
    std::printf("  movement covering (%s): agent radius %.6g, slop %.6g, height %.6g, climb %.6g; rays are not kept\n",
                m.reach == AgentReach::walk ? "walk" : "fly", m.radius, m.slop, m.height, m.climb);
    std::printf("  reach grid: %lld cells of %.6g, %lld reachable, %d seed%s; %d of %d faces touchable; %.3f s\n",
                m.grid_cells, m.cell, m.reachable_cells, m.seeds, m.seeds == 1 ? "" : "s", m.touchable_faces, faces,
                m.seconds_reach);
    std::printf("  exact covering to start from: %.3f s; hulls proven %lld, merges %lld, refused undecided %lld\n",
                m.seconds_exact, m.candidates, m.merges, m.undecided);
  } else if (has_allowance(o.decompose))
    std::printf("  allowance: agent radius %.6g, max deviation %.6g\n", o.decompose.agent_radius.value_or(0.0),
                o.decompose.max_deviation.value_or(0.0));
  if (c.near_merge_distance > 0.0)
    std::printf("  near merges (patches sharing no edge, within %.6g): %d of %d merges\n", c.near_merge_distance,
                c.statistics.near_merges, c.statistics.merges);
  if (c.dissolve)
    std::printf("  dissolved patches (emptied into their neighbours): %d\n", c.statistics.dissolved_patches);
  if (!o.cell_cache.empty()) {
    std::printf(
        "  cell cache %s: %d cells, %d reused (re-checked against this scene, %.3f s), %d stale, %d merged "
        "(%.3f s)\n",
        o.cell_cache.c_str(), cache.cells, cache.reused, cache.seconds_checking, cache.stale, cache.merged,
        cache.seconds_merging);
    if (cache.changed_faces < 0)
      std::printf("    no usable record of the last bake (or an allowance): every kept patch re-checked (%ld)\n",
                  cache.patches_rechecked);
    else
      std::printf(
          "    %d faces added or removed since the last bake: %ld kept patches within their reach "
          "re-checked, %ld out of reach kept as they were\n",
          cache.changed_faces, cache.patches_rechecked, cache.patches_kept_unchecked);
  }
  if (!exported.empty()) std::printf("  %s\n", exported.c_str());
  std::printf("  wrote %s%s%s%s%s\n", o.obj_path.c_str(), o.json_path.empty() ? "" : ", ", o.json_path.c_str(),
              o.world_path.empty() ? "" : ", ", o.world_path.c_str());
  return kExitSuccess;
}

} // namespace

void register_decompose_command(CLI::App& app, int& exit_status) {
  auto o = std::make_shared<DecomposeCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "decompose",
      "Compute the convex hull covering of a scene (the paper's greedy, compactness-ordered merging)\n"
      "and write it as OBJ, one 'o' group per hull, with an optional JSON sidecar.");
  cmd->add_option("IN", o->input, "Scene file (OBJ, PLY, STL, glTF/GLB, FBX)")->required();
  cmd->add_option("-o,--output", o->obj_path, "Output: the hull OBJ, or with --format an engine export (glb or obj)")
      ->required();
  cmd->add_option("--json", o->json_path, "Also write per-hull figures, totals, options and timing as JSON");
  cmd->add_option("--world", o->world_path, "Also write the runtime file (.hcw) that 'query' and game servers load");
  cmd->add_option("--tol", o->tolerance,
                  "Tolerance in scene units, for every island (default " + number_text(kDefaultRelativeTolerance) +
                      " x each place's diagonal)")
      ->check(positive_number());
  add_import_limit_options(*cmd, o->limits);
  cmd->add_option("--threads", o->decompose.threads,
                  "Threads merging cells at once (default 0: every core); the output is the same for any count")
      ->check(thread_count());
  cmd->add_option("--cell-size", o->decompose.cell_size,
                  "Patches merge only within cells of this side, scene units, laid out per island (pieces of the "
                  "scene set apart from the rest); every hull is still checked against the whole scene. Default: "
                  "automatic, one cell per island of up to 8192 faces, a centred grid over larger ones (a cube of it "
                  "holding over 16384 faces cut into the eight of half its side); 0: one cell for the whole scene")
      ->check(non_negative_number());
  cmd->add_option("--cell-cache", o->cell_cache,
                  "Re-bake only what changed: keep each cell's result in this folder under a hash of its faces and "
                  "the options; a later bake reuses a cell whose hash is unchanged once every hull it keeps passes "
                  "the validity checks against the scene as it is now, and merges the rest (created if absent). "
                  "The folder also keeps the faces the last bake saw (last-bake.scene), so only hulls an edit can "
                  "reach are re-checked");
  cmd->add_option("--order", o->order, "Merge order: compact (the paper's) or random")
      ->check(CLI::IsMember({"compact", "random"}))
      ->capture_default_str();
  cmd->add_option("--conditions", o->conditions,
                  "Validity: exact (the paper's four conditions plus those that keep every bit of free space: "
                  "coincident faces, whole open edges, self-intersections) or paper (the four alone)")
      ->check(CLI::IsMember({"exact", "paper"}))
      ->capture_default_str();
  cmd->add_option("--reach", o->decompose.free_space_reach,
                  "Exact mode: cap on how far free space is kept in front of faces and beyond open edges, scene "
                  "units (default: no cap, every ray of free space up to its first mesh hit)")
      ->check(positive_number());
  cmd->add_option("--agent-radius", o->decompose.agent_radius,
                  "Exact mode for agents: hulls may also fill free space no ball of this radius (touching no "
                  "triangle) reaches, scene units; spheres and capsules at least this wide collide as with the "
                  "triangles (default 0: exact)")
      ->check(non_negative_number());
  cmd->add_option("--max-deviation", o->decompose.max_deviation,
                  "Exact mode for props: hulls may also fill free space within this distance of the mesh, scene "
                  "units; with --agent-radius, a hull takes only space that both allow (default 0: exact)")
      ->check(non_negative_number());
  cmd->add_option("--near-merge", o->decompose.near_merge_distance,
                  "After the paper's merging, also try patches that share no edge but come within this distance, "
                  "scene units, under the same conditions; 0 = off, the paper's algorithm alone (default: exact " +
                      number_text(kDefaultNearMergeRelative) +
                      " x each island's diagonal, halved in a cell cut from a crowded cube per halving; paper 0)")
      ->check(non_negative_number());
  cmd->add_option("--dissolve", o->dissolve,
                  "After merging, empty each patch whose faces can each join a patch around it (across an edge or "
                  "within the near-merge distance) under the same conditions, then merge again: on or off (default: "
                  "exact on, paper off)")
      ->check(CLI::IsMember({"on", "off"}));
  cmd->add_option("--seed", o->decompose.seed, "Seed of the random order (0 or more)")
      ->check(seed_number())
      ->capture_default_str();
  cmd->add_option("--tries", o->decompose.order_tries,
                  "Merge N times: in --order, then in random orders seeded --seed, --seed + 1, ...; keep the "
                  "covering with the fewest hulls (N times the merging time)")
      ->check(count_from(1, 1 << 16))
      ->capture_default_str();
  cmd->add_option("--bar-length", o->decompose.bar_half_length,
                  "Half-length of the boundary constraint bars, scene units (default: paper " +
                      number_text(kDefaultBarHalfLengthRelative) + " x diagonal, exact " +
                      number_text(kExactBarHalfLengthInTolerances) + " x tol)")
      ->check(positive_number());
  cmd->add_option("--prism-cap", o->decompose.prism_thickness_cap,
                  "Largest thickness of the prisms made from planar patches (default " +
                      number_text(kDefaultPrismCapRelative) +
                      " x each island's diagonal;\na prism also stops short of a smaller neighbouring map's zone)")
      ->check(non_negative_number());
  cmd->add_option("--max-hull-vertices", o->decompose.max_hull_vertices,
                  "Largest vertex count of a hull; a merge that exceeds it is not made")
      ->check(count_from(8, 1 << 20))
      ->capture_default_str();
  cmd->add_option("--max-hull-triangles", o->decompose.max_hull_triangles,
                  "Largest triangle count of a hull, its facets fanned into triangles, a flat hull counted as the "
                  "prism an engine export makes of it (Unity's convex MeshCollider: 255); default no limit")
      ->check(count_from(kFewestTrianglesOfAHullLimit, 1 << 22));
  cmd->add_flag("--materials", o->decompose.keep_materials_apart,
                "Keep materials apart: one material per hull, bars on material borders");
  add_movement_options(*cmd, o->movement);
  add_collider_export_options(cmd, o->exported);
  cmd->add_flag("-q,--quiet", o->quiet, "No progress bar (drawn on stderr only when it is a terminal)");
  cmd->callback([o, &exit_status] { exit_status = run_decompose(*o); });
}

} // namespace hullcover::app
