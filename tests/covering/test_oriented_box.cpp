// Boxes along any axes (lib/covering/src/movement/oriented_box.h), what
// the movement proofs halve when the region they search is slanted: the
// box's own geometry against points sampled in it, the clearance's and the
// reach grid's answers for it against the same, and a hull's proof on a
// tilted floor, which takes that path, against its verdicts on the level
// floor (test_movement_kernels.cpp).

#include "movement_scene.h"

#include "movement/movement_validity.h"
#include "movement/oriented_box.h"
#include "movement/reach_grid.h"
#include "movement/scene_clearance.h"
#include "movement/within_slop.h"

#include "hullcover/geometry/planar_hull.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace hullcover::detail::oriented_box_tests {
namespace {

using V = Eigen::Vector3d;

constexpr double kTol = 1e-6;
// Points sampled along each of a box's axes.
constexpr int kSamples = 15;

Eigen::Matrix3d random_rotation(std::mt19937& random) {
  std::normal_distribution<double> normal;
  return Eigen::Quaterniond(normal(random), normal(random), normal(random), normal(random))
      .normalized()
      .toRotationMatrix();
}

OrientedBox random_box(std::mt19937& random, const V& near, double size) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  OrientedBox box;
  box.centre = near + size * V(unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5);
  box.axes = random_rotation(random);
  box.half = 0.5 * size * V(unit(random), unit(random), unit(random));
  return box;
}

// The box's points on a kSamples^3 lattice, corners included.
std::vector<V> samples_of(const OrientedBox& box) {
  std::vector<V> out;
  for (int i = 0; i < kSamples; ++i)
    for (int j = 0; j < kSamples; ++j)
      for (int k = 0; k < kSamples; ++k) {
        const V local = V(i, j, k) * (2.0 / (kSamples - 1)) - V::Ones();
        out.push_back(box.centre + box.axes * local.cwiseProduct(box.half));
      }
  return out;
}

// How far a box point can be from the nearest sample.
double sample_gap(const OrientedBox& box) { return box.half.norm() / (kSamples - 1); }

bool in_box(const OrientedBox& box, const V& p, double slack) {
  const V local = box.axes.transpose() * (p - box.centre);
  return (local.cwiseAbs() - box.half).maxCoeff() <= slack;
}

TEST(OrientedBox, ItsHalvesCoverItAndItsBoundsHoldIt) {
  std::mt19937 random(20261207);
  for (int trial = 0; trial < 200; ++trial) {
    const OrientedBox box = random_box(random, V(3, -2, 5), 2.0);
    const auto [low, high] = box.halves();
    const Aabb bounds = box.bounds();
    for (const V& p : samples_of(box)) {
      EXPECT_TRUE(in_box(low, p, 1e-12) || in_box(high, p, 1e-12)) << trial;
      EXPECT_TRUE((p.array() >= bounds.min.array() - 1e-12).all() && (p.array() <= bounds.max.array() + 1e-12).all());
      EXPECT_LE((p - box.centre).norm(), box.half_diagonal() + 1e-12);
    }
    EXPECT_LT(low.half_diagonal(), box.half_diagonal());
  }
}

// The first box of a search holds its whole region: a piece's column (the
// points within r - E of the piece's plane whose foot lies in it) for any
// axes along the piece's normal, and a side's ball-swept segment for any
// axes along the side; axes of no length, or not orthonormal, give the
// scene's. Points of each region at random, with no slack beyond the
// box's own padding.
TEST(OrientedBox, ABoxAlongARegionHoldsEveryPointOfIt) {
  std::mt19937 random(17);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal;
  const double reach = 0.28, pad = 1e-7;
  const auto turned_about_first = [&](Eigen::Matrix3d axes) {
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(2.0 * M_PI * unit(random), axes.col(0)).toRotationMatrix();
    axes.col(1) = turn * axes.col(1);
    axes.col(2) = turn * axes.col(2);
    return axes;
  };
  for (int trial = 0; trial < 300; ++trial) {
    const V centre = 1000.0 * V(normal(random), normal(random), normal(random));
    const V n = V(normal(random), normal(random), normal(random)).normalized();
    const Eigen::Matrix3d axes = turned_about_first(axes_about(n));
    // A piece: corners round its centre in its plane.
    std::vector<V> corners;
    const int count = 3 + trial % 5;
    for (int k = 0; k < count; ++k) {
      const double angle = 2.0 * M_PI * (k + 0.5 * unit(random)) / count;
      corners.push_back(centre +
                        (0.2 + 2.0 * unit(random)) * (std::cos(angle) * axes.col(1) + std::sin(angle) * axes.col(2)));
    }
    const OrientedBox column = box_along(axes, corners, V(1, 0, 0), reach, pad);
    for (int i = 0; i < 200; ++i) {
      V foot = V::Zero();
      double total = 0.0;
      for (const V& c : corners) {
        const double w = unit(random);
        foot += w * c;
        total += w;
      }
      const V p = foot / total + (2.0 * unit(random) - 1.0) * reach * n;
      ASSERT_TRUE(in_box(column, p, 0.0)) << trial;
    }
    // A side: a segment and the points within reach of it.
    const V a = corners[0], b = corners[1];
    const OrientedBox around = box_along(turned_about_first(axes_about(b - a)), {a, b}, V::Ones(), reach, pad);
    for (int i = 0; i < 200; ++i) {
      const V off = V(normal(random), normal(random), normal(random)).normalized() * reach * unit(random);
      ASSERT_TRUE(in_box(around, a + unit(random) * (b - a) + off, 0.0)) << trial;
    }
  }
  EXPECT_EQ(axes_about(V::Zero()), Eigen::Matrix3d::Identity());
  EXPECT_EQ(box_along(Eigen::Matrix3d::Zero(), {V(1, 2, 3)}, V::Ones(), 1.0, 0.0).axes, Eigen::Matrix3d::Identity());
  EXPECT_EQ(box_along(2.0 * Eigen::Matrix3d::Identity(), {V(1, 2, 3)}, V::Ones(), 1.0, 0.0).axes,
            Eigen::Matrix3d::Identity());
}

// A cube the box is parted from holds none of the box's points; a cube it
// is not parted from comes within the sampling's gap of one (the 15 axes
// decide two boxes exactly). Both answers occur.
TEST(OrientedBox, IsPartedFromACubeExactlyWhenTheyShareNoPoint) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int parted = 0, meeting = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const OrientedBox box = random_box(random, V::Zero(), 2.0);
    const V cube = 2.0 * V(unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5);
    const double half_side = 0.1 + 0.4 * unit(random);
    const auto distance_to_cube = [&](const V& p) {
      return ((p - cube).cwiseAbs() - V::Constant(half_side)).cwiseMax(0.0).norm();
    };
    double nearest = std::numeric_limits<double>::infinity();
    for (const V& p : samples_of(box)) nearest = std::min(nearest, distance_to_cube(p));
    if (box.apart_from_cube(cube, half_side)) {
      ++parted;
      EXPECT_GT(nearest, 0.0) << trial;
    } else {
      ++meeting;
      EXPECT_LE(nearest, sample_gap(box) + 1e-12) << trial;
    }
  }
  EXPECT_GT(parted, 50);
  EXPECT_GT(meeting, 50);
}

// Where box_within says every point of a box lies nearer than the limit
// to a triangle, every sampled point does; along the scene's axes it
// answers as the Aabb test does. Both the plane's shortcut (a box over the
// triangle's inside) and the corners (a box over its edge) say yes.
TEST(SceneClearance, AnOrientedBoxIsWithinATriangleOnlyWhenEveryPointIs) {
  Mesh triangle;
  triangle.positions = {V(0, 0, 0), V(4, 0, 0), V(0, 0, 4)};
  triangle.triangles = {Eigen::Vector3i(0, 1, 2)};
  const SceneClearance clearance(triangle);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int within = 0, over_an_edge = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const OrientedBox box = random_box(random, V(1.5, 0.2, 1.5), 3.0 * unit(random) + 0.05);
    const double limit = 0.3 + unit(random);
    if (clearance.box_within(box, 0, limit)) {
      ++within;
      bool past_edge = false;
      for (const V& p : samples_of(box)) {
        EXPECT_LT(clearance.to_face(p, 0), limit) << trial;
        past_edge = past_edge || p.x() < 0.0 || p.z() < 0.0 || p.x() + p.z() > 4.0;
      }
      over_an_edge += past_edge;
    }
    OrientedBox along = box;
    along.axes = Eigen::Matrix3d::Identity();
    EXPECT_EQ(clearance.box_within(along, 0, limit), clearance.box_within(along.bounds(), 0, limit)) << trial;
  }
  EXPECT_GT(within, 50);
  EXPECT_GT(over_an_edge, 5);
}

// A box meets a cell that may hold a reachable centre: when a sampled
// point of it lies in one, the grid says so; when the grid says so, some
// such cell comes within the sampling's gap of a sampled point. Tried on
// the boxes where it matters: those whose bounding box meets a reachable
// cell while their centre's cell is not one, inside the grid and over at
// most kMostCellsTestedOneByOne cells. A few of them (5 of 1,000 here)
// are told apart from every reachable cell: the reason for the test cell
// by cell, where a proof's small slanted boxes would otherwise be halved
// to the smallest size beside a reachable cell they do not meet.
TEST(ReachGrid, AnOrientedBoxMeetsAReachableCellExactlyWhenOneOfTheCellsItMeetsIs) {
  const test::MovementLevel level = test::movement_level();
  const SceneClearance clearance(level.mesh);
  const ReachGrid grid = build_reach_grid(level.mesh, clearance, test::level_agent(), {level.spawn}, true, 1).value();
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const V extent = grid.dims.cast<double>() * grid.cell;
  const auto cell_of = [&](const V& p) { return ((p - grid.origin) / grid.cell).array().floor().cast<int>().matrix(); };
  const auto in_grid = [&](const Eigen::Vector3i& c) {
    return (c.array() >= 0).all() && (c.array() < grid.dims.array()).all();
  };
  int tried = 0, reached = 0, parted = 0;
  for (int trial = 0; trial < 200000 && tried < 1000; ++trial) {
    const V near = grid.origin + V(unit(random), unit(random), unit(random)).cwiseProduct(extent);
    const OrientedBox box = random_box(random, near, grid.cell * (0.2 + 0.8 * unit(random)));
    const Aabb bounds = box.bounds();
    const Eigen::Vector3i lo = cell_of(bounds.min), hi = cell_of(bounds.max);
    if (!in_grid(lo) || !in_grid(hi) || (hi - lo + Eigen::Vector3i::Ones()).prod() > kMostCellsTestedOneByOne) continue;
    if (grid.reachable_at(box.centre) || !grid.any_reachable(bounds)) continue;
    ++tried;
    const bool any = grid.any_reachable(box);
    bool sampled = false;
    double nearest = std::numeric_limits<double>::infinity();
    for (const V& p : samples_of(box)) {
      sampled = sampled || grid.reachable_at(p);
      for (int k = lo.z(); k <= hi.z(); ++k)
        for (int j = lo.y(); j <= hi.y(); ++j)
          for (int i = lo.x(); i <= hi.x(); ++i) {
            if (!grid.reachable(i, j, k)) continue;
            const V gap = (p - grid.centre(i, j, k)).cwiseAbs() - V::Constant(0.5 * grid.cell);
            nearest = std::min(nearest, gap.cwiseMax(0.0).norm());
          }
    }
    if (sampled) {
      EXPECT_TRUE(any) << trial;
    }
    if (any) {
      EXPECT_LE(nearest, sample_gap(box) + 1e-12) << trial;
    }
    reached += any;
    parted += !any;
  }
  EXPECT_EQ(tried, 1000);
  EXPECT_GT(reached, 100);
  EXPECT_GT(parted, 0);
}

// The triangles of a closed crate [-1, 1]^3, its top with a pit 0.7 wide
// and 0.3 deep over x, z in [0.1, 0.8] when `pit`, every corner turned by
// `rotation`.
Mesh crate(const Eigen::Matrix3d& rotation, bool pit) {
  Mesh mesh;
  const auto quad = [&](const V& a, const V& b, const V& c, const V& d) {
    const int base = static_cast<int>(mesh.positions.size());
    for (const V& p : {a, b, c, d}) mesh.positions.push_back(rotation * p);
    mesh.triangles.emplace_back(base, base + 1, base + 2);
    mesh.triangles.emplace_back(base, base + 2, base + 3);
  };
  // The top at y = 1 over [x0, x1] by [z0, z1].
  const auto top = [&](double x0, double x1, double z0, double z1) {
    quad(V(x0, 1, z0), V(x0, 1, z1), V(x1, 1, z1), V(x1, 1, z0));
  };
  quad(V(-1, -1, -1), V(1, -1, -1), V(1, -1, 1), V(-1, -1, 1));
  quad(V(-1, -1, -1), V(-1, 1, -1), V(1, 1, -1), V(1, -1, -1));
  quad(V(-1, -1, 1), V(1, -1, 1), V(1, 1, 1), V(-1, 1, 1));
  quad(V(-1, -1, -1), V(-1, -1, 1), V(-1, 1, 1), V(-1, 1, -1));
  quad(V(1, -1, -1), V(1, 1, -1), V(1, 1, 1), V(1, -1, 1));
  if (!pit) {
    top(-1, 1, -1, 1);
    return mesh;
  }
  const double lo = 0.1, hi = 0.8, floor = 0.7;
  top(-1, 1, -1, lo);
  top(-1, 1, hi, 1);
  top(-1, lo, lo, hi);
  top(hi, 1, lo, hi);
  quad(V(lo, floor, lo), V(hi, floor, lo), V(hi, floor, hi), V(lo, floor, hi));
  quad(V(lo, floor, lo), V(lo, 1, lo), V(hi, 1, lo), V(hi, floor, lo));
  quad(V(lo, floor, hi), V(hi, floor, hi), V(hi, 1, hi), V(lo, 1, hi));
  quad(V(lo, floor, lo), V(lo, floor, hi), V(lo, 1, hi), V(lo, 1, lo));
  quad(V(hi, floor, lo), V(hi, 1, lo), V(hi, 1, hi), V(hi, floor, hi));
  return mesh;
}

// A square inside a closed crate, 0.05 under its top (more than the slop:
// no triangle holds it within E), with the whole scene turned: its column
// reaches up through the top into the air, so its proof searches the
// column box by box (the grid clears the crate's inside, the distance to
// the top the air just over it), along the column when the turn slants it.
// It is valid at every turn. Under a top with a pit a flyer sinks into,
// 0.05 from the square, it is refused at every turn (none of the points
// tried over the whole square, near its corners and the middles of its
// sides is in the pit; the proof finds it over a part of the square). The
// same square 0.03 over the top (more than E out) is refused.
TEST(MovementProof, ASquareUnderATiltedCratesTopIsDecidedAsUnderALevelOne) {
  std::mt19937 random(5);
  for (int turn = 0; turn < 6; ++turn) {
    const Eigen::Matrix3d rotation = turn == 0 ? Eigen::Matrix3d::Identity() : random_rotation(random);
    for (const bool pit : {false, true}) {
      const Mesh mesh = crate(rotation, pit);
      const SceneClearance clearance(mesh);
      AgentShape agent;
      agent.radius = 0.3;
      agent.slop = 0.02;
      agent.reach = AgentReach::fly;
      const ReachGrid grid = build_reach_grid(mesh, clearance, agent, {rotation * V(0, 3, 0)}, true, 1).value();
      ASSERT_EQ(grid.reachable_at(rotation * V(0.45, 1.0, 0.45)), pit) << "a flyer sinks into the pit alone";
      const MovementContext context{mesh, clearance, grid, agent, kTol};
      const auto square = [&](double y) {
        std::vector<V> corners;
        for (const V& p : {V(-0.9, y, -0.9), V(0.9, y, -0.9), V(0.9, y, 0.9), V(-0.9, y, 0.9)})
          corners.push_back(rotation * p);
        return corners;
      };
      const auto flat = [&](const std::vector<V>& corners) {
        return flat_polytope(make_flat_polygon(corners, {0, 1, 2, 3}, rotation * V(0, 1, 0), kTol), true);
      };
      std::vector<int> near;
      ASSERT_FALSE(held_within_slop(context, square(0.95), near)) << "held: the square would need no search";
      UncoveredBoundary boundary;
      EXPECT_EQ(check_movement_hull(context, flat(square(0.95)), true, {}, boundary),
                pit ? MovementVerdict::centre_near_boundary : MovementVerdict::valid)
          << "turn " << turn << (pit ? ", pit" : "");
      EXPECT_EQ(check_movement_hull(context, flat(square(1.03)), true, {}, boundary),
                MovementVerdict::centre_near_boundary)
          << turn;
    }
  }
}

} // namespace
} // namespace hullcover::detail::oriented_box_tests
