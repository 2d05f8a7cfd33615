// The enclosure test (validate/src/enclosed_space.h): a point is enclosed
// when it lies on no face's open front ray. The columns are found through a
// tree of boxes cut at the mesh's bounding box; these scenes put the point
// where a box cut too short, or not grown by tol, would miss the column.

#include "covering_fixture.h"
#include "enclosed_space.h"

#include "hullcover/bvh/triangle_world.h"
#include "hullcover/mesh/prepared_mesh.h"

#include <gtest/gtest.h>

#include <memory>

namespace hullcover::validate::probe {
namespace {

using V = Eigen::Vector3d;

constexpr double kTolerance = 1e-3; // scene units: stated, not derived, so the offsets below are exact multiples

struct Judge {
  PreparedMesh prepared;
  std::shared_ptr<const bvh::TriangleWorld> triangles;
  std::unique_ptr<EnclosedSpace> enclosed;
};

Judge judge_of(const Mesh& mesh) {
  Judge j;
  Result<PreparedMesh> prepared = prepare_mesh(mesh, kTolerance);
  EXPECT_TRUE(prepared.ok()) << prepared.status().message();
  j.prepared = std::move(prepared).value();
  Result<std::shared_ptr<const bvh::TriangleWorld>> triangles =
      bvh::TriangleWorld::build(j.prepared.mesh, kTolerance, j.prepared.connectivity.zero_area);
  EXPECT_TRUE(triangles.ok()) << triangles.status().message();
  j.triangles = triangles.value();
  j.enclosed = std::make_unique<EnclosedSpace>(j.prepared, *j.triangles);
  return j;
}

// A small face sloping at 45 degrees near the origin (front along
// (1, 0, 1)/sqrt 2) and, 120 units away, a face looking away from it that
// stretches the mesh's box (to y = -10, so that points beside the column's
// y = -1 side lie inside it): the slope's column crosses the whole box
// diagonally, open all the way (nothing ahead of it).
Mesh slope_and_far_marker() {
  Mesh m;
  test::add_triangle(m, V(-1, -1, 1), V(1, -1, -1), V(0, 1, 0));              // front (1, 0, 1)/sqrt 2
  test::add_triangle(m, V(120, -10, 110), V(120, -9, 110), V(120, -10, 112)); // front +x, off the column
  return m;
}

TEST(EnclosedSpace, APointFarAlongASlopedFacesOpenColumnIsFree) {
  const Judge j = judge_of(slope_and_far_marker());
  const V n = V(1, 0, 1).normalized();
  const V centroid = V(0, -1.0 / 3.0, 0);
  // 80 units out, far beyond the face's own box: a column box not swept to
  // the edge of the mesh's box would not reach it.
  for (double height : {0.5, 10.0, 80.0, 150.0})
    EXPECT_FALSE(j.enclosed->holds(centroid + height * n, kTolerance)) << "height " << height;
}

TEST(EnclosedSpace, APointWithinTolBesideAnOpenColumnIsFreeAndBeyondItIsNot) {
  const Judge j = judge_of(slope_and_far_marker());
  const V n = V(1, 0, 1).normalized();
  // The face's edge from (-1,-1,1) to (1,-1,-1) bounds its column at y = -1.
  const V on_edge = V(0, -1, 0) + 80.0 * n;
  EXPECT_FALSE(j.enclosed->holds(on_edge - V(0, 0.5 * kTolerance, 0), kTolerance));
  EXPECT_TRUE(j.enclosed->holds(on_edge - V(0, 3.0 * kTolerance, 0), kTolerance));
  EXPECT_TRUE(j.enclosed->holds(on_edge - V(0, 5.0, 0), kTolerance));
}

// A floor looking up under a one-sided table top that also looks up (its
// back faces the floor), with a far marker so the box reaches above it.
Mesh floor_under_one_sided_top() {
  Mesh m;
  test::add_quad_facing(m, V(0, 0, 0), V(10, 0, 0), V(10, 10, 0), V(0, 10, 0), V(0, 0, 1)); // floor
  test::add_quad_facing(m, V(2, 2, 2), V(8, 2, 2), V(8, 8, 2), V(2, 8, 2), V(0, 0, 1));     // table top
  test::add_triangle(m, V(50, 50, 20), V(51, 50, 20), V(50, 51, 20));                       // marker, up
  return m;
}

TEST(EnclosedSpace, UnderAOneSidedTopIsEnclosedBesideItAndAboveItIsFree) {
  const Judge j = judge_of(floor_under_one_sided_top());
  EXPECT_TRUE(j.enclosed->holds(V(5, 5, 1), kTolerance));   // the floor's ray ends on the top's back
  EXPECT_FALSE(j.enclosed->holds(V(1, 5, 1), kTolerance));  // beside the top: the floor's ray escapes
  EXPECT_FALSE(j.enclosed->holds(V(5, 5, 3), kTolerance));  // above: the top's own ray escapes
  EXPECT_FALSE(j.enclosed->holds(V(5, 5, 30), kTolerance)); // above the mesh's box: every column is tried
  EXPECT_TRUE(j.enclosed->holds(V(5, 5, -1), kTolerance));  // below the floor: behind every face
}

} // namespace
} // namespace hullcover::validate::probe
