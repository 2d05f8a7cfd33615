#include "hullcover/validate/audit.h"

#include "hullcover/covering/decompose_options.h"
#include "hullcover/geometry/parallel_for.h"

#include <cmath>
#include <exception>
#include <memory>
#include <string>
#include <utility>

namespace hullcover::validate {
namespace {

// The worlds the probe and the proxies query: the hulls, and the triangles
// they stand for.
struct Worlds {
  std::shared_ptr<const bvh::HullWorld> hulls;
  std::shared_ptr<const bvh::TriangleWorld> triangles;
};

Result<Worlds> build_worlds(const PreparedMesh& prepared, const HullSet& set) {
  Result<std::shared_ptr<const bvh::HullWorld>> hulls = bvh::HullWorld::build(set.hulls);
  Result<std::shared_ptr<const bvh::TriangleWorld>> triangles =
      bvh::TriangleWorld::build(prepared.mesh, prepared.tolerance.length, prepared.connectivity.zero_area);
  for (const Status& s : {hulls.status(), triangles.status()})
    if (!s.ok()) return s;
  return Worlds{std::move(hulls).value(), std::move(triangles).value()};
}

// Where the audit's progress stands after the re-check and before the
// proxies: the probe's rays take most of its time.
constexpr double kRecheckShareOfAudit = 0.1;
constexpr double kProxiesStartOfAudit = 0.9;

Result<AuditReport> audit(const PreparedMesh& prepared, const HullSet& set, const AuditOptions& options) {
  const double bar_half_length =
      options.bar_half_length.value_or(kDefaultBarHalfLengthRelative * prepared.tolerance.largest_island);
  if (!(bar_half_length > 0.0) || std::isinf(bar_half_length))
    return Status{StatusCode::invalid_argument, "the bar half-length must be a positive length"};
  if (options.threads < 0)
    return Status{StatusCode::invalid_argument, "the thread count must be 0 (every core) or more"};
  const int threads = threads_to_use(options.threads);
  const AllowanceOptions& allowance = options.probe.allowance;
  BehaviourOptions behaviour = options.behaviour;
  if (allowance.agent_radius) {
    if (behaviour.size && *behaviour.size < *allowance.agent_radius)
      return Status{StatusCode::invalid_argument, "the proxies may not be smaller than the agent radius"};
    behaviour.size = behaviour.size.value_or(*allowance.agent_radius);
  }
  AuditReport report;
  report.hull_count = set.hulls.size();
  report.groups_without_area = set.groups_without_area;
  const auto progress = [&](double fraction) {
    if (options.progress) options.progress(fraction);
  };
  report.recheck = recheck_hulls(prepared, hulls_under_check(set.hulls), bar_half_length, allowance.any(), threads);
  progress(kRecheckShareOfAudit);
  const Result<Worlds> worlds = build_worlds(prepared, set);
  if (!worlds.ok()) return worlds.status();
  const bvh::TriangleWorld& triangles = *worlds.value().triangles;
  const bvh::HullWorld& hulls = *worlds.value().hulls;
  ProbeOptions probe = options.probe;
  if (options.progress)
    probe.progress = [&](double fraction) {
      progress(kRecheckShareOfAudit + (kProxiesStartOfAudit - kRecheckShareOfAudit) * fraction);
    };
  Result<ProbeReport> probed = probe_accessible_space(prepared, triangles, hulls, probe, threads);
  if (!probed.ok()) return probed.status();
  report.probe = std::move(probed).value();
  progress(kProxiesStartOfAudit);
  Result<BehaviourReport> compared = compare_behaviour(prepared, triangles, hulls, behaviour);
  progress(1.0);
  if (!compared.ok()) return compared.status();
  report.behaviour = std::move(compared).value();
  report.findings = audit_findings(report.probe, report.recheck, report.behaviour);
  return report;
}

} // namespace

const char* audit_finding_name(AuditFinding finding) {
  switch (finding) {
    case AuditFinding::front_space_lost: return "front_space_lost";
    case AuditFinding::openings_lost: return "openings_lost";
    case AuditFinding::recheck_violations: return "recheck_violations";
    case AuditFinding::contacts_missed: return "contacts_missed";
    case AuditFinding::false_contacts: return "false_contacts";
    case AuditFinding::deviation_exceeded: return "deviation_exceeded";
    case AuditFinding::reachable_space_lost: return "reachable_space_lost";
    case AuditFinding::allowance_undecided: return "allowance_undecided";
  }
  return "unknown";
}

std::vector<AuditFinding> audit_findings(const ProbeReport& probe, const CheckReport& recheck,
                                         const BehaviourReport& behaviour) {
  std::vector<AuditFinding> findings;
  const AllowanceReport& allowance = probe.allowance;
  const bool exact = !allowance.options.any();
  if (exact && probe.front.lost != 0) findings.push_back(AuditFinding::front_space_lost);
  if (exact && probe.opening.lost != 0) findings.push_back(AuditFinding::openings_lost);
  if (recheck.violations() != 0) findings.push_back(AuditFinding::recheck_violations);
  if (behaviour.missed != 0) findings.push_back(AuditFinding::contacts_missed);
  // With E alone a proxy may meet a hull within E of the mesh, taken by
  // right: the rays judge it there. An agent radius promises spheres and
  // capsules of that size exact contacts, E or not (the knobs combine as
  // both promises: README "Agent-exact coverings").
  const long judged_false = exact ? behaviour.deep_false_contacts
                            : allowance.options.agent_radius
                                ? behaviour.deep_false_contacts - behaviour.deep_false_boxes
                                : 0;
  if (judged_false != 0) findings.push_back(AuditFinding::false_contacts);
  if (allowance.beyond_deviation != 0) findings.push_back(AuditFinding::deviation_exceeded);
  if (allowance.reach_lost != 0) findings.push_back(AuditFinding::reachable_space_lost);
  if (allowance.undecided != 0) findings.push_back(AuditFinding::allowance_undecided);
  return findings;
}

Result<AuditReport> run_audit(const PreparedMesh& prepared, const HullSet& hulls, const AuditOptions& options) {
  try {
    return audit(prepared, hulls, options);
  } catch (const std::exception& e) {
    return Status{StatusCode::internal_error, std::string("audit failed: ") + e.what()};
  }
}

} // namespace hullcover::validate
