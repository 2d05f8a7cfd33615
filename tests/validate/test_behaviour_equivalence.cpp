// Behaviour equivalence (behaviour_equivalence.h): a proxy clear of the
// triangles that reaches deeper than tol into a hull is lost space where the
// space it reaches is free, and allowed where it is enclosed.

#include "box_hulls.h"
#include "covering_fixture.h"

#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/validate/audit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>

namespace hullcover::validate {
namespace {

using V = Eigen::Vector3d;

// Cut from Red Eclipse's deathtrap (faces 4246-13516, 16 units of the 80
// the rail runs): a slot in a wall, floor at z = -8 and ceiling at z = 8,
// its back walls at x = -338 above and below a rail (x -338..-336, z -4..4)
// whose side against the back wall is left out. The slot's floor and ceiling
// run on 6 units behind the back walls, so their rays call that space free
// (the floor's meet the ceiling's front). A proxy there passes the rail's
// missing side without touching a triangle; what it reaches, the inside of
// the rail, lies on no open ray (each ends on a back of the rail): enclosed.
Mesh deathtrap_rail() {
  const double y0 = 72, y1 = 88;
  const std::vector<std::array<V, 4>> quads = {
      {{V(-344, y0, -8), V(-336, y0, -8), V(-336, y1, -8), V(-344, y1, -8)}}, // floor, up
      {{V(-344, y0, 8), V(-344, y1, 8), V(-336, y1, 8), V(-336, y0, 8)}},     // ceiling, down
      {{V(-338, y0, -8), V(-338, y1, -8), V(-338, y1, -4), V(-338, y0, -4)}}, // back wall below the rail, +x
      {{V(-338, y0, 4), V(-338, y1, 4), V(-338, y1, 8), V(-338, y0, 8)}},     // back wall above it, +x
      {{V(-338, y0, -4), V(-338, y1, -4), V(-336, y1, -4), V(-336, y0, -4)}}, // rail bottom, down
      {{V(-338, y0, 4), V(-336, y0, 4), V(-336, y1, 4), V(-338, y1, 4)}},     // rail top, up
      {{V(-336, y0, -4), V(-336, y1, -4), V(-336, y1, 4), V(-336, y0, 4)}},   // rail front, +x
  };
  Mesh m;
  for (const auto& q : quads) {
    test::add_triangle(m, q[0], q[1], q[2]);
    test::add_triangle(m, q[0], q[2], q[3]);
  }
  return m;
}

AuditReport audit_with(const PreparedMesh& prepared, const bvh::RuntimeHull& solid) {
  HullSet set;
  set.hulls.push_back(solid);
  const Mesh& m = prepared.mesh;
  for (const Eigen::Vector3i& t : m.triangles) // every face on a hull's surface
    set.hulls.push_back(bvh::flat_triangle_hull(m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]));
  AuditOptions options;
  options.behaviour.proxies = 3000;
  options.behaviour.size = 5.785637389259717; // deathtrap's default proxy size
  Result<AuditReport> r = run_audit(prepared, set, options);
  EXPECT_TRUE(r.ok()) << r.status().message();
  return r.ok() ? r.value() : AuditReport{};
}

TEST(Behaviour, AProxyReachingThroughAnOpeningIntoEnclosedSpaceTakesNothingFree) {
  constexpr double kDeathtrapTolerance = 0.011571274778519436;
  Result<PreparedMesh> prepared = prepare_mesh(deathtrap_rail(), kDeathtrapTolerance);
  ASSERT_TRUE(prepared.ok()) << prepared.status().message();

  // The decomposer's hull there: the rail closed.
  const AuditReport rail = audit_with(prepared.value(), test::box_hull(V(-338, 72, -4), V(-336, 88, 4)));
  const BehaviourReport& b = rail.behaviour;
  EXPECT_GT(b.enclosed_false_contacts, 0) << "no proxy reached the rail: the cut tests nothing";
  EXPECT_EQ(b.deep_false_contacts, 0) << b.deepest_false.depth << " into hull " << b.deepest_false.hull << " from "
                                      << b.deepest_false.centre.transpose();
  EXPECT_FALSE(test::has_finding(rail, AuditFinding::false_contacts));
  EXPECT_EQ(rail.probe.front.lost + rail.probe.opening.lost, 0); // the rays agree: enclosed

  // Control: a hull in the free space behind the back walls, where the
  // proxies stand, is lost space to both.
  const AuditReport floating = audit_with(prepared.value(), test::box_hull(V(-343, 76, -2), V(-340, 84, 2)));
  EXPECT_GT(floating.behaviour.deep_false_contacts, 0);
  EXPECT_TRUE(test::has_finding(floating, AuditFinding::false_contacts));
  EXPECT_GT(floating.probe.front.lost, 0);
}

} // namespace
} // namespace hullcover::validate
