// Faces thinner than tol join no patch (lib/covering/src/merging/face_coverage.h),
// yet coverage (docs/definitions-and-proofs.md: every point of every face on a hull, within tol)
// holds for them too. The fan below is how a Cube map trims a wall: slivers
// between two straight lines, each thinner than tol, together a strip with
// real area.

#include "covering_fixture.h"

#include "hullcover/bvh/hull_contact.h"
#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/mesh/scene_builder.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace hullcover {
namespace {

using test::add_quad_facing;
using test::add_triangle;
using test::decompose_and_check;
using V = Eigen::Vector3d;

constexpr double kTol = 0.01;

// Adds triangle a-b-c facing `front`; returns its face index.
int add_facing(Mesh& m, const V& a, const V& b, const V& c, const V& front) {
  if ((b - a).cross(c - a).dot(front) >= 0.0)
    add_triangle(m, a, b, c);
  else
    add_triangle(m, a, c, b);
  return static_cast<int>(m.triangles.size()) - 1;
}

struct ThinScene {
  Mesh mesh;
  std::vector<int> fan; // slivers fanned from one corner: one triangle together
  int lone = -1;        // a sliver far from everything
  int along_floor = -1; // a sliver along the floor's edge, in its plane
};

ThinScene thin_scene() {
  ThinScene s;
  const V up(0, 1, 0);
  add_quad_facing(s.mesh, V(-5, 0, -5), V(-5, 0, 5), V(5, 0, 5), V(5, 0, -5), up);
  // Ten slivers between x = 20 .. 30 on z = 0 and one corner 0.1 off that
  // line: each 1 wide at the line, 20-30 long, so its height is under
  // 0.005 (half tol); together the triangle (20, 2, 0), (30, 2, 0), (0, 2, 0.1).
  for (int i = 20; i < 30; ++i) s.fan.push_back(add_facing(s.mesh, V(i, 2, 0), V(i + 1, 2, 0), V(0, 2, 0.1), up));
  s.lone = add_facing(s.mesh, V(0, 4, -3), V(10, 4, -3), V(5, 4, -3.005), up);
  s.along_floor = add_facing(s.mesh, V(-5, 0, 5), V(5, 0, 5), V(0, 0, 5.004), up);
  return s;
}

// Hull index claiming face f, -1 when none does.
int claiming_hull(const Covering& covering, int f) {
  for (size_t h = 0; h < covering.hulls.size(); ++h) {
    const std::vector<int>& faces = covering.hulls[h].faces;
    if (std::binary_search(faces.begin(), faces.end(), f)) return static_cast<int>(h);
  }
  return -1;
}

TEST(FaceCoverage, EveryThinFaceIsWithinTolOfAHull) {
  const ThinScene s = thin_scene();
  // decompose_and_check also runs the audit's re-check, which counts a
  // thin face no hull covers.
  const auto d = decompose_and_check(s.mesh, {}, kTol);
  ASSERT_TRUE(d);
  for (int f = 0; f < static_cast<int>(s.mesh.triangles.size()); ++f)
    ASSERT_EQ(d->prepared.connectivity.zero_area[f] != 0, f > 1) << "face " << f;
  // Measured with the runtime's distance, not the decomposer's.
  std::vector<bvh::RuntimeHull> hulls;
  for (const CoveringHull& h : d->covering.hulls) hulls.push_back(bvh::make_runtime_hull(h.polytope, 0));
  for (int f = 2; f < static_cast<int>(s.mesh.triangles.size()); ++f) {
    const Eigen::Vector3i& t = d->prepared.mesh.triangles[f];
    bool covered = false;
    for (const bvh::RuntimeHull& hull : hulls) {
      bool all = true;
      for (int k = 0; k < 3; ++k) all &= bvh::closest_to_point(hull, d->prepared.mesh.positions[t[k]]).distance <= kTol;
      covered |= all;
    }
    EXPECT_TRUE(covered) << "thin face " << f;
  }
}

TEST(FaceCoverage, AFanThatIsOneTriangleGetsOneFlatHull) {
  const ThinScene s = thin_scene();
  const auto d = decompose_and_check(s.mesh, {}, kTol);
  ASSERT_TRUE(d);
  const int fan_hull = claiming_hull(d->covering, s.fan.front());
  ASSERT_GE(fan_hull, 0);
  const CoveringHull& hull = d->covering.hulls[fan_hull];
  EXPECT_EQ(hull.faces, s.fan);
  EXPECT_TRUE(hull.planar);
  EXPECT_EQ(hull.thickness, 0.0);
  EXPECT_EQ(hull.polytope.vertices.size(), 3u); // the fan's outline, not its 12 points
  const int lone_hull = claiming_hull(d->covering, s.lone);
  ASSERT_GE(lone_hull, 0);
  EXPECT_EQ(d->covering.hulls[lone_hull].faces, std::vector<int>{s.lone});
  // The floor's hull is within tol of the sliver along its edge: no hull of its own.
  EXPECT_EQ(claiming_hull(d->covering, s.along_floor), -1);
  EXPECT_EQ(d->covering.statistics.faces_given_flat_hulls, 11);
  EXPECT_EQ(d->covering.statistics.faces_left_uncovered, 0);
  EXPECT_EQ(d->covering.hulls.size(), 3u); // floor, fan, lone sliver
}

// Without the thin faces' hulls the audit's re-check finds them uncovered:
// the check above can fail.
TEST(FaceCoverage, TheRecheckFindsThinFacesLeftUncovered) {
  const ThinScene s = thin_scene();
  const auto d = decompose_and_check(s.mesh, {}, kTol);
  ASSERT_TRUE(d);
  Covering without = d->covering;
  without.hulls.erase(
      std::remove_if(
          without.hulls.begin(), without.hulls.end(),
          [&](const CoveringHull& h) { return h.faces.front() == s.fan.front() || h.faces.front() == s.lone; }),
      without.hulls.end());
  ASSERT_EQ(without.hulls.size(), 1u);
  const validate::CheckReport report = validate::check_covering_independently(d->prepared, without);
  EXPECT_EQ(report.faces_uncovered, 11) << report.summary();
}

} // namespace
} // namespace hullcover
