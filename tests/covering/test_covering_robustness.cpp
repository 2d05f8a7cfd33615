// Hard inputs for the decomposer (docs/design.md, "Files
// from anyone"): far from the origin, near-coplanar faces, slivers and
// zero-area faces, duplicate vertices, T-junctions, flipped and non-manifold
// faces, very thin slabs. Each must give valid hulls (independent re-check),
// finite coordinates and no crash.

#include "covering_fixture.h"

#include "hullcover/mesh/scene_builder.h"

#include <gtest/gtest.h>

#include <random>

namespace hullcover {
namespace {

using test::add_quad_facing;
using test::decompose_and_check;
using V = Eigen::Vector3d;

void expect_finite(const Covering& covering) {
  for (const CoveringHull& h : covering.hulls) {
    for (const V& v : h.polytope.vertices) ASSERT_TRUE(v.allFinite());
    for (const Plane& p : h.polytope.planes) ASSERT_TRUE(p.normal.allFinite() && std::isfinite(p.offset));
  }
}

Mesh translated(Mesh m, const V& offset) {
  for (V& p : m.positions) p += offset;
  return m;
}

TEST(Robustness, FarFromTheOriginGivesTheSameHulls) {
  const auto here = decompose_and_check(demo_building());
  const auto far = decompose_and_check(translated(demo_building(), V(1e5, -1e5, 1e5)));
  ASSERT_TRUE(here && far);
  expect_finite(far->covering);
  EXPECT_EQ(far->covering.hulls.size(), here->covering.hulls.size());
}

TEST(Robustness, NearCoplanarFacesJitteredWithinTheTolerance) {
  Mesh m;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-2e-6, 2e-6); // well under the tolerance (1e-5 x ~11)
  add_height_field(m, {0, 1, 2, 3, 4, 5, 6, 7, 8}, {0, 1, 2, 3, 4, 5, 6, 7, 8},
                   [&](double, double) { return jitter(rng); });
  const auto d = decompose_and_check(m);
  ASSERT_TRUE(d);
  expect_finite(d->covering);
  EXPECT_EQ(d->covering.hulls.size(), 1u); // a flat floor, however it drifts within tol
}

TEST(Robustness, SliversZeroAreaFacesAndDuplicateVertices) {
  Mesh m;
  add_box(m, V(0, 0, 0), V(1, 1, 1));
  // A sliver and a collapsed triangle along the box's top edge, and a
  // duplicate of every top corner.
  const int base = static_cast<int>(m.positions.size());
  m.positions.push_back(V(0, 1, 0));
  m.positions.push_back(V(1, 1, 0));
  m.positions.push_back(V(0.5, 1 + 1e-9, 0));
  m.triangles.emplace_back(base, base + 1, base + 2);
  m.triangles.emplace_back(base, base, base + 1);
  m.material_ids.insert(m.material_ids.end(), {0, 0});
  const auto d = decompose_and_check(m);
  ASSERT_TRUE(d);
  expect_finite(d->covering);
  EXPECT_EQ(d->covering.statistics.zero_area_faces_skipped, 2);
}

TEST(Robustness, TJunctionsFlippedAndNonManifoldFaces) {
  Mesh m;
  // A floor of two quads, the right one split in two, so the left quad's
  // edge has a T-junction.
  add_quad_facing(m, V(0, 0, 0), V(0, 0, 2), V(1, 0, 2), V(1, 0, 0), V(0, 1, 0));
  add_quad_facing(m, V(1, 0, 0), V(1, 0, 1), V(2, 0, 1), V(2, 0, 0), V(0, 1, 0));
  add_quad_facing(m, V(1, 0, 1), V(1, 0, 2), V(2, 0, 2), V(2, 0, 1), V(0, 1, 0));
  // A fin standing on the floor (non-manifold with the floor's edge x = 1
  // after welding) and a flipped face beside it.
  add_quad_facing(m, V(1, 0, 0), V(1, 0, 1), V(1, 1, 1), V(1, 1, 0), V(1, 0, 0));
  add_quad_facing(m, V(2, 0, 0), V(3, 0, 0), V(3, 0, 1), V(2, 0, 1), V(0, -1, 0));
  const auto d = decompose_and_check(m);
  ASSERT_TRUE(d);
  expect_finite(d->covering);
}

TEST(Robustness, VeryThinSlabKeepsItsFacesApart) {
  for (double thickness : {3e-5, 1e-4, 1e-2}) {
    Mesh m;
    add_box(m, V(0, 0, 0), V(2, thickness, 2));
    const auto d = decompose_and_check(m, {}, 1e-6);
    ASSERT_TRUE(d) << thickness;
    expect_finite(d->covering);
    EXPECT_EQ(d->covering.hulls.size(), 1u) << thickness; // a closed box, however thin
  }
}

TEST(Robustness, TwoSheetsCloserThanTheTolerance) {
  // Two parallel floors 1e-7 apart (below tol): they must not swallow each
  // other whatever the decomposer makes of them.
  Mesh m;
  add_quad_facing(m, V(0, 0, 0), V(0, 0, 1), V(1, 0, 1), V(1, 0, 0), V(0, 1, 0));
  add_quad_facing(m, V(0, 1e-7, 0), V(0, 1e-7, 1), V(1, 1e-7, 1), V(1, 1e-7, 0), V(0, 1, 0));
  const auto d = decompose_and_check(m);
  ASSERT_TRUE(d);
  expect_finite(d->covering);
}

} // namespace
} // namespace hullcover
