// The allowances of loss_allowance.h (--max-deviation, --agent-radius): a
// covering may take free space exact mode keeps, only where the allowance
// covers it. Each test checks the covering against the definition directly
// (distances to the mesh's triangles, balls clear of them), not against the
// decomposer's own proofs.

#include "covering_fixture.h"

#include "hullcover/covering/covering.h"
#include "hullcover/geometry/triangle_distance.h"
#include "hullcover/mesh/prepared_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

namespace hullcover {
namespace {

using V = Eigen::Vector3d;

using test::grooved_floor;
using test::kGrooveDepth;

double clearance(const Mesh& m, const V& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3i& t : m.triangles)
    best = std::min(best,
                    (closest_point_on_triangle(p, m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]) - p).norm());
  return best;
}

struct Decomposition {
  PreparedMesh prepared;
  Covering covering;
};

Decomposition decompose_with(const Mesh& m, const DecomposeOptions& options) {
  Result<PreparedMesh> prepared = prepare_mesh(m, std::nullopt);
  EXPECT_TRUE(prepared.ok());
  Result<Covering> covering = decompose(prepared.value(), options);
  EXPECT_TRUE(covering.ok()) << covering.status().message();
  return {std::move(prepared).value(), std::move(covering).value()};
}

// The points of a grid over the groove's free side, from 0.2 below the
// floor to 0.5 above it.
template <typename Visit>
void for_each_grid_point(Visit&& visit) {
  constexpr int kSteps = 40;
  for (int i = 0; i <= kSteps; ++i)
    for (int j = 0; j <= kSteps; ++j) visit(V(0.6 + 1.0 * i / kSteps, -0.2 + 0.7 * j / kSteps, 0.5));
}

TEST(MaxDeviation, SpansAShallowGrooveAndTakesNothingFartherThanAllowed) {
  const Mesh m = grooved_floor();
  const Decomposition exact = decompose_with(m, {});
  DecomposeOptions options;
  options.max_deviation = 2.0 * kGrooveDepth;
  const Decomposition relaxed = decompose_with(m, options);
  const double tol = relaxed.prepared.tolerance.length;
  // The groove's free space is within the allowance: spanning it saves hulls.
  EXPECT_LT(relaxed.covering.hulls.size(), exact.covering.hulls.size());
  EXPECT_TRUE(test::point_inside_covering(relaxed.covering, V(1.1, -0.5 * kGrooveDepth, 0.5), tol));
  EXPECT_FALSE(test::point_inside_covering(exact.covering, V(1.1, -0.5 * kGrooveDepth, 0.5), tol));
  // Nothing in front of the faces farther than the allowance is taken.
  int checked = 0;
  for_each_grid_point([&](const V& p) {
    if (p.y() <= 0.0 || clearance(m, p) <= *options.max_deviation + tol) return;
    ++checked;
    EXPECT_FALSE(test::point_inside_covering(relaxed.covering, p, tol)) << p.transpose();
  });
  EXPECT_GT(checked, 100);
}

TEST(MaxDeviation, TooSmallAnAllowanceLeavesTheGrooveOpen) {
  const Mesh m = grooved_floor();
  DecomposeOptions options;
  options.max_deviation = 0.25 * kGrooveDepth;
  const Decomposition relaxed = decompose_with(m, options);
  const double tol = relaxed.prepared.tolerance.length;
  // The groove's middle lies farther than the allowance from every face.
  const V middle(1.1, -0.5 * kGrooveDepth, 0.5);
  ASSERT_GT(clearance(m, middle), *options.max_deviation + tol);
  EXPECT_FALSE(test::point_inside_covering(relaxed.covering, middle, tol));
}

TEST(AgentRadius, NoBallClearOfTheTrianglesReachesIntoAHull) {
  const Mesh m = grooved_floor();
  DecomposeOptions options;
  options.agent_radius = 0.3; // wider than the groove, which it still sags into
  const Decomposition relaxed = decompose_with(m, options);
  const double r = *options.agent_radius;
  const double tol = relaxed.prepared.tolerance.length;
  // Every ball of radius r above the floor that touches no triangle, on a
  // grid: no point of it lies inside a hull (deeper than tol).
  int balls = 0;
  for_each_grid_point([&](const V& centre) {
    if (centre.y() <= 0.0 || clearance(m, centre) < r) return;
    ++balls;
    constexpr int kAround = 24;
    for (int k = 0; k < kAround; ++k) {
      const double a = 2.0 * EIGEN_PI * k / kAround;
      const V p = centre + (r - tol) * V(std::cos(a), std::sin(a), 0.0);
      EXPECT_FALSE(test::point_inside_covering(relaxed.covering, p, tol)) << centre.transpose();
    }
  });
  EXPECT_GT(balls, 100);
}

} // namespace
} // namespace hullcover
