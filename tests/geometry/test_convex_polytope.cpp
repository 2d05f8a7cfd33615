#include "hullcover/covering/convex_hull_3d.h"
#include "hullcover/geometry/convex_polytope.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <random>

namespace hullcover {
namespace {

std::vector<Eigen::Vector3d> cube_points(const Eigen::Vector3d& offset) {
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < 8; ++i) p.push_back(offset + Eigen::Vector3d(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  p.push_back(offset + Eigen::Vector3d(0.5, 0.5, 0.5)); // interior: not a vertex
  return p;
}

TEST(ConvexHullBuilder, CubeFarFromTheOriginHasSixSquareFacets) {
  ConvexHullBuilder builder;
  const Eigen::Vector3d offset(1e5, -2e5, 5e4);
  const Result<ConvexPolytope> hull = builder.build(cube_points(offset), {0, 1, 2, 3, 4, 5, 6, 7, 8});
  ASSERT_TRUE(hull.ok()) << hull.status().message();
  EXPECT_EQ(hull.value().vertices.size(), 8u);
  EXPECT_EQ(hull.value().facets.size(), 6u);
  EXPECT_NEAR(polytope_volume(hull.value()), 1.0, 1e-6);
  for (int id : hull.value().vertex_ids) EXPECT_NE(id, 8);
  // Facets wind counter-clockwise seen from outside: Newell normal agrees with the plane.
  for (size_t f = 0; f < hull.value().facets.size(); ++f) {
    const auto& facet = hull.value().facets[f];
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for (size_t i = 0; i < facet.size(); ++i)
      n += (hull.value().vertices[facet[i]] - offset)
               .cross(hull.value().vertices[facet[(i + 1) % facet.size()]] - offset);
    EXPECT_GT(n.dot(hull.value().planes[f].normal), 0.0);
  }
}

TEST(ConvexHullBuilder, FlatInputFailsWithAStatusNotAnExit) {
  ConvexHullBuilder builder;
  const Result<ConvexPolytope> hull = builder.build({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}});
  EXPECT_FALSE(hull.ok());
  EXPECT_EQ(hull.status().code(), StatusCode::degenerate_scene);
}

// collision-world turned by 0.7 rad and moved to 1e5: a double-sided wall's
// eight corners lie within 2e-12 of one plane. Qhull builds a sliver of
// them; the builder refuses it as flat, as it refuses exactly coplanar
// points, while a hull a millionth of its size thick is kept.
TEST(ConvexHullBuilder, PointsFlatButForRoundingAreFlat) {
  const std::vector<Eigen::Vector3d> wall = {{100012.08214695222, 100005.7471582244, -99934.850726621211},
                                             {99965.131032148158, 100005.7471582244, -99974.397105070457},
                                             {99965.131032148158, 100013.41627016439, -99974.397105070457},
                                             {100012.08214695222, 100013.41627016439, -99934.850726621211},
                                             {99962.824609436037, 100005.7471582244, -99976.339778121313},
                                             {99962.824609436037, 100013.41627016439, -99976.339778121313},
                                             {100005.73494219754, 100007.50687353345, -99940.196903434495},
                                             {100005.73494219754, 100008.70089570616, -99940.196903434495}};
  ConvexHullBuilder builder;
  const auto sliver = builder.build(wall);
  EXPECT_FALSE(sliver.ok());
  EXPECT_EQ(sliver.status().code(), hullcover::StatusCode::degenerate_scene);
  // Refused by the width test, not by Qhull: Qhull builds it.
  EXPECT_NE(sliver.status().message().find("within rounding of a plane"), std::string::npos)
      << sliver.status().message();
  // The same wall a micrometre thick (its extent is about 60): a solid.
  std::vector<Eigen::Vector3d> slab = wall;
  const Eigen::Vector3d across = (wall[1] - wall[0]).cross(wall[3] - wall[0]).normalized();
  for (const Eigen::Vector3d& p : wall) slab.push_back(p + 1e-6 * across);
  EXPECT_TRUE(builder.build(slab).ok());
}

TEST(SegmentEntersInterior, CountsOnlyDepthBeyondTheTolerance) {
  ConvexHullBuilder builder;
  const Result<ConvexPolytope> hull = builder.build(cube_points(Eigen::Vector3d::Zero()));
  ASSERT_TRUE(hull.ok());
  const auto& planes = hull.value().planes;
  const double tol = 1e-3;
  EXPECT_TRUE(segment_enters_interior(planes, {-1, 0.5, 0.5}, {2, 0.5, 0.5}, tol));        // through
  EXPECT_FALSE(segment_enters_interior(planes, {-1, 0, 0.5}, {2, 0, 0.5}, tol));           // along a face
  EXPECT_FALSE(segment_enters_interior(planes, {-1, 0.0005, 0.5}, {2, 0.0005, 0.5}, tol)); // within tol of it
  EXPECT_TRUE(segment_enters_interior(planes, {-1, 0.01, 0.5}, {2, 0.01, 0.5}, tol));
  EXPECT_FALSE(segment_enters_interior(planes, {-1, 2, 2}, {-0.5, 2, 2}, tol)); // away
  EXPECT_LT(deepest_signed_distance(planes, {0.5, 0.5, 0.5}), -0.4);
}

TEST(ClipPolygon, KeepsTheInnerPart) {
  const Plane x_below_one{{1, 0, 0}, 1.0};
  const std::vector<Eigen::Vector3d> square = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  const auto half = clip_polygon(square, x_below_one, 0.0);
  ASSERT_EQ(half.size(), 4u);
  for (const auto& p : half) EXPECT_LE(p.x(), 1.0 + 1e-12);
  EXPECT_TRUE(clip_polygon(square, {{1, 0, 0}, -1.0}, 0.0).empty());
}

// A regular n-gon about `centre`, turned and stretched in its plane by the
// axes u and v.
std::vector<Eigen::Vector3d> regular_polygon(int n, const Eigen::Vector3d& centre, const Eigen::Vector3d& u,
                                             const Eigen::Vector3d& v) {
  std::vector<Eigen::Vector3d> polygon;
  for (int i = 0; i < n; ++i) {
    const double angle = 2.0 * 3.141592653589793 * i / n;
    polygon.push_back(centre + std::cos(angle) * u + std::sin(angle) * v);
  }
  return polygon;
}

// Random convex polygons (regular n-gons, turned and stretched in their
// plane) cut by random planes, some through a corner exactly.
TEST(SplitPolygon, EachSideIsTheClipBitForBit) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto random_vector = [&] { return Eigen::Vector3d(unit(rng), unit(rng), unit(rng)); };
  std::vector<Eigen::Vector3d> inner, outer;
  int both_sides = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const int n = 3 + trial % 6;
    const Eigen::Vector3d centre = 100.0 * random_vector();
    const Eigen::Vector3d u = random_vector(), v = random_vector();
    const std::vector<Eigen::Vector3d> polygon = regular_polygon(n, centre, u, v);
    const Eigen::Vector3d normal = random_vector().normalized();
    const Eigen::Vector3d through = trial % 3 == 0 ? polygon[trial % n] : centre + 0.7 * random_vector();
    const Plane plane{normal, normal.dot(through)};
    split_polygon(polygon, plane, inner, outer);
    const std::vector<Eigen::Vector3d> kept = clip_polygon(polygon, plane, 0.0);
    const std::vector<Eigen::Vector3d> cut_off = clip_polygon(polygon, plane.flipped(), 0.0);
    ASSERT_EQ(inner.size(), kept.size()) << "trial " << trial;
    ASSERT_EQ(outer.size(), cut_off.size()) << "trial " << trial;
    for (size_t i = 0; i < kept.size(); ++i) EXPECT_TRUE(inner[i] == kept[i]) << "trial " << trial;
    for (size_t i = 0; i < cut_off.size(); ++i) EXPECT_TRUE(outer[i] == cut_off[i]) << "trial " << trial;
    both_sides += !kept.empty() && !cut_off.empty();
  }
  EXPECT_GT(both_sides, 500); // the planes do cut, not only pass by
}

TEST(ClipPolygonInto, ReusesItsOutputAndMatchesClipPolygon) {
  const Plane x_below_one{{1, 0, 0}, 1.0};
  const std::vector<Eigen::Vector3d> square = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  std::vector<Eigen::Vector3d> out = {{9, 9, 9}}; // stale content is cleared
  clip_polygon_into(square, x_below_one, 0.25, out);
  const std::vector<Eigen::Vector3d> expected = clip_polygon(square, x_below_one, 0.25);
  ASSERT_EQ(out.size(), expected.size());
  for (size_t i = 0; i < out.size(); ++i) EXPECT_TRUE(out[i] == expected[i]);
  for (const auto& p : out) EXPECT_LE(p.x(), 0.75 + 1e-12);
  clip_polygon_into({}, x_below_one, 0.0, out);
  EXPECT_TRUE(out.empty());
}

TEST(ClipPolygonInPlace, GivesWhatClipPolygonGivesBitForBit) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto random_vector = [&] { return Eigen::Vector3d(unit(rng), unit(rng), unit(rng)); };
  std::vector<Eigen::Vector3d> spare;
  int untouched = 0, cut = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const int n = 3 + trial % 5;
    const Eigen::Vector3d centre = 100.0 * random_vector();
    const Eigen::Vector3d u = random_vector(), v = random_vector();
    const std::vector<Eigen::Vector3d> polygon = regular_polygon(n, centre, u, v);
    const Eigen::Vector3d normal = random_vector().normalized();
    // Planes through a corner (a corner exactly on it), near the middle,
    // and far off either way (nothing cut, or nothing left).
    const double shift = trial % 4 == 0 ? 0.0 : 3.0 * unit(rng);
    const Eigen::Vector3d through = (trial % 4 == 0 ? polygon[trial % n] : centre) + shift * normal;
    const Plane plane{normal, normal.dot(through)};
    const double inset = trial % 2 == 0 ? 0.0 : 0.1 * unit(rng);
    const std::vector<Eigen::Vector3d> expected = clip_polygon(polygon, plane, inset);
    std::vector<Eigen::Vector3d> clipped = polygon;
    clip_polygon_in_place(clipped, plane, inset, spare);
    ASSERT_EQ(clipped.size(), expected.size()) << "trial " << trial;
    for (size_t i = 0; i < expected.size(); ++i) EXPECT_TRUE(clipped[i] == expected[i]) << "trial " << trial;
    untouched += expected.size() == polygon.size() && std::equal(expected.begin(), expected.end(), polygon.begin());
    cut += !expected.empty() && expected.size() != polygon.size();
  }
  // Both the shortcut (wholly inside) and real cuts were put to the test.
  EXPECT_GT(untouched, 300);
  EXPECT_GT(cut, 300);
}

} // namespace
} // namespace hullcover
