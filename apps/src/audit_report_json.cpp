#include "audit_report_json.h"

#include <optional>

namespace hullcover::app {
namespace {

nlohmann::json place_json(const validate::LostPlace& p) {
  if (p.hull < 0) return nullptr;
  return {{"point", {p.point.x(), p.point.y(), p.point.z()}},
          {"face", p.face},
          {"hull", p.hull},
          {"depth", p.depth},
          {"opening", p.opening}};
}

nlohmann::json ray_point_json(const validate::RayPoint& p) {
  if (p.face < 0) return nullptr;
  return {{"point", {p.point.x(), p.point.y(), p.point.z()}}, {"face", p.face}, {"opening", p.opening}};
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

nlohmann::json optional_json(const std::optional<double>& x) {
  return x ? nlohmann::json(*x) : nlohmann::json(nullptr);
}

nlohmann::json allowance_json(const validate::AllowanceReport& a) {
  if (!a.options.any()) return nullptr;
  const validate::ReachPlace& p = a.deepest_reach;
  return {
      {"agent_radius", optional_json(a.options.agent_radius)},
      {"max_deviation", optional_json(a.options.max_deviation)},
      {"lost_stretches", a.lost_stretches},
      {"max_lost_deviation", a.max_lost_deviation},
      {"farthest", a.farthest_hull < 0
                       ? nlohmann::json(nullptr)
                       : nlohmann::json{{"point", {a.farthest_point.x(), a.farthest_point.y(), a.farthest_point.z()}},
                                        {"face", a.farthest_face},
                                        {"hull", a.farthest_hull}}},
      {"beyond_deviation", a.beyond_deviation},
      {"centre_rays", a.centre_rays},
      {"reach_lost", a.reach_lost},
      {"enclosed_balls", a.enclosed_balls},
      {"deepest_reach", p.hull < 0 ? nlohmann::json(nullptr)
                                   : nlohmann::json{{"centre", {p.centre.x(), p.centre.y(), p.centre.z()}},
                                                    {"face", p.face},
                                                    {"hull", p.hull},
                                                    {"depth", p.depth},
                                                    {"clearance", p.clearance},
                                                    {"opening", p.opening}}},
      {"undecided", a.undecided},
      {"first_undecided", ray_point_json(a.first_undecided)}};
}

} // namespace

nlohmann::json audit_report_json(const PreparedMesh& prepared, const validate::AuditReport& a) {
  const validate::ProbeReport& r = a.probe;
  const validate::CheckReport& recheck = a.recheck;
  const validate::BehaviourReport& b = a.behaviour;
  nlohmann::json worst = nlohmann::json::array();
  for (const validate::LostPlace& p : r.worst) worst.push_back(place_json(p));
  nlohmann::json findings = nlohmann::json::array();
  for (validate::AuditFinding f : a.findings) findings.push_back(validate::audit_finding_name(f));
  return {
      {"clean", a.clean()},
      {"findings", findings},
      {"hull_count", a.hull_count},
      {"groups_without_area", a.groups_without_area},
      {"tolerance", prepared.tolerance.length},
      {"probe_distance", optional_json(r.probe_distance)},
      {"resolution", r.resolution},
      {"finest_ray_spacing", r.finest_spacing},
      {"coarsest_ray_spacing", r.coarsest_spacing},
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
        {"faces_inside", recheck.faces_inside},
        {"inside_allowed", recheck.inside_allowed},
        {"uncovered_area", recheck.uncovered_area},
        {"total_area", recheck.total_area},
        {"examples", recheck.examples}}},
      {"worst", worst},
      {"allowance", allowance_json(r.allowance)},
      {"behaviour",
       {{"proxies", b.poses},
        {"size", b.size},
        {"missed", b.missed},
        {"false_contacts", b.false_contacts},
        {"deep_false_contacts", b.deep_false_contacts},
        {"deep_false_boxes", b.deep_false_boxes},
        {"enclosed_false_contacts", b.enclosed_false_contacts},
        {"max_false_depth", b.max_false_depth},
        {"deepest_false_contact", false_contact_json(b.deepest_false)},
        {"both_touch", b.both_touch},
        {"mean_normal_angle_deg", b.mean_normal_angle},
        {"max_normal_angle_deg", b.max_normal_angle}}},
  };
}

} // namespace hullcover::app
