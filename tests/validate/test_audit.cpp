// The audit's verdict, as a library user gets it: the decomposer's hulls of
// the demo building are clean, and a hull closing its doorway is caught for
// the space it takes (not for anything else).

#include "box_hulls.h"
#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/bvh/hull_contact.h"
#include "hullcover/validate/audit.h"

#include "covering_fixture.h"
#include "temp_dir.h"

#include "hullcover/bvh/runtime_file.h"

#include "hullcover/mesh/scene_builder.h"

#include <gtest/gtest.h>

#include <ostream>
#include <string>

namespace hullcover::validate {

// GoogleTest prints findings by name (found by argument-dependent lookup).
void PrintTo(AuditFinding finding, std::ostream* os) { *os << audit_finding_name(finding); }

namespace {

using V = Eigen::Vector3d;

using test::box_hull;

// Coarser than the defaults (R / 8 = 0.06 m here) and fewer proxies: the
// unit tier stays fast, and a 1.2 x 2.1 x 0.2 m doorway still holds samples.
AuditOptions quick_options() {
  AuditOptions o;
  o.probe.resolution = 0.15;
  o.behaviour.proxies = 600;
  return o;
}

TEST(Audit, TheDecomposedBuildingIsCleanAndAClosedDoorwayLosesSpace) {
  const auto d = test::decompose_and_check(demo_building());
  ASSERT_TRUE(d);
  HullSet set;
  set.hulls = bvh::runtime_hulls(d->covering);
  const Result<AuditReport> clean = run_audit(d->prepared, set, quick_options());
  ASSERT_TRUE(clean.ok()) << clean.status().message();
  EXPECT_TRUE(clean.value().clean()) << test::finding_names(clean.value().findings);
  EXPECT_EQ(clean.value().hull_count, d->covering.hulls.size());
  EXPECT_GT(clean.value().probe.front.rays, 1000);
  EXPECT_GT(clean.value().behaviour.poses, 300);

  // The same hulls plus one that fills the doorway exactly: it touches the
  // mesh only on its surface, so the re-check and the proxies find nothing;
  // the space in front of the floor and the door jambs is lost.
  set.hulls.push_back(box_hull(V(-0.6, 0.0, 3.8), V(0.6, 2.1, 4.0)));
  const Result<AuditReport> closed = run_audit(d->prepared, set, quick_options());
  ASSERT_TRUE(closed.ok()) << closed.status().message();
  EXPECT_FALSE(closed.value().clean());
  EXPECT_EQ(closed.value().findings, (std::vector<AuditFinding>{AuditFinding::front_space_lost}))
      << test::finding_names(closed.value().findings);
  EXPECT_GT(closed.value().probe.lost_cells, 0);
  ASSERT_FALSE(closed.value().probe.worst.empty());
  EXPECT_EQ(closed.value().probe.worst[0].hull, static_cast<int>(set.hulls.size()) - 1);
}

// The verdict counts lost space, re-check violations, missed contacts and
// false contacts deeper than tol; the paper's bars and shallow false
// contacts are reported only.
TEST(Audit, TheVerdictCountsLossesNotBarsOrShallowFalseContacts) {
  EXPECT_TRUE(audit_findings({}, {}, {}).empty());
  ProbeReport probe;
  CheckReport recheck;
  BehaviourReport behaviour;
  recheck.bars_inside = 3;
  behaviour.false_contacts = 5;
  EXPECT_TRUE(audit_findings(probe, recheck, behaviour).empty());
  probe.opening.lost = 1;
  recheck.faces_uncovered = 1;
  behaviour.missed = 2;
  behaviour.deep_false_contacts = 1;
  EXPECT_EQ(audit_findings(probe, recheck, behaviour),
            (std::vector<AuditFinding>{AuditFinding::openings_lost, AuditFinding::recheck_violations,
                                       AuditFinding::contacts_missed, AuditFinding::false_contacts}));
  probe = {};
  probe.front.lost = 1;
  probe.lost_cells = 1; // a picture of the lost rays, not a finding of its own
  EXPECT_EQ(audit_findings(probe, {}, {}), (std::vector<AuditFinding>{AuditFinding::front_space_lost}));
}

// A covering written as OBJ (flat hulls as their front polygon) and as the
// runtime file is one set of hulls: the audit gives the same figures.
TEST(Audit, ACoveringAuditsTheSameFromObjAndFromTheRuntimeFile) {
  const auto d = test::decompose_and_check(demo_building());
  ASSERT_TRUE(d);
  test::TempDir dir;
  const std::string obj = dir.write("hulls.obj", test::covering_obj_bytes(d->covering));
  const std::string hcw = dir.path("hulls.hcw");
  ASSERT_TRUE(bvh::write_runtime_file(bvh::runtime_hulls(d->covering), hcw).ok());
  const Result<HullSet> from_obj = load_hull_set(obj), from_hcw = load_hull_set(hcw);
  ASSERT_TRUE(from_obj.ok() && from_hcw.ok());
  EXPECT_EQ(from_obj.value().groups_without_area, 0);
  ASSERT_EQ(from_obj.value().hulls.size(), from_hcw.value().hulls.size());
  int flat = 0;
  for (const bvh::RuntimeHull& h : from_obj.value().hulls) flat += polytope_volume(h.shape) == 0.0;
  EXPECT_GT(flat, 0); // the test means something only with flat hulls in it
  const Result<AuditReport> a = run_audit(d->prepared, from_obj.value(), quick_options());
  const Result<AuditReport> b = run_audit(d->prepared, from_hcw.value(), quick_options());
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(a.value().findings, b.value().findings)
      << test::finding_names(a.value().findings) << "/ " << test::finding_names(b.value().findings);
  EXPECT_EQ(a.value().probe.front.lost, b.value().probe.front.lost);
  EXPECT_EQ(a.value().probe.opening.lost, b.value().probe.opening.lost);
  EXPECT_EQ(a.value().probe.front.enclosed, b.value().probe.front.enclosed);
  EXPECT_EQ(a.value().recheck.total(), b.value().recheck.total());
  EXPECT_EQ(a.value().recheck.faces_uncovered, b.value().recheck.faces_uncovered);
  EXPECT_EQ(a.value().behaviour.missed, b.value().behaviour.missed);
  EXPECT_EQ(a.value().behaviour.false_contacts, b.value().behaviour.false_contacts);
}

TEST(Audit, RefusesBadOptionsWithAStatus) {
  Mesh room;
  add_box(room, V(0, 0, 0), V(4, 3, 5), false);
  const auto d = test::decompose_and_check(room);
  ASSERT_TRUE(d);
  HullSet set;
  set.hulls = bvh::runtime_hulls(d->covering);
  AuditOptions o = quick_options();
  o.bar_half_length = -1.0;
  EXPECT_EQ(run_audit(d->prepared, set, o).status().code(), StatusCode::invalid_argument);
  o = quick_options();
  o.behaviour.proxies = 0;
  EXPECT_EQ(run_audit(d->prepared, set, o).status().code(), StatusCode::invalid_argument);
  EXPECT_EQ(run_audit(d->prepared, HullSet{}, quick_options()).status().code(), StatusCode::invalid_argument);
}

} // namespace
} // namespace hullcover::validate
