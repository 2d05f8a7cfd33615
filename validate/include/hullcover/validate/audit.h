#pragma once
/// \file audit.h
/// The whole audit of a set of hulls against the scene they stand for, and
/// its verdict: what `hullcover audit` runs and prints, for a program that
/// links the library instead. Three independent looks: the accessible-space
/// probe (accessible_space.h), the re-check of the paper's conditions
/// (validity_recheck.h) and the character proxies (behaviour_equivalence.h).

#include "hullcover/validate/accessible_space.h"
#include "hullcover/validate/behaviour_equivalence.h"
#include "hullcover/validate/hull_set.h"
#include "hullcover/validate/validity_recheck.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

namespace hullcover::validate {

/// Everything the audit can be told; every default is the command's.
struct AuditOptions {
  /// The accessible-space probe: ray spacing (and octree cell), an optional
  /// cap on the rays (none by default), and where to write the octree of
  /// lost cells (nowhere when empty).
  ProbeOptions probe;
  /// Half-length of the re-check's boundary bars, scene units (> 0);
  /// default `kDefaultBarHalfLengthRelative` x the diagonal (the paper-mode default;
  /// exact mode decomposes with 4 x tol sheets, and the re-check reports bars
  /// without judging them).
  std::optional<double> bar_half_length;
  /// The character proxies: how many, their seed and their size. With an
  /// agent radius (probe.allowance) the size defaults to it and may not be
  /// smaller.
  BehaviourOptions behaviour;
  /// Called now and then with the fraction of the audit done (0..1, never
  /// decreasing): the re-check, the probe's rays, then the proxies; always
  /// from the thread that called run_audit; may be empty.
  std::function<void(double)> progress;
  /// Threads re-checking hulls and faces and tracing the probe's rays at
  /// once; 0: every core (std::thread::hardware_concurrency), negative
  /// refused. The report is the same, to the last bit, for any count: work
  /// is split by hull, face and open edge, and what each finds is added up
  /// in that order. The proxies run on the calling thread (a few percent of
  /// the time).
  int threads = 0;
};

/// One reason the audit is not clean.
enum class AuditFinding {
  front_space_lost,     ///< open rays in front of faces pass deeper than tol inside hulls
  openings_lost,        ///< open rays beyond open edges pass deeper than tol inside hulls
  recheck_violations,   ///< the re-check's violations() (all but the paper's bars)
  contacts_missed,      ///< proxies touch the triangles but no hull
  false_contacts,       ///< proxies clear of the triangles lie deeper than tol inside a hull
  deviation_exceeded,   ///< with a max deviation E alone: a hull takes a point farther than E + tol from the mesh
  reachable_space_lost, ///< with an agent radius r: a ball of radius r clear of every triangle reaches into a hull
  allowance_undecided,  ///< the allowance audit ran out of evaluations on some ray
};

/// Short stable name of a finding ("front_space_lost", ...), for logs and JSON.
const char* audit_finding_name(AuditFinding finding);

/// The audit's figures and its verdict.
struct AuditReport {
  ProbeReport probe;                  ///< free space lost, openings lost, lost volume
  CheckReport recheck;                ///< the paper's conditions 1-4 and coverage, re-checked
  BehaviourReport behaviour;          ///< missed and false contacts of the proxies
  size_t hull_count = 0;              ///< hulls audited
  int groups_without_area = 0;        ///< OBJ groups skipped for spanning no area (from the HullSet)
  std::vector<AuditFinding> findings; ///< why it is not clean, in enum order; empty when clean

  /// No accessible space lost: no finding.
  bool clean() const { return findings.empty(); }
};

/// The verdict on the three reports: one finding per kind of loss. The
/// paper's bars are not counted: they stand in for openings at one point
/// per edge, and the probe measures the openings themselves. False contacts
/// count when deeper than tol (lost space, found by the proxies); shallower
/// ones and normal angles are reported, not judged. Enclosed space is
/// allowed. With an allowance (probe.allowance), the strict lost rays are
/// reported, not judged: the allowance audit judges what the hulls take
/// instead; false contacts count only under an agent radius alone, and only
/// for spheres and capsules (unions of balls of the proxies' radius >= r).
std::vector<AuditFinding> audit_findings(const ProbeReport& probe, const CheckReport& recheck,
                                         const BehaviourReport& behaviour);

/// Audits `hulls` against `prepared` (whose tolerance the audit uses): the
/// re-check, then the probe, then the proxies. Fails with the first failing
/// step's status: `invalid_argument` for a bar half-length <= 0 or
/// infinite, for no hull or a malformed one (HullWorld::build), for a
/// mesh with no face with a surface (TriangleWorld::build), or for the
/// probe's and the proxies' own bad options (probe_accessible_space,
/// compare_behaviour), or for a negative thread count; `unwritable_file`
/// when the octree cannot be written;
/// `internal_error` when anything else goes wrong. Never throws.
[[nodiscard]] Result<AuditReport> run_audit(const PreparedMesh& prepared, const HullSet& hulls,
                                            const AuditOptions& options);

} // namespace hullcover::validate
