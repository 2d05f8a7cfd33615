// `hullcover audit MESH HULLS`: does a set of hulls (from hullcover or any
// other tool) take accessible space away from the scene it stands for?

#include "commands.h"
#include "scene_loading.h"

#include "hullcover/validate/audit.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <string>

namespace hullcover::app {
namespace {

constexpr int kExitViolation = 1;

// What the command line holds: the files, the scene's tolerance, and the
// audit's own options (validate::AuditOptions, defaults included).
struct AuditCommandOptions {
  std::string mesh, hulls, json_path;
  std::optional<double> tolerance;
  validate::AuditOptions audit;
};

double percent(long part, long whole) { return whole > 0 ? 100.0 * static_cast<double>(part) / whole : 0.0; }

int bad_input(const Status& status) {
  std::fprintf(stderr, "hullcover: error: %s\n", status.message().c_str());
  return kExitBadInput;
}

void print_deepest_lost(const validate::ProbeReport& r) {
  if (r.worst.empty()) return;
  std::printf("  deepest lost points (max depth %.6g):\n", r.max_lost_depth);
  for (const validate::LostPlace& p : r.worst)
    std::printf("    depth %.6g in hull %d, from %s of face %d, at (%.6g, %.6g, %.6g)\n", p.depth, p.hull,
                p.opening ? "the open edge" : "the front", p.face, p.point.x(), p.point.y(), p.point.z());
}

void print_audit(const AuditCommandOptions& o, const PreparedMesh& prepared, const validate::AuditReport& a) {
  const validate::ProbeReport& r = a.probe;
  const validate::CheckReport& recheck = a.recheck;
  const validate::BehaviourReport& b = a.behaviour;
  std::printf("%s: %s\n", o.hulls.c_str(),
              a.clean() ? "CLEAN: no accessible space lost" : "VIOLATIONS: accessible space lost");
  std::printf("  %zu hulls against %zu faces; tolerance %.6g, probe distance %.6g, resolution %.6g\n", a.hull_count,
              prepared.mesh.triangles.size(), prepared.tolerance.length, r.probe_distance, r.resolution);
  if (a.groups_without_volume > 0)
    std::printf("  %d OBJ groups span no volume and were skipped\n", a.groups_without_volume);
  std::printf("  front free space: %ld of %ld points lost (%.3f%%)\n", r.front_lost, r.front_points,
              percent(r.front_lost, r.front_points));
  std::printf("  openings:         %ld of %ld points lost (%.3f%%)\n", r.opening_lost, r.opening_points,
              percent(r.opening_lost, r.opening_points));
  std::printf("  free volume:      %.6g of %.6g lost (%.3f%%), %ld of %ld octree cells (%ld more straddle a hull's "
              "surface)\n",
              r.lost_volume, r.free_volume, r.free_volume > 0 ? 100.0 * r.lost_volume / r.free_volume : 0.0,
              r.lost_cells, r.free_cells, r.straddling_cells);
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
  print_deepest_lost(r);
}

nlohmann::json audit_json(const AuditCommandOptions& o, const PreparedMesh& prepared, const validate::AuditReport& a) {
  const validate::ProbeReport& r = a.probe;
  const validate::CheckReport& recheck = a.recheck;
  const validate::BehaviourReport& b = a.behaviour;
  nlohmann::json worst = nlohmann::json::array();
  for (const validate::LostPlace& p : r.worst)
    worst.push_back({{"point", {p.point.x(), p.point.y(), p.point.z()}},
                     {"face", p.face},
                     {"hull", p.hull},
                     {"depth", p.depth},
                     {"opening", p.opening}});
  return {
      {"mesh", o.mesh},
      {"hulls", o.hulls},
      {"clean", a.clean()},
      {"hull_count", a.hull_count},
      {"tolerance", prepared.tolerance.length},
      {"probe_distance", r.probe_distance},
      {"resolution", r.resolution},
      {"front", {{"points", r.front_points}, {"lost", r.front_lost}}},
      {"openings", {{"points", r.opening_points}, {"lost", r.opening_lost}}},
      {"enclosed", {{"points", r.enclosed_points}, {"in_hulls", r.enclosed_in_hulls}}},
      {"free_space",
       {{"cells", r.free_cells},
        {"lost_cells", r.lost_cells},
        {"straddling_cells", r.straddling_cells},
        {"volume", r.free_volume},
        {"lost_volume", r.lost_volume}}},
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
}

bool write_json(const std::string& path, const nlohmann::json& j) {
  std::ofstream out(path);
  out << j.dump(1) << "\n";
  return static_cast<bool>(out);
}

// Loads the files, audits, prints; the verdict (validate::run_audit's, as a
// library user gets it) picks the exit status.
int run_audit_command(const AuditCommandOptions& o) {
  const std::optional<LoadedScene> scene = load_scene(o.mesh, o.tolerance);
  if (!scene) return kExitBadInput;
  const Result<validate::HullSet> set = validate::load_hull_set(o.hulls);
  if (!set.ok()) return bad_input(set.status());
  const Result<validate::AuditReport> audited = validate::run_audit(scene->prepared, set.value(), o.audit);
  if (!audited.ok()) return bad_input(audited.status());
  const validate::AuditReport& a = audited.value();
  print_audit(o, scene->prepared, a);
  if (!o.json_path.empty() && !write_json(o.json_path, audit_json(o, scene->prepared, a))) {
    std::fprintf(stderr, "hullcover: error: %s: cannot write\n", o.json_path.c_str());
    return kExitBadInput;
  }
  return a.clean() ? kExitSuccess : kExitViolation;
}

} // namespace

void register_audit_command(CLI::App& app, int& exit_status) {
  auto o = std::make_shared<AuditCommandOptions>();
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
  cmd->add_option("--probe", o->audit.probe.probe_distance,
                  "Probe distance R in scene units (default 0.02 x diagonal)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--resolution", o->audit.probe.resolution, "Octree cell and sample spacing (default R / 8)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--bar-length", o->audit.bar_half_length,
                  "Half-length of the boundary bars of the re-check (default 0.1 x diagonal, the paper-mode default)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--proxies", o->audit.behaviour.proxies,
                  "Character proxies (sphere, capsule, box) compared on both worlds")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--proxy-size", o->audit.behaviour.size, "Proxy radius / half extent (default 0.005 x diagonal)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--seed", o->audit.behaviour.seed, "Seed of the proxy poses")->capture_default_str();
  cmd->add_option("--octree", o->audit.probe.octree_path,
                  "Write the probed octree (.bt, for OctoMap's viewer; origin = box centre)");
  cmd->add_option("--json", o->json_path, "Write the figures as JSON");
  cmd->callback([o, &exit_status] { exit_status = run_audit_command(*o); });
}

} // namespace hullcover::app
