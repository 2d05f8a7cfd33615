// `hullcover audit MESH HULLS`: does a set of hulls (from hullcover or any
// other tool) take accessible space away from the scene it stands for?

#include "help_numbers.h"
#include "hullcover/covering/decompose_options.h"
#include "hullcover/geometry/tolerances.h"
#include "number_checks.h"
#include "audit_printout.h"
#include "audit_report_json.h"
#include "commands.h"
#include "movement_cli.h"
#include "scene_loading.h"
#include "terminal_progress.h"

#include "render/audit_report_html.h"

#include "hullcover/geometry/atomic_file.h"
#include "hullcover/validate/audit.h"
#include "hullcover/validate/movement_audit.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <exception>
#include <limits>
#include <memory>
#include <optional>
#include <string>

namespace hullcover::app {
namespace {

// What the command line holds: the files, the scene's tolerance, and the
// audit's own options (validate::AuditOptions, defaults included).
struct AuditCommandOptions {
  std::string mesh, hulls, json_path, html_path;
  std::string html_up = "y"; // the pictures' up axis
  std::optional<double> tolerance;
  ImportLimits limits;
  validate::AuditOptions audit;
  MovementCliOptions movement; // with --agent-reach, the movement audit
  double lattice_spacing = 0.0;
  bool hull_bound = false; // with --agent-reach: the fewest hulls any covering can have, bounded below
  bool quiet = false;
};

int bad_input(const Status& status) {
  std::fprintf(stderr, "hullcover: error: %s\n", status.message().c_str());
  return kExitBadInput;
}

nlohmann::json audit_json(const AuditCommandOptions& o, const PreparedMesh& prepared, const validate::AuditReport& a) {
  nlohmann::json out = {{"mesh", o.mesh}, {"hulls", o.hulls}};
  out.update(audit_report_json(prepared, a));
  return out;
}

// The movement audit (--agent-reach): prints its figures and verdict.
int run_movement_audit(const AuditCommandOptions& o, const LoadedScene& scene, const validate::HullSet& set) {
  const double radius = o.audit.probe.allowance.agent_radius.value_or(0.0);
  if (!(radius > 0.0)) return bad_input({StatusCode::invalid_argument, "--agent-reach needs --agent-radius above 0"});
  std::optional<MovementOptions> agent = movement_options_from(o.movement, radius);
  if (!agent) return kExitBadInput;
  validate::MovementAuditOptions options;
  options.agent = *agent;
  options.spacing = o.lattice_spacing;
  options.hull_bound = o.hull_bound;
  TerminalProgress bar(o.hull_bound ? "auditing movement (reach, centres, contacts, bound)"
                                    : "auditing movement (reach, centres, contacts)",
                       o.quiet);
  if (bar.enabled()) options.progress = [&bar](double fraction) { bar.update(fraction); };
  const Result<validate::MovementAuditReport> audited =
      validate::audit_movement(scene.prepared, set.hulls, options, o.audit.threads);
  bar.finish();
  if (!audited.ok()) return bad_input(audited.status());
  const validate::MovementAuditReport& m = audited.value();
  std::printf("%s: %zu hulls against %s, movement audit (%s): agent radius %.6g, slop %.6g, height %.6g\n",
              o.hulls.c_str(), set.hulls.size(), o.mesh.c_str(), o.movement.reach.c_str(), radius, m.slop, m.height);
  std::printf("  lattice spacing %.6g: %lld points, %lld clear, %lld reachable centres\n", m.spacing, m.lattice_points,
              m.clear_points, m.reachable_points);
  std::printf("  reachable centres sinking deeper than the slop into a hull: %lld", m.sinking);
  if (m.sinking > 0)
    std::printf(" (deepest %.6g into hull %d at %.6g %.6g %.6g)", m.deepest, m.deepest_hull, m.deepest_at.x(),
                m.deepest_at.y(), m.deepest_at.z());
  std::printf("\n  touching poses %lld, contacts lost (no hull within the slop): %lld", m.touching_poses,
              m.contacts_lost);
  if (m.contacts_lost > 0)
    std::printf(" (first at %.6g %.6g %.6g)", m.first_lost_at.x(), m.first_lost_at.y(), m.first_lost_at.z());
  std::printf("\n  verdict: %s\n", m.clean() ? "CLEAN" : "VIOLATIONS");
  const std::optional<validate::MovementHullBound>& bound = m.hull_bound;
  if (bound) {
    std::printf(
        "  hull bound: every covering keeping the promise for these reachable centres has at least %d hulls "
        "(these: %zu; %lld points of touched faces tried)\n",
        bound->hulls_needed, set.hulls.size(), bound->points_tried);
  }
  if (!o.json_path.empty()) {
    nlohmann::json out = {{"mesh", o.mesh},
                          {"hulls", o.hulls},
                          {"movement",
                           {{"reach", o.movement.reach},
                            {"radius", radius},
                            {"slop", m.slop},
                            {"height", m.height},
                            {"spacing", m.spacing},
                            {"lattice_points", m.lattice_points},
                            {"reachable_centres", m.reachable_points},
                            {"sinking", m.sinking},
                            {"deepest", m.deepest},
                            {"touching_poses", m.touching_poses},
                            {"contacts_lost", m.contacts_lost},
                            {"clean", m.clean()}}}};
    if (bound) out["movement"]["hull_bound"] = bound->hulls_needed;
    if (Status written = write_file_atomically(o.json_path, out.dump(1) + "\n"); !written.ok())
      return bad_input(written);
  }
  return m.clean() ? kExitSuccess : kExitFinding;
}

// Loads the files, audits, prints; the verdict (validate::run_audit's, as a
// library user gets it) picks the exit status.
int run_audit_command(const AuditCommandOptions& o) {
  const std::optional<LoadedScene> scene = load_scene(o.mesh, o.tolerance, o.limits);
  if (!scene) return kExitBadInput;
  if (const std::string stray = option_without_reach(o.movement); !stray.empty())
    return bad_input({StatusCode::invalid_argument, stray + " needs --agent-reach walk or fly"});
  if (o.hull_bound && o.movement.reach.empty())
    return bad_input({StatusCode::invalid_argument, "--hull-bound needs --agent-reach walk or fly"});
  if (!o.movement.reach.empty()) {
    const Result<validate::HullSet> hulls = validate::load_hull_set(o.hulls);
    if (!hulls.ok()) return bad_input(hulls.status());
    return run_movement_audit(o, *scene, hulls.value());
  }
  const Result<render::UpAxis> html_up = render::parse_up_axis(o.html_up);
  if (!html_up.ok()) return bad_input(html_up.status());
  const Result<validate::HullSet> set = validate::load_hull_set(o.hulls);
  if (!set.ok()) return bad_input(set.status());
  TerminalProgress bar("auditing (re-check, rays, proxies)", o.quiet);
  validate::AuditOptions options = o.audit;
  if (bar.enabled()) options.progress = [&bar](double fraction) { bar.update(fraction); };
  const Result<validate::AuditReport> audited = validate::run_audit(scene->prepared, set.value(), options);
  bar.finish();
  if (!audited.ok()) return bad_input(audited.status());
  const validate::AuditReport& a = audited.value();
  print_audit(o.hulls, scene->prepared, a);
  if (!o.json_path.empty())
    if (Status written = write_file_atomically(
            o.json_path,
            audit_json(o, scene->prepared, a).dump(1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
        !written.ok())
      return bad_input(written);
  if (!o.html_path.empty()) {
    render::AuditHtmlInput page;
    page.scene = &scene->prepared.mesh;
    page.hulls = &set.value().hulls;
    page.report = &a;
    page.figures = audit_json(o, scene->prepared, a);
    page.mesh_path = o.mesh;
    page.hulls_path = o.hulls;
    page.up = html_up.value();
    if (Status written = render::write_audit_report_html(o.html_path, page); !written.ok()) return bad_input(written);
  }
  return a.clean() ? kExitSuccess : kExitFinding;
}

} // namespace

void register_audit_command(CLI::App& app, int& exit_status) {
  auto o = std::make_shared<AuditCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "audit",
      "Check that hulls take no accessible space from the scene (the strict definition "
      "(docs/definitions-and-proofs.md)): rays from\n"
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
  cmd->add_option("--tol", o->tolerance,
                  "Tolerance in scene units, for every island (default " + number_text(kDefaultRelativeTolerance) +
                      " x each place's diagonal)")
      ->check(positive_number());
  add_import_limit_options(*cmd, o->limits);
  cmd->add_option("--probe", o->audit.probe.probe_distance,
                  "Optional cap on every ray's length in scene units (default none: the strict definition;\n"
                  "a cap audits less than it)")
      ->check(positive_number());
  cmd->add_option("--resolution", o->audit.probe.resolution,
                  "Ray spacing on faces and open edges, and octree cell size (default 0.0025 x the diagonal of\n"
                  "each face's island for the rays, of the scene for the octree; every face gets rays however small)")
      ->check(positive_number());
  cmd->add_option("--bar-length", o->audit.bar_half_length,
                  "Half-length of the boundary bars of the re-check (default " +
                      number_text(kDefaultBarHalfLengthRelative) + " x diagonal, the paper-mode default)")
      ->check(positive_number());
  cmd->add_option("--proxies", o->audit.behaviour.proxies,
                  "Character proxies (sphere, capsule, box) compared on both worlds")
      ->check(count_from(1, kMostProxies))
      ->capture_default_str();
  cmd->add_option("--proxy-size", o->audit.behaviour.size, "Proxy radius / half extent (default 0.005 x diagonal)")
      ->check(positive_number());
  cmd->add_option("--seed", o->audit.behaviour.seed, "Seed of the proxy poses (0 or more)")
      ->check(seed_number())
      ->capture_default_str();
  cmd->add_option(
      "--octree", o->audit.probe.octree_path,
      "Write the octree of the cells of lost rays' deepest points (.bt, for OctoMap's viewer; origin = box centre)");
  cmd->add_option("--agent-radius", o->audit.probe.allowance.agent_radius,
                  "Audit a covering made for agents of this radius (scene units): every ball of this radius clear\n"
                  "of the mesh, centred on the probe's rays, must stay out of the hulls (within the tolerance);\n"
                  "the proxies take this size (or --proxy-size, not smaller) and spheres and capsules must\n"
                  "neither miss a contact nor make a false one. Faces may lie inside hulls.")
      ->check(positive_number());
  cmd->add_option("--max-deviation", o->audit.probe.allowance.max_deviation,
                  "Audit a covering allowed to take free space within this distance of the mesh (scene units):\n"
                  "the farthest point any hull takes from a probe ray is found (within the tolerance) and must\n"
                  "lie no farther. With --agent-radius, both are judged.")
      ->check(positive_number());
  cmd->add_option("--max-ray-evaluations", o->audit.probe.allowance.max_evaluations_per_ray,
                  "With --agent-radius or --max-deviation: distance evaluations one ray may use before it counts\n"
                  "as undecided (a violation; the report says where the first was given up). A ray needs about 2\n"
                  "per tolerance of its length beside hulls in enclosed space")
      ->check(count_from(2, std::numeric_limits<int>::max()))
      ->capture_default_str();
  cmd->add_option("--threads", o->audit.threads,
                  "Threads re-checking hulls and tracing rays at once (default 0: every core); the verdict,\n"
                  "the figures and the located places are the same for any count")
      ->check(thread_count());
  cmd->add_option("--json", o->json_path, "Write the figures as JSON");
  cmd->add_option("--html", o->html_path,
                  "Write a self-contained HTML report (pictures embedded): the verdict in a green or red banner,\n"
                  "every figure of --json, the scene with its hulls, and the located lost places as red balls over\n"
                  "pale, cut-away hulls (see 'hullcover render --help' for the cut)");
  cmd->add_option("--html-up", o->html_up, "The scene's up axis for the HTML report's pictures: x, y or z")
      ->capture_default_str();
  add_movement_options(*cmd, o->movement);
  cmd->add_option("--lattice-spacing", o->lattice_spacing,
                  "With --agent-reach: the spacing of the audit's lattice of agent centres, scene units (default " +
                      number_text(validate::kDefaultAuditSpacingInRadii) +
                      " x radius, widened to keep the lattice within " +
                      std::to_string(validate::kMostAuditLatticePoints) + " points)")
      ->check(positive_number());
  cmd->add_flag("--hull-bound", o->hull_bound,
                "With --agent-reach: also bound from below the hulls any covering keeping the movement promise\n"
                "needs, on the audit's reachable centres (points of touched faces that no one hull may hold\n"
                "together: a reachable centre lies nearer than r - E - 2 tol to the segment between any two)");
  cmd->add_flag("-q,--quiet", o->quiet, "No progress bar (drawn on stderr only when it is a terminal)");
  cmd->callback([o, &exit_status] { exit_status = run_audit_command(*o); });
}

} // namespace hullcover::app
