// How far a sweep's rays run before their first hit (first_hit_bound.h), in the
// sweep's own view and in every view at once: what a re-bake follows a sweep
// to when it asks whether an edit crosses it (scene_change.h).

#include "indexed_scene.h"
#include "validity/mesh_ray.h"
#include "validity/first_hit_bound.h"

#include "hullcover/geometry/tolerances.h"
#include "covering_fixture.h"
#include "hullcover/mesh/scene_builder.h"

#include <gtest/gtest.h>

#include <random>

namespace hullcover {
namespace {

using V = Eigen::Vector3d;

// A floor (facing up, the sweep's face), something just above it that ends
// its rays in one view but not in another, and a roof far above that ends
// them in every view.
enum class Between {
  kSheetWithinTheCoarseStandOff, // a coarse view stands off past it
  kCeilingWithACrack,            // a fine view passes through the crack
};

constexpr double kFine = 0.001;
constexpr double kCoarse = 0.01;
constexpr double kRoofHeight = 5.0;

Mesh floor_and_roof(Between between) {
  Mesh m;
  add_quad(m, V(0, 0, 0), V(1, 0, 0), V(1, 1, 0), V(0, 1, 0));
  if (between == Between::kSheetWithinTheCoarseStandOff) {
    // 3 fine tolerances up: past a fine view's stand-off, inside a coarse one's.
    add_quad(m, V(0, 0, 0.003), V(0, 1, 0.003), V(1, 1, 0.003), V(1, 0, 0.003));
  } else {
    // A crack 4 fine tolerances wide at x = 0.5: closed to a coarse view (each
    // face counts within its tolerance), open to a fine one.
    add_quad(m, V(-1, -1, 1), V(-1, 2, 1), V(0.498, 2, 1), V(0.498, -1, 1));
    add_quad(m, V(0.502, -1, 1), V(0.502, 2, 1), V(2, 2, 1), V(2, -1, 1));
  }
  add_quad(m, V(-1, -1, kRoofHeight), V(-1, 2, kRoofHeight), V(2, 2, kRoofHeight), V(2, -1, kRoofHeight));
  return m;
}

TEST(FirstHitBound, ASweepsRaysAreBoundedInEveryViewNotOnlyInItsOwn) {
  for (const Between between : {Between::kSheetWithinTheCoarseStandOff, Between::kCeilingWithACrack}) {
    SCOPED_TRACE(static_cast<int>(between));
    const auto scene = test::index_scene(floor_and_roof(between), kFine, {1.0, false, ValidityMode::exact, 20.0});
    const double extent = scene->prepared.tolerance.largest_island;
    // The sweep's own view: the fine one where a coarse view passes the sheet,
    // the coarse one where a fine view passes the crack.
    const double own = between == Between::kSheetWithinTheCoarseStandOff ? kFine : kCoarse;
    const SceneIndex own_view(scene->data, own, extent);
    const SceneIndex finest(scene->data, kFine, extent);
    std::vector<V> floor_triangle(3);
    triangle_corners(scene->prepared.mesh, 0, floor_triangle);
    const FreeSpaceSweep sweep = front_space_sweep(floor_triangle, V::UnitZ(), 20.0, own);
    std::vector<int> scratch;

    // In its own view the floor's rays end on what lies just above...
    EXPECT_LT(detail::first_hit_bound(own_view, sweep, scratch), 1.5);
    // ... but some view follows them on to the roof.
    const double bound = detail::first_hit_bound_in_every_view(finest, sweep, kCoarse, scratch);
    EXPECT_GE(bound, kRoofHeight);
    EXPECT_LT(bound, kRoofHeight + 1.0);

    // Every ray, in every view between the two, first meets a face past its
    // stand-off within the bound.
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const double tol : {kFine, 0.004, kCoarse}) {
      const SceneIndex view(scene->data, tol, extent);
      int beyond_own_reach = 0;
      for (int i = 0; i < 400; ++i) {
        double a = unit(random), b = unit(random);
        if (a + b > 1.0) a = 1.0 - a, b = 1.0 - b;
        // Crack rays are rare among random ones: every fourth runs up it.
        V on_floor = floor_triangle[0] + a * (floor_triangle[1] - floor_triangle[0]) +
                     b * (floor_triangle[2] - floor_triangle[0]);
        if (i % 4 == 0) on_floor.x() = 0.5, on_floor.y() = 0.25;
        const V base = on_floor + sweep.start.signed_distance(on_floor) * sweep.direction;
        const auto hit = first_mesh_hit(view, base, sweep.direction, kRayStandOffInTolerances * tol,
                                        scene->prepared.tolerance.diagonal, scratch);
        ASSERT_TRUE(hit) << on_floor.transpose();
        EXPECT_LE(hit->t, bound) << "view " << tol << ", ray from " << on_floor.transpose();
        beyond_own_reach += hit->t > 1.5;
      }
      // The views that pass what lies above do reach the roof.
      const bool passes = between == Between::kSheetWithinTheCoarseStandOff ? tol > 0.0015 : tol < 0.002;
      EXPECT_EQ(beyond_own_reach > 0, passes) << "view " << tol;
    }
  }
}

// A floor under the sharp tip (5.7 degrees) of a triangle, a roof far
// above: the tip's edges pushed out by tol reach 20 tol past it, beyond its
// box grown by tol, where rays do not meet it (mesh_ray.h). The floor's rays
// just past the tip run on to the roof, and every bound must say so.
TEST(FirstHitBound, RaysPastASharpCornerAreNotEndedByIt) {
  Mesh m;
  test::add_triangle(m, V(-0.015, 0, 0), V(0.5, -0.02, 0), V(0.5, 0.02, 0));
  test::add_triangle(m, V(0, 0, 1), V(1, 0.05, 1), V(1, -0.05, 1));
  add_quad(m, V(-1, -1, kRoofHeight), V(-1, 2, kRoofHeight), V(2, 2, kRoofHeight), V(2, -1, kRoofHeight));
  const auto scene = test::index_scene(m, kFine, {1.0, false, ValidityMode::exact, 20.0});
  const double extent = scene->prepared.tolerance.largest_island;
  std::vector<V> floor_triangle(3);
  triangle_corners(scene->prepared.mesh, 0, floor_triangle);
  const SceneIndex finest(scene->data, kFine, extent);
  std::vector<int> scratch;
  int past_the_tip = 0;
  for (const double tol : {kFine, 0.004, kCoarse}) {
    const SceneIndex view(scene->data, tol, extent);
    const FreeSpaceSweep sweep = front_space_sweep(floor_triangle, V::UnitZ(), 20.0, tol);
    const double own = detail::first_hit_bound(view, sweep, scratch);
    const double every = detail::first_hit_bound_in_every_view(finest, sweep, kCoarse, scratch);
    for (double x = -0.0149; x < 0.05; x += 0.0005) {
      const V on_floor(x, 0.0, 0.0);
      const V base = on_floor + sweep.start.signed_distance(on_floor) * sweep.direction;
      const auto hit = first_mesh_hit(view, base, sweep.direction, kRayStandOffInTolerances * tol,
                                      scene->prepared.tolerance.diagonal, scratch);
      ASSERT_TRUE(hit) << x;
      EXPECT_LE(hit->t, own) << "view " << tol << ", ray from x = " << x;
      EXPECT_LE(hit->t, every) << "view " << tol << ", ray from x = " << x;
      past_the_tip += hit->t > 2.0;
    }
  }
  EXPECT_GT(past_the_tip, 0);
}

} // namespace
} // namespace hullcover
