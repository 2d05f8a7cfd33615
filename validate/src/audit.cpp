#include "hullcover/validate/audit.h"

#include "hullcover/covering/decompose_options.h"

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
      bvh::TriangleWorld::build(prepared.mesh, prepared.tolerance.length);
  for (const Status& s : {hulls.status(), triangles.status()})
    if (!s.ok()) return s;
  return Worlds{std::move(hulls).value(), std::move(triangles).value()};
}

Result<AuditReport> audit(const PreparedMesh& prepared, const HullSet& set, const AuditOptions& options) {
  const double bar_half_length =
      options.bar_half_length.value_or(kDefaultBarHalfLengthRelative * prepared.tolerance.diagonal);
  if (!(bar_half_length > 0.0) || std::isinf(bar_half_length))
    return Status{StatusCode::invalid_argument, "the bar half-length must be a positive length"};
  AuditReport report;
  report.hull_count = set.hulls.size();
  report.groups_without_area = set.groups_without_area;
  report.recheck = recheck_hulls(prepared, hulls_under_check(set.hulls), bar_half_length);
  const Result<Worlds> worlds = build_worlds(prepared, set);
  if (!worlds.ok()) return worlds.status();
  const bvh::TriangleWorld& triangles = *worlds.value().triangles;
  const bvh::HullWorld& hulls = *worlds.value().hulls;
  Result<ProbeReport> probed = probe_accessible_space(prepared, triangles, hulls, options.probe);
  if (!probed.ok()) return probed.status();
  report.probe = std::move(probed).value();
  Result<BehaviourReport> compared = compare_behaviour(prepared, triangles, hulls, options.behaviour);
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
  }
  return "unknown";
}

std::vector<AuditFinding> audit_findings(const ProbeReport& probe, const CheckReport& recheck,
                                         const BehaviourReport& behaviour) {
  std::vector<AuditFinding> findings;
  if (probe.front.lost != 0) findings.push_back(AuditFinding::front_space_lost);
  if (probe.opening.lost != 0) findings.push_back(AuditFinding::openings_lost);
  if (recheck.violations() != 0) findings.push_back(AuditFinding::recheck_violations);
  if (behaviour.missed != 0) findings.push_back(AuditFinding::contacts_missed);
  if (behaviour.deep_false_contacts != 0) findings.push_back(AuditFinding::false_contacts);
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
