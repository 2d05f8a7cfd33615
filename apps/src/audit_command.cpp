// `hullcover audit MESH HULLS`: does a set of hulls (from hullcover or any
// other tool) take accessible space away from the scene it stands for?

#include "number_checks.h"
#include "audit_report_json.h"
#include "commands.h"
#include "scene_loading.h"
#include "terminal_progress.h"

#include "render/audit_report_html.h"

#include "hullcover/geometry/atomic_file.h"
#include "hullcover/validate/audit.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <exception>
#include <limits>
#include <memory>
#include <optional>
#include <string>

namespace hullcover::app {
namespace {

constexpr int kExitViolation = 1;

// What the command line holds: the files, the scene's tolerance, and the
// audit's own options (validate::AuditOptions, defaults included).
struct AuditCommandOptions {
  std::string mesh, hulls, json_path, html_path;
  std::string html_up = "y";  // the pictures' up axis
  std::optional<double> tolerance;
  ImportLimits limits;
  validate::AuditOptions audit;
  bool quiet = false;
};

// `--threads N`: a whole number, 0 (every core) or more, refused otherwise
// with a message that says so (bad usage: exit 2).
CLI::Validator thread_count_check() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        size_t used = 0;
        long count = -1;
        try {
          count = std::stol(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == 0 || used != text.size() || count < 0 || count > std::numeric_limits<int>::max())
          return "the thread count must be 0 (every core) or a positive whole number, not '" + text + "'";
        return {};
      },
      "N>=0");
}

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

void print_allowance(const validate::AllowanceReport& a) {
  if (!a.options.any()) return;
  std::printf("  allowance:");
  if (a.options.agent_radius) std::printf(" agent radius %.6g", *a.options.agent_radius);
  if (a.options.max_deviation) std::printf(" max deviation %.6g", *a.options.max_deviation);
  std::printf(" (the strict lost rays above are reported, not judged)\n");
  std::printf("    deviation: %ld lost stretches; the farthest lost point lies %.6g from the mesh", a.lost_stretches,
              a.max_lost_deviation);
  if (a.farthest_hull >= 0)
    std::printf(", in hull %d, on a ray of face %d, at (%.17g, %.17g, %.17g)", a.farthest_hull, a.farthest_face,
                a.farthest_point.x(), a.farthest_point.y(), a.farthest_point.z());
  std::printf("\n");
  if (a.options.max_deviation && !a.options.agent_radius)
    std::printf("               %ld rays lose a point farther than the max deviation\n", a.beyond_deviation);
  if (a.options.agent_radius) {
    std::printf("    reachable space: %ld rays of ball centres decided; %ld hold a ball of radius %.6g clear of the\n"
                "                     mesh yet deeper than the stand-off and tolerance in a hull\n",
                a.centre_rays, a.reach_lost, *a.options.agent_radius);
    std::printf("                     %ld balls reach into hulls only in enclosed space (allowed)\n", a.enclosed_balls);
    const validate::ReachPlace& p = a.deepest_reach;
    if (p.hull >= 0)
      std::printf("      deepest: %.6g into hull %d, ball centred at (%.17g, %.17g, %.17g) (clearance %.6g) on a ray of\n"
                  "      %s of face %d\n",
                  p.depth, p.hull, p.centre.x(), p.centre.y(), p.centre.z(), p.clearance,
                  p.opening ? "the open edge" : "the front", p.face);
  }
  if (a.undecided > 0) {
    const validate::RayPoint& u = a.first_undecided;
    std::printf("    %ld rays ran out of evaluations (undecided: a violation); the first at (%.17g, %.17g, %.17g),\n"
                "      on a ray of %s of face %d\n",
                a.undecided, u.point.x(), u.point.y(), u.point.z(), u.opening ? "the open edge" : "the front", u.face);
  }
}

void print_audit(const AuditCommandOptions& o, const PreparedMesh& prepared, const validate::AuditReport& a) {
  const validate::ProbeReport& r = a.probe;
  const validate::CheckReport& recheck = a.recheck;
  const validate::BehaviourReport& b = a.behaviour;
  const bool allowance = r.allowance.options.any();
  std::printf("%s: %s\n", o.hulls.c_str(),
              a.clean() ? (allowance ? "CLEAN: nothing taken beyond the allowance" : "CLEAN: no accessible space lost")
                        : (allowance ? "VIOLATIONS: more taken than the allowance" : "VIOLATIONS: accessible space lost"));
  std::printf("  %zu hulls against %zu faces; tolerance %.6g%s, ray spacing %.6g", a.hull_count,
              prepared.mesh.triangles.size(), prepared.tolerance.length,
              prepared.tolerance.largest_length() > prepared.tolerance.length ? " (smallest; each place its own)" : "",
              r.finest_spacing);
  if (r.coarsest_spacing > r.finest_spacing) std::printf(" to %.6g (each island its own)", r.coarsest_spacing);
  std::printf(", ");
  if (r.probe_distance)
    std::printf("rays capped at %.6g (not the strict definition)\n", *r.probe_distance);
  else
    std::printf("rays uncapped\n");
  if (a.groups_without_area > 0)
    std::printf("  %d OBJ groups span no area and were skipped\n", a.groups_without_area);
  print_rays("front free space:", r.front);
  print_rays("openings:        ", r.opening);
  std::printf("  lost cells:       %ld octree cells hold a lost ray's deepest point\n", r.lost_cells);
  std::printf("  re-check: %ld mesh vertices and %ld edges inside hulls%s, %ld faces under flat hulls,\n"
              "            %ld hulls not convex; %ld faces (%.3f%% of the area) %s;\n"
              "            %ld of the paper's bars in hulls (its stand-in for openings, measured above instead)\n",
              recheck.vertices_inside, recheck.edges_inside, recheck.inside_allowed ? " (allowed)" : "",
              recheck.faces_below_polygon, recheck.hulls_not_convex, recheck.faces_uncovered,
              recheck.total_area > 0 ? 100.0 * recheck.uncovered_area / recheck.total_area : 0.0,
              recheck.inside_allowed ? "neither on nor inside a hull" : "on no hull's surface", recheck.bars_inside);
  if (recheck.inside_allowed) std::printf("            %ld faces covered by lying inside a hull\n", recheck.faces_inside);
  std::printf("  behaviour: %ld proxies (size %.6g): %ld missed contacts, %ld false contacts (%ld deeper than the\n"
              "             tolerance in free space, %ld only in enclosed space (allowed), deepest %.6g), normals\n"
              "             %.3g deg apart on average, %.3g at most, over %ld shared contacts\n",
              b.poses, b.size, b.missed, b.false_contacts, b.deep_false_contacts, b.enclosed_false_contacts,
              b.max_false_depth, b.mean_normal_angle, b.max_normal_angle, b.both_touch);
  if (b.deepest_false.hull >= 0)
    std::printf("      deepest false contact: %.6g into hull %d, proxy centred at (%.17g, %.17g, %.17g) in front of face %d,\n"
                "      touching at (%.17g, %.17g, %.17g)\n",
                b.deepest_false.depth, b.deepest_false.hull, b.deepest_false.centre.x(), b.deepest_false.centre.y(),
                b.deepest_false.centre.z(), b.deepest_false.face, b.deepest_false.point.x(), b.deepest_false.point.y(),
                b.deepest_false.point.z());
  if (b.deep_false_boxes > 0)
    std::printf("      of them by boxes: %ld%s\n", b.deep_false_boxes,
                r.allowance.options.agent_radius ? " (a box is no union of balls: measured, not judged)" : "");
  print_allowance(r.allowance);
  if (!r.worst.empty()) std::printf("  deepest lost point per hull (max depth %.6g):\n", r.max_lost_depth);
  for (const validate::LostPlace& p : r.worst) print_place("    ", p);
}

nlohmann::json audit_json(const AuditCommandOptions& o, const PreparedMesh& prepared, const validate::AuditReport& a) {
  nlohmann::json out = {{"mesh", o.mesh}, {"hulls", o.hulls}};
  out.update(audit_report_json(prepared, a));
  return out;
}

// Loads the files, audits, prints; the verdict (validate::run_audit's, as a
// library user gets it) picks the exit status.
int run_audit_command(const AuditCommandOptions& o) {
  const std::optional<LoadedScene> scene = load_scene(o.mesh, o.tolerance, o.limits);
  if (!scene) return kExitBadInput;
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
  print_audit(o, scene->prepared, a);
  if (!o.json_path.empty())
    if (Status written = write_file_atomically(o.json_path, audit_json(o, scene->prepared, a).dump(1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
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
  return a.clean() ? kExitSuccess : kExitViolation;
}

} // namespace

void register_audit_command(CLI::App& app, int& exit_status) {
  auto o = std::make_shared<AuditCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "audit",
      "Check that hulls take no accessible space from the scene (the strict definition (docs/definitions-and-proofs.md)): rays from\n"
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
  cmd->add_option("--tol", o->tolerance, "Tolerance in scene units, for every island (default 1e-5 x each place's diagonal)");
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
                  "Half-length of the boundary bars of the re-check (default 0.1 x diagonal, the paper-mode default)")
      ->check(positive_number());
  cmd->add_option("--proxies", o->audit.behaviour.proxies,
                  "Character proxies (sphere, capsule, box) compared on both worlds")
      ->check(positive_number())
      ->capture_default_str();
  cmd->add_option("--proxy-size", o->audit.behaviour.size, "Proxy radius / half extent (default 0.005 x diagonal)")
      ->check(positive_number());
  cmd->add_option("--seed", o->audit.behaviour.seed, "Seed of the proxy poses (0 or more)")
      ->check(non_negative_number())
      ->capture_default_str();
  cmd->add_option("--octree", o->audit.probe.octree_path,
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
      ->check(CLI::Range(2, std::numeric_limits<int>::max()))
      ->capture_default_str();
  cmd->add_option("--threads", o->audit.threads,
                  "Threads re-checking hulls and tracing rays at once (default 0: every core); the verdict,\n"
                  "the figures and the located places are the same for any count")
      ->check(thread_count_check());
  cmd->add_option("--json", o->json_path, "Write the figures as JSON");
  cmd->add_option("--html", o->html_path,
                  "Write a self-contained HTML report (pictures embedded): the verdict in a green or red banner,\n"
                  "every figure of --json, the scene with its hulls, and the located lost places as red balls over\n"
                  "pale, cut-away hulls (see 'hullcover render --help' for the cut)");
  cmd->add_option("--html-up", o->html_up, "The scene's up axis for the HTML report's pictures: x, y or z")
      ->capture_default_str();
  cmd->add_flag("-q,--quiet", o->quiet, "No progress bar (drawn on stderr only when it is a terminal)");
  cmd->callback([o, &exit_status] { exit_status = run_audit_command(*o); });
}

} // namespace hullcover::app
