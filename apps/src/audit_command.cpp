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

void print_place(const char* label, const validate::LostPlace& p) {
  if (p.hull < 0) return;
  std::printf("%sdepth %.6g in hull %d, from %s of face %d, at (%.17g, %.17g, %.17g)\n", label, p.depth, p.hull,
              p.opening ? "the open edge" : "the front", p.face, p.point.x(), p.point.y(), p.point.z());
}

void print_rays(const char* kind, const validate::RayTally& t) {
  std::printf("  %s %ld of %ld rays lost (%.3f%%), %.6g long in all; %ld enclosed (allowed)\n", kind, t.lost, t.rays,
              percent(t.lost, t.rays), t.lost_length, t.enclosed);
  print_place("      deepest: ", t.deepest);
}

void print_audit(const AuditCommandOptions& o, const PreparedMesh& prepared, const validate::AuditReport& a) {
  const validate::ProbeReport& r = a.probe;
  const validate::CheckReport& recheck = a.recheck;
  const validate::BehaviourReport& b = a.behaviour;
  std::printf("%s: %s\n", o.hulls.c_str(),
              a.clean() ? "CLEAN: no accessible space lost" : "VIOLATIONS: accessible space lost");
  std::printf("  %zu hulls against %zu faces; tolerance %.6g, ray spacing %.6g, ", a.hull_count,
              prepared.mesh.triangles.size(), prepared.tolerance.length, r.resolution);
  if (r.probe_distance)
    std::printf("rays capped at %.6g (not the strict definition)\n", *r.probe_distance);
  else
    std::printf("rays uncapped\n");
  if (a.groups_without_area > 0)
    std::printf("  %d OBJ groups span no area and were skipped\n", a.groups_without_area);
  print_rays("front free space:", r.front);
  print_rays("openings:        ", r.opening);
  std::printf("  lost cells:       %ld octree cells hold a lost ray's deepest point\n", r.lost_cells);
  std::printf("  re-check: %ld mesh vertices and %ld edges inside hulls, %ld faces under flat hulls,\n"
              "            %ld hulls not convex; %ld faces (%.3f%% of the area) on no hull's surface;\n"
              "            %ld of the paper's bars in hulls (its stand-in for openings, measured above instead)\n",
              recheck.vertices_inside, recheck.edges_inside, recheck.faces_below_polygon,
              recheck.hulls_not_convex, recheck.faces_uncovered,
              recheck.total_area > 0 ? 100.0 * recheck.uncovered_area / recheck.total_area : 0.0, recheck.bars_inside);
  std::printf("  behaviour: %ld proxies (size %.6g): %ld missed contacts, %ld false contacts (%ld deeper than the\n"
              "             tolerance, deepest %.6g), normals %.3g deg apart on average, %.3g at most, over %ld\n"
              "             shared contacts\n",
              b.poses, b.size, b.missed, b.false_contacts, b.deep_false_contacts, b.max_false_depth,
              b.mean_normal_angle, b.max_normal_angle, b.both_touch);
  if (b.deepest_false.hull >= 0)
    std::printf("      deepest false contact: %.6g into hull %d, proxy centred at (%.17g, %.17g, %.17g) in front of face %d,\n"
                "      touching at (%.17g, %.17g, %.17g)\n",
                b.deepest_false.depth, b.deepest_false.hull, b.deepest_false.centre.x(), b.deepest_false.centre.y(),
                b.deepest_false.centre.z(), b.deepest_false.face, b.deepest_false.point.x(), b.deepest_false.point.y(),
                b.deepest_false.point.z());
  if (!r.worst.empty()) std::printf("  deepest lost point per hull (max depth %.6g):\n", r.max_lost_depth);
  for (const validate::LostPlace& p : r.worst) print_place("    ", p);
}

nlohmann::json place_json(const validate::LostPlace& p) {
  if (p.hull < 0) return nullptr;
  return {{"point", {p.point.x(), p.point.y(), p.point.z()}},
          {"face", p.face},
          {"hull", p.hull},
          {"depth", p.depth},
          {"opening", p.opening}};
}

nlohmann::json false_contact_json(const validate::FalseContactPlace& p) {
  if (p.hull < 0) return nullptr;
  return {{"hull", p.hull},
          {"face", p.face},
          {"centre", {p.centre.x(), p.centre.y(), p.centre.z()}},
          {"point", {p.point.x(), p.point.y(), p.point.z()}},
          {"depth", p.depth}};
}

nlohmann::json rays_json(const validate::RayTally& t) {
  return {{"rays", t.rays},
          {"enclosed", t.enclosed},
          {"lost", t.lost},
          {"lost_length", t.lost_length},
          {"deepest", place_json(t.deepest)}};
}

nlohmann::json audit_json(const AuditCommandOptions& o, const PreparedMesh& prepared, const validate::AuditReport& a) {
  const validate::ProbeReport& r = a.probe;
  const validate::CheckReport& recheck = a.recheck;
  const validate::BehaviourReport& b = a.behaviour;
  nlohmann::json worst = nlohmann::json::array();
  for (const validate::LostPlace& p : r.worst) worst.push_back(place_json(p));
  nlohmann::json findings = nlohmann::json::array();
  for (validate::AuditFinding f : a.findings) findings.push_back(validate::audit_finding_name(f));
  return {
      {"mesh", o.mesh},
      {"hulls", o.hulls},
      {"clean", a.clean()},
      {"findings", findings},
      {"hull_count", a.hull_count},
      {"groups_without_area", a.groups_without_area},
      {"tolerance", prepared.tolerance.length},
      {"probe_distance", r.probe_distance ? nlohmann::json(*r.probe_distance) : nlohmann::json(nullptr)},
      {"resolution", r.resolution},
      {"front", rays_json(r.front)},
      {"openings", rays_json(r.opening)},
      {"lost_cells", r.lost_cells},
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
        {"deep_false_contacts", b.deep_false_contacts},
        {"max_false_depth", b.max_false_depth},
        {"deepest_false_contact", false_contact_json(b.deepest_false)},
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
      "Check that hulls take no accessible space from the scene (DESIGN.md's strict definition): rays from\n"
      "points of every face along its normal, and from every open edge outward in the face's plane and tilted\n"
      "to either side, run with no distance cap to the first mesh hit (or out of the box of scene and hulls);\n"
      "each is decided exactly against every hull it meets (the segment against the hull shrunk by the\n"
      "tolerance): a stretch inside is lost. A ray whose first hit is the back of a face is enclosed:\n"
      "reported, allowed. The paper's conditions 1-4 and coverage are re-checked independently of the\n"
      "decomposer, and character proxies near the surfaces are collided with the triangles and the hulls\n"
      "(missed contacts, and false contacts deeper than the tolerance, count as violations).\n"
      "Exit status 0 clean, 1 space lost, 2 unreadable input.");
  cmd->add_option("MESH", o->mesh, "The scene the hulls stand for")->required();
  cmd->add_option("HULLS", o->hulls,
                  "Hulls: a runtime file (.hcw) or an OBJ with one o/g group per hull (each hull the convex\n"
                  "hull of its group's vertices; a group in one plane is a flat polygon)")
      ->required();
  cmd->add_option("--tol", o->tolerance, "Tolerance in scene units (default 1e-5 x bounding-box diagonal)");
  cmd->add_option("--probe", o->audit.probe.probe_distance,
                  "Optional cap on every ray's length in scene units (default none: the strict definition;\n"
                  "a cap audits less than it)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--resolution", o->audit.probe.resolution,
                  "Ray spacing on faces and open edges, and octree cell size (default 0.0025 x diagonal; every\n"
                  "face gets rays however small)")
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
                  "Write the octree of the cells of lost rays' deepest points (.bt, for OctoMap's viewer; origin = box centre)");
  cmd->add_option("--json", o->json_path, "Write the figures as JSON");
  cmd->callback([o, &exit_status] { exit_status = run_audit_command(*o); });
}

} // namespace hullcover::app
