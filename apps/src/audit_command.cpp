// `hullcover audit MESH HULLS`: does a set of hulls (from hullcover or any
// other tool) take accessible space away from the scene it stands for?

#include "commands.h"
#include "scene_loading.h"

#include "hullcover/validate/accessible_space.h"
#include "hullcover/validate/behaviour_equivalence.h"
#include "hullcover/validate/hull_set.h"
#include "hullcover/validate/validity_recheck.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <memory>

namespace hullcover::app {
namespace {

constexpr int kExitViolation = 1;

struct AuditOptions {
  std::string mesh, hulls, json_path, octree_path;
  std::optional<double> tolerance, probe, resolution, bar_length, proxy_size;
  int proxies = 3000;
  std::uint64_t seed = 1;
};

double percent(long part, long whole) { return whole > 0 ? 100.0 * static_cast<double>(part) / whole : 0.0; }

int run_audit(const AuditOptions& o) {
  const std::optional<LoadedScene> scene = load_scene(o.mesh, o.tolerance);
  if (!scene) return kExitBadInput;
  Result<validate::HullSet> set = validate::load_hull_set(o.hulls);
  if (!set.ok()) {
    std::fprintf(stderr, "hullcover: error: %s\n", set.status().message().c_str());
    return kExitBadInput;
  }
  const size_t hull_count = set.value().hulls.size();
  const double bar_length = o.bar_length.value_or(kDefaultBarHalfLengthRelative * scene->prepared.tolerance.diagonal);
  const validate::CheckReport recheck =
      validate::recheck_hulls(scene->prepared, validate::hulls_under_check(set.value().hulls), bar_length);
  Result<std::shared_ptr<const bvh::HullWorld>> hulls = bvh::HullWorld::build(std::move(set.value().hulls));
  Result<std::shared_ptr<const bvh::TriangleWorld>> triangles =
      bvh::TriangleWorld::build(scene->prepared.mesh, scene->prepared.tolerance.length);
  for (const Status& s : {hulls.status(), triangles.status()})
    if (!s.ok()) {
      std::fprintf(stderr, "hullcover: error: %s\n", s.message().c_str());
      return kExitBadInput;
    }
  const Result<validate::ProbeReport> probed = validate::probe_accessible_space(
      scene->prepared, *triangles.value(), *hulls.value(), {o.probe, o.resolution, o.octree_path});
  if (!probed.ok()) {
    std::fprintf(stderr, "hullcover: error: %s\n", probed.status().message().c_str());
    return kExitBadInput;
  }
  const validate::ProbeReport& r = probed.value();
  const Result<validate::BehaviourReport> compared = validate::compare_behaviour(
      scene->prepared, *triangles.value(), *hulls.value(), {o.proxies, o.seed, o.proxy_size});
  if (!compared.ok()) {
    std::fprintf(stderr, "hullcover: error: %s\n", compared.status().message().c_str());
    return kExitBadInput;
  }
  const validate::BehaviourReport& b = compared.value();
  const bool clean =
      r.front_lost == 0 && r.opening_lost == 0 && r.lost_cells == 0 && recheck.violations() == 0 && b.missed == 0;
  std::printf("%s: %s\n", o.hulls.c_str(), clean ? "CLEAN: no accessible space lost" : "VIOLATIONS: accessible space lost");
  std::printf("  %zu hulls against %zu faces; tolerance %.6g, probe distance %.6g, resolution %.6g\n", hull_count,
              scene->prepared.mesh.triangles.size(), scene->prepared.tolerance.length, r.probe_distance, r.resolution);
  if (set.value().groups_without_volume > 0)
    std::printf("  %d OBJ groups span no volume and were skipped\n", set.value().groups_without_volume);
  std::printf("  front free space: %ld of %ld points lost (%.3f%%)\n", r.front_lost, r.front_points,
              percent(r.front_lost, r.front_points));
  std::printf("  openings:         %ld of %ld points lost (%.3f%%)\n", r.opening_lost, r.opening_points,
              percent(r.opening_lost, r.opening_points));
  std::printf("  free volume:      %.6g of %.6g lost (%.3f%%), %ld of %ld octree cells (%ld more straddle a hull's surface)\n",
              r.lost_volume, r.free_volume, r.free_volume > 0 ? 100.0 * r.lost_volume / r.free_volume : 0.0, r.lost_cells,
              r.free_cells, r.straddling_cells);
  std::printf("  enclosed (allowed): %ld of %ld points inside hulls\n", r.enclosed_in_hulls, r.enclosed_points);
  std::printf("  re-check: %ld mesh vertices and %ld edges inside hulls, %ld faces under flat hulls,\n"
              "            %ld hulls not convex; %ld faces (%.3f%% of the area) on no hull's surface;\n"
              "            %ld of the paper's bars in hulls (its stand-in for openings, measured above instead)\n",
              recheck.vertices_inside, recheck.edges_inside, recheck.faces_below_polygon,
              recheck.hulls_not_convex, recheck.faces_uncovered,
              recheck.total_area > 0 ? 100.0 * recheck.uncovered_area / recheck.total_area : 0.0, recheck.bars_inside);
  std::printf("  behaviour: %ld proxies (size %.6g): %ld missed contacts, %ld false contacts (deepest %.6g),\n"
              "             normals %.3g deg apart on average, %.3g at most, over %ld shared contacts\n",
              b.poses, b.size, b.missed, b.false_contacts, b.max_false_depth, b.mean_normal_angle, b.max_normal_angle,
              b.both_touch);
  if (!r.worst.empty()) {
    std::printf("  deepest lost points (max depth %.6g):\n", r.max_lost_depth);
    for (const validate::LostPlace& p : r.worst)
      std::printf("    depth %.6g in hull %d, from %s of face %d, at (%.6g, %.6g, %.6g)\n", p.depth, p.hull,
                  p.opening ? "the open edge" : "the front", p.face, p.point.x(), p.point.y(), p.point.z());
  }
  if (!o.json_path.empty()) {
    nlohmann::json worst = nlohmann::json::array();
    for (const validate::LostPlace& p : r.worst)
      worst.push_back({{"point", {p.point.x(), p.point.y(), p.point.z()}},
                       {"face", p.face},
                       {"hull", p.hull},
                       {"depth", p.depth},
                       {"opening", p.opening}});
    const nlohmann::json j = {
        {"mesh", o.mesh},
        {"hulls", o.hulls},
        {"clean", clean},
        {"hull_count", hull_count},
        {"tolerance", scene->prepared.tolerance.length},
        {"probe_distance", r.probe_distance},
        {"resolution", r.resolution},
        {"front", {{"points", r.front_points}, {"lost", r.front_lost}}},
        {"openings", {{"points", r.opening_points}, {"lost", r.opening_lost}}},
        {"enclosed", {{"points", r.enclosed_points}, {"in_hulls", r.enclosed_in_hulls}}},
        {"free_space",
         {{"cells", r.free_cells}, {"lost_cells", r.lost_cells}, {"straddling_cells", r.straddling_cells}, {"volume", r.free_volume}, {"lost_volume", r.lost_volume}}},
        {"max_lost_depth", r.max_lost_depth},
        {"recheck",
         {{"vertices_inside", recheck.vertices_inside},
          {"edges_inside", recheck.edges_inside},
          {"bars_inside", recheck.bars_inside},
          {"faces_below_polygon", recheck.faces_below_polygon},
          {"hulls_not_convex", recheck.hulls_not_convex},
          {"faces_uncovered", recheck.faces_uncovered},
          {"uncovered_area", recheck.uncovered_area},
          {"total_area", recheck.total_area}}},
        {"worst", worst},
        {"behaviour",
         {{"proxies", b.poses},
          {"size", b.size},
          {"missed", b.missed},
          {"false_contacts", b.false_contacts},
          {"max_false_depth", b.max_false_depth},
          {"both_touch", b.both_touch},
          {"mean_normal_angle_deg", b.mean_normal_angle},
          {"max_normal_angle_deg", b.max_normal_angle}}},
    };
    std::ofstream out(o.json_path);
    out << j.dump(1) << "\n";
    if (!out) {
      std::fprintf(stderr, "hullcover: error: %s: cannot write\n", o.json_path.c_str());
      return kExitBadInput;
    }
  }
  return clean ? kExitSuccess : kExitViolation;
}

} // namespace

void register_audit_command(CLI::App& app, int& exit_status) {
  auto o = std::make_shared<AuditOptions>();
  CLI::App* cmd = app.add_subcommand(
      "audit",
      "Check that hulls take no accessible space from the scene: free space is probed by rays from every\n"
      "face along its normal and from every open edge outward, up to the probe distance or the first mesh hit,\n"
      "and every probed point and OctoMap free cell is tested against the hulls (deeper than the tolerance\n"
      "= lost). Space behind a face (ray ending on a back face) is enclosed: reported, allowed. The paper's\n"
      "conditions 1-4 and coverage are re-checked independently of the decomposer, and character proxies\n"
      "near the surfaces are collided with the triangles and the hulls (missed and false contacts).\n"
      "Exit status 0 clean, 1 space lost, 2 unreadable input.");
  cmd->add_option("MESH", o->mesh, "The scene the hulls stand for")->required();
  cmd->add_option("HULLS", o->hulls,
                  "Hulls: a runtime file (.hcw) or an OBJ with one o/g group per hull (each hull the convex\n"
                  "hull of its group's vertices)")
      ->required();
  cmd->add_option("--tol", o->tolerance, "Tolerance in scene units (default 1e-5 x bounding-box diagonal)");
  cmd->add_option("--probe", o->probe, "Probe distance R in scene units (default 0.02 x diagonal)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--resolution", o->resolution, "Octree cell and sample spacing (default R / 8)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--bar-length", o->bar_length,
                  "Half-length of the boundary bars of the re-check (default 0.1 x diagonal, as decompose)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--proxies", o->proxies, "Character proxies (sphere, capsule, box) compared on both worlds")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--proxy-size", o->proxy_size, "Proxy radius / half extent (default 0.005 x diagonal)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--seed", o->seed, "Seed of the proxy poses")->capture_default_str();
  cmd->add_option("--octree", o->octree_path, "Write the probed octree (.bt, for OctoMap's viewer; origin = box centre)");
  cmd->add_option("--json", o->json_path, "Write the figures as JSON");
  cmd->callback([o, &exit_status] { exit_status = run_audit(*o); });
}

} // namespace hullcover::app
