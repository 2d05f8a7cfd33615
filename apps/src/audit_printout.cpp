// The audit's report as text, as `hullcover audit` and `hullcover demo` print it.

#include "audit_printout.h"

#include <cstdio>

namespace hullcover::app {
namespace {

double percent(long part, long whole) { return whole > 0 ? 100.0 * static_cast<double>(part) / whole : 0.0; }

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
    std::printf(
        "    reachable space: %ld rays of ball centres decided; %ld hold a ball of radius %.6g clear of the\n"
        "                     mesh yet deeper than the stand-off and tolerance in a hull\n",
        a.centre_rays, a.reach_lost, *a.options.agent_radius);
    std::printf("                     %ld balls reach into hulls only in enclosed space (allowed)\n", a.enclosed_balls);
    const validate::ReachPlace& p = a.deepest_reach;
    if (p.hull >= 0)
      std::printf(
          "      deepest: %.6g into hull %d, ball centred at (%.17g, %.17g, %.17g) (clearance %.6g) on a ray of\n"
          "      %s of face %d\n",
          p.depth, p.hull, p.centre.x(), p.centre.y(), p.centre.z(), p.clearance,
          p.opening ? "the open edge" : "the front", p.face);
  }
  if (a.undecided > 0) {
    const validate::RayPoint& u = a.first_undecided;
    std::printf(
        "    %ld rays ran out of evaluations (undecided: a violation); the first at (%.17g, %.17g, %.17g),\n"
        "      on a ray of %s of face %d\n",
        a.undecided, u.point.x(), u.point.y(), u.point.z(), u.opening ? "the open edge" : "the front", u.face);
  }
}

} // namespace

void print_audit(const std::string& hulls_label, const PreparedMesh& prepared, const validate::AuditReport& a) {
  const validate::ProbeReport& r = a.probe;
  const validate::CheckReport& recheck = a.recheck;
  const validate::BehaviourReport& b = a.behaviour;
  const bool allowance = r.allowance.options.any();
  std::printf("%s: %s\n", hulls_label.c_str(),
              a.clean()
                  ? (allowance ? "CLEAN: nothing taken beyond the allowance" : "CLEAN: no accessible space lost")
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
  if (a.groups_without_area > 0) std::printf("  %d OBJ groups span no area and were skipped\n", a.groups_without_area);
  print_rays("front free space:", r.front);
  print_rays("openings:        ", r.opening);
  std::printf("  lost cells:       %ld octree cells hold a lost ray's deepest point\n", r.lost_cells);
  std::printf(
      "  re-check: %ld mesh vertices and %ld edges inside hulls%s, %ld faces under flat hulls,\n"
      "            %ld hulls not convex; %ld faces (%.3f%% of the area) %s;\n"
      "            %ld of the paper's bars in hulls (its stand-in for openings, measured above instead)\n",
      recheck.vertices_inside, recheck.edges_inside, recheck.inside_allowed ? " (allowed)" : "",
      recheck.faces_below_polygon, recheck.hulls_not_convex, recheck.faces_uncovered,
      recheck.total_area > 0 ? 100.0 * recheck.uncovered_area / recheck.total_area : 0.0,
      recheck.inside_allowed ? "neither on nor inside a hull" : "on no hull's surface", recheck.bars_inside);
  if (recheck.inside_allowed)
    std::printf("            %ld faces covered by lying inside a hull\n", recheck.faces_inside);
  std::printf(
      "  behaviour: %ld proxies (size %.6g): %ld missed contacts, %ld false contacts (%ld deeper than the\n"
      "             tolerance in free space, %ld only in enclosed space (allowed), deepest %.6g), normals\n"
      "             %.3g deg apart on average, %.3g at most, over %ld shared contacts\n",
      b.poses, b.size, b.missed, b.false_contacts, b.deep_false_contacts, b.enclosed_false_contacts, b.max_false_depth,
      b.mean_normal_angle, b.max_normal_angle, b.both_touch);
  if (b.deepest_false.hull >= 0)
    std::printf(
        "      deepest false contact: %.6g into hull %d, proxy centred at (%.17g, %.17g, %.17g) in front of face %d,\n"
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

} // namespace hullcover::app
