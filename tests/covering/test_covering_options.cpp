// The decomposer's options, on scenes built in code: determinism, caps,
// materials, merge orders, thin walls (the shared scenes: tests/scenes/).

#include "covering_fixture.h"
#include "temp_dir.h"

#include "hullcover/covering/covering_export.h"
#include "hullcover/mesh/mesh_import.h"
#include "hullcover/mesh/scene_builder.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <limits>
#include <sstream>

namespace hullcover {
namespace {

TEST(Decompose, IsDeterministicToTheByte) {
  const Mesh m = demo_building();
  for (MergeOrder order : {MergeOrder::compact, MergeOrder::random}) {
    DecomposeOptions o;
    o.order = order;
    const auto first = test::decompose_and_check(m, o);
    const auto second = test::decompose_and_check(m, o);
    ASSERT_TRUE(first && second);
    EXPECT_EQ(test::covering_obj_bytes(first->covering), test::covering_obj_bytes(second->covering));
  }
}

TEST(Decompose, HullVertexCapIsRespected) {
  Mesh m;
  add_height_field(m, {0, 1, 2, 3, 4, 5, 6, 7, 8}, {0, 1, 2, 3, 4, 5, 6, 7, 8},
                   [](double x, double z) { return -0.05 * ((x - 4) * (x - 4) + (z - 4) * (z - 4)); });
  DecomposeOptions o;
  o.max_hull_vertices = 12;
  const auto d = test::decompose_and_check(m, o);
  ASSERT_TRUE(d);
  for (const CoveringHull& h : d->covering.hulls) EXPECT_LE(h.polytope.vertices.size(), 12u);
  const auto unlimited = test::decompose_and_check(m);
  ASSERT_TRUE(unlimited);
  EXPECT_LT(unlimited->covering.hulls.size(), d->covering.hulls.size());
}

TEST(Decompose, KeepingMaterialsApartGivesOneMaterialPerHull) {
  const Mesh m = demo_building();
  DecomposeOptions o;
  o.keep_materials_apart = true;
  const auto d = test::decompose_and_check(m, o);
  ASSERT_TRUE(d);
  for (const CoveringHull& h : d->covering.hulls)
    for (int f : h.faces) EXPECT_EQ(m.material_ids[f], h.material);
}

TEST(Decompose, RejectsOptionsOutOfRange) {
  Result<PreparedMesh> p = prepare_mesh(demo_building(), std::nullopt);
  ASSERT_TRUE(p.ok());
  DecomposeOptions o;
  o.bar_half_length = -1.0;
  EXPECT_EQ(decompose(p.value(), o).status().code(), StatusCode::invalid_argument);
  o = {};
  o.max_hull_vertices = 3;
  EXPECT_EQ(decompose(p.value(), o).status().code(), StatusCode::invalid_argument);
  for (double bad : {-1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    o = {};
    o.near_merge_distance = bad;
    EXPECT_EQ(decompose(p.value(), o).status().code(), StatusCode::invalid_argument) << bad;
  }
}

// More merge orders keep the best: the covering with the fewest hulls of
// the given order and the seeded random ones, each valid on its own.
TEST(Decompose, OrderTriesKeepTheFewestHulls) {
  const Mesh m = demo_building();
  DecomposeOptions one;
  size_t fewest = SIZE_MAX;
  int best_try = -1;
  for (int attempt = 0; attempt < 4; ++attempt) {
    one.order = attempt == 0 ? MergeOrder::compact : MergeOrder::random;
    one.seed = 7 + static_cast<std::uint64_t>(attempt > 0 ? attempt - 1 : 0);
    const auto d = test::decompose_and_check(m, one);
    ASSERT_TRUE(d);
    if (d->covering.hulls.size() < fewest) {
      fewest = d->covering.hulls.size();
      best_try = attempt;
    }
  }
  DecomposeOptions tries;
  tries.seed = 7;
  tries.order_tries = 4;
  const auto d = test::decompose_and_check(m, tries);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->covering.hulls.size(), fewest);
  EXPECT_EQ(d->covering.statistics.kept_try, best_try);
  EXPECT_EQ(d->covering.statistics.order_tries, 4);
  tries.order_tries = 0;
  const Result<PreparedMesh> p = prepare_mesh(m, std::nullopt);
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(decompose(p.value(), tries).status().code(), StatusCode::invalid_argument);
}

// A double-sided wall: two coincident sheets back to back. A prism behind
// either sheet would fill the other's front space, so both stay flat.
TEST(Decompose, BackToBackSheetsGiveFlatHulls) {
  Mesh m;
  test::add_quad_facing(m, {0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 1});
  test::add_quad_facing(m, {0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, -1});
  const auto d = test::decompose_and_check(m);
  ASSERT_TRUE(d);
  for (const CoveringHull& h : d->covering.hulls) EXPECT_EQ(h.thickness, 0.0);
}

// A thin wall box: the prism behind its front face stops at its back face.
TEST(Decompose, PrismStopsAtTheBackOfAThinWall) {
  Mesh m;
  test::add_quad_facing(m, {0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 1});
  test::add_quad_facing(m, {0, 0, -0.1}, {2, 0, -0.1}, {2, 2, -0.1}, {0, 2, -0.1}, {0, 0, -1});
  DecomposeOptions o;
  o.prism_thickness_cap = 1.0;
  const auto d = test::decompose_and_check(m, o);
  ASSERT_TRUE(d);
  ASSERT_EQ(d->covering.hulls.size(), 2u);
  for (const CoveringHull& h : d->covering.hulls) EXPECT_NEAR(h.thickness, 0.1, 1e-9);
  EXPECT_FALSE(test::point_inside_covering(d->covering, {1, 1, -0.5}, d->tol()));
}

} // namespace
} // namespace hullcover
