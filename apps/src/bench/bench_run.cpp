#include "bench_run.h"

#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/bvh/hull_world.h"
#include "hullcover/bvh/runtime_file.h"
#include "hullcover/covering/covering.h"
#include "hullcover/covering/movement_covering.h"
#include "hullcover/validate/audit.h"
#include "hullcover/validate/movement_audit.h"

#include <chrono>
#include <filesystem>

namespace hullcover::app::bench {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

std::optional<double> on_or_off(double x) { return x > 0.0 ? std::optional<double>(x) : std::nullopt; }

void count_shapes(const Covering& covering, BenchRow& row) {
  long facets = 0, vertices = 0;
  for (const CoveringHull& h : covering.hulls) {
    facets += static_cast<long>(h.polytope.facets.size());
    vertices += static_cast<long>(h.polytope.vertices.size());
  }
  row.hulls = static_cast<long>(covering.hulls.size());
  row.hulls_per_face = row.faces > 0 ? static_cast<double>(row.hulls) / row.faces : 0.0;
  row.facets_per_hull = row.hulls > 0 ? static_cast<double>(facets) / row.hulls : 0.0;
  row.vertices_per_hull = row.hulls > 0 ? static_cast<double>(vertices) / row.hulls : 0.0;
}

void copy_audit(const validate::AuditReport& a, BenchRow& row) {
  row.clean = a.clean();
  for (validate::AuditFinding f : a.findings)
    row.findings += (row.findings.empty() ? "" : " ") + std::string(validate::audit_finding_name(f));
  row.front_rays = a.probe.front.rays;
  row.front_lost = a.probe.front.lost;
  row.opening_rays = a.probe.opening.rays;
  row.opening_lost = a.probe.opening.lost;
  row.max_lost_depth = a.probe.max_lost_depth;
  const validate::AllowanceReport& allowance = a.probe.allowance;
  row.max_lost_deviation = allowance.max_lost_deviation;
  row.centre_rays = allowance.centre_rays;
  row.reach_lost = allowance.reach_lost;
  row.undecided = allowance.undecided;
  row.proxies = a.behaviour.poses;
  row.missed_contacts = a.behaviour.missed;
  row.false_contacts = a.behaviour.deep_false_contacts;
  const double total = a.recheck.total_area;
  row.coverage_percent = total > 0.0 ? 100.0 * (1.0 - a.recheck.uncovered_area / total) : 100.0;
}

} // namespace

Result<BenchRow> bench_setting(const PreparedMesh& prepared, const SceneSpec& scene, const Setting& setting,
                               const bvh::TriangleWorld& triangles, const QueryPoses& poses,
                               const BenchRunOptions& options) {
  const std::filesystem::path scene_path(scene.path);
  BenchRow row;
  row.scene = scene_path.filename().string();
  row.setting = setting.label();
  row.tolerance = prepared.tolerance.length;
  row.diagonal = prepared.tolerance.diagonal;
  row.faces = static_cast<int>(prepared.mesh.triangles.size());
  const double metre = scene.metre(row.diagonal);
  row.agent_radius = setting.agent_radius.resolve(metre, row.diagonal);
  row.max_deviation = setting.max_deviation.resolve(metre, row.diagonal);
  row.max_deviation_percent = row.diagonal > 0.0 ? 100.0 * row.max_deviation / row.diagonal : 0.0;

  row.reach = setting.reach;
  MovementOptions movement;
  movement.radius = row.agent_radius;
  movement.reach = setting.reach == "fly" ? AgentReach::fly : AgentReach::walk;
  if (setting.slop.value > 0.0) movement.slop = setting.slop.resolve(metre, row.diagonal);
  DecomposeOptions decompose_options;
  decompose_options.agent_radius = on_or_off(row.agent_radius);
  decompose_options.max_deviation = on_or_off(row.max_deviation);
  const Clock::time_point start = Clock::now();
  Result<Covering> covering = Status{};
  if (row.reach.empty()) {
    covering = decompose(prepared, decompose_options);
  } else {
    Result<MovementCovering> made = decompose_for_movement(prepared, movement);
    if (made.ok()) {
      row.slop = made.value().movement.slop;
      row.undecided = made.value().movement.undecided;
      covering = std::move(made).value().covering;
    } else {
      covering = made.status();
    }
  }
  row.decompose_seconds = seconds_since(start);
  if (!covering.ok()) return covering.status();
  count_shapes(covering.value(), row);

  row.runtime_path =
      (std::filesystem::path(options.out_dir) / (scene_path.stem().string() + "." + setting.file_label() + ".hcw"))
          .string();
  if (Status s = bvh::write_runtime_file(bvh::runtime_hulls(covering.value()), row.runtime_path); !s.ok()) return s;
  std::error_code size_error;
  row.runtime_bytes = static_cast<long>(std::filesystem::file_size(row.runtime_path, size_error));

  // Timed and audited from the file, as a server and a level designer get it.
  Result<std::vector<bvh::RuntimeHull>> loaded = bvh::read_runtime_file(row.runtime_path);
  if (!loaded.ok()) return loaded.status();
  const std::vector<bvh::RuntimeHull> file_hulls = std::move(loaded).value();
  Result<std::shared_ptr<const bvh::HullWorld>> world = bvh::HullWorld::build(file_hulls);
  if (!world.ok()) return world.status();
  row.query_radius = poses.radius;
  row.query_half_height = poses.half_height;
  Result<QueryTimings> timed = time_queries(*world.value(), triangles, poses, options.query_seconds);
  if (!timed.ok()) return timed.status();
  row.queries = timed.value();

  const Clock::time_point audit_start = Clock::now();
  if (!row.reach.empty()) {
    validate::MovementAuditOptions audit;
    audit.agent = movement;
    const Result<validate::MovementAuditReport> report =
        validate::audit_movement(prepared, file_hulls, audit, movement.threads);
    row.audit_seconds = seconds_since(audit_start);
    if (!report.ok()) return report.status();
    const validate::MovementAuditReport& m = report.value();
    row.clean = m.clean();
    if (m.sinking > 0) row.findings = "centres_sinking";
    if (m.contacts_lost > 0) row.findings += (row.findings.empty() ? "" : " ") + std::string("contacts_lost");
    row.reachable_centres = m.reachable_points;
    row.sinking = m.sinking;
    row.deepest_sinking = m.deepest;
    row.touching_poses = m.touching_poses;
    row.contacts_lost = m.contacts_lost;
    return row;
  }
  const Result<validate::HullSet> set = validate::load_hull_set(row.runtime_path);
  if (!set.ok()) return set.status();
  validate::AuditOptions audit_options;
  audit_options.probe.allowance.agent_radius = on_or_off(row.agent_radius);
  audit_options.probe.allowance.max_deviation = on_or_off(row.max_deviation);
  const Result<validate::AuditReport> audited = validate::run_audit(prepared, set.value(), audit_options);
  row.audit_seconds = seconds_since(audit_start);
  if (!audited.ok()) return audited.status();
  copy_audit(audited.value(), row);
  return row;
}

} // namespace hullcover::app::bench
