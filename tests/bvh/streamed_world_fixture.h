#pragma once
// A world of generated hulls in a grid of sections, written to a runtime
// file and read back, and the answers a streamed world must give: those of
// a HullWorld built from the hulls it has loaded, their indices mapped to
// the file's. Shared by test_streamed_world.cpp and
// test_streamed_world_threads.cpp, which link the runtime alone (no
// decomposer) so that the ThreadSanitizer build (preset tsan) needs little.

#include "hullcover/bvh/hull_world.h"
#include "hullcover/bvh/runtime_file.h"
#include "hullcover/bvh/streamed_world.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace hullcover::bvh::test {

/// The section grid: kCells x kCells cells of kCellSize (scene units) in x
/// and z; a hull belongs to the cell holding its box's centre, and many
/// hulls reach over the border into the next.
inline constexpr int kCells = 4;
inline constexpr double kCellSize = 10.0;

/// A world written with sections and read back as a game server would.
struct SectionedWorld {
  std::string path;                      ///< the .hcw, in a fresh temporary folder
  std::vector<RuntimeHull> hulls;        ///< read_runtime_file's, global index order
  std::vector<SectionHulls> sections;    ///< read_runtime_section's, for every id in the table
  std::shared_ptr<const HullWorld> full; ///< built from the whole file
};

/// Boxes (turned), tetrahedra and flat triangles at seeded random places.
SectionedWorld make_sectioned_world(std::uint32_t seed, int hull_count);

/// Removes the temporary folder of a world.
void remove_sectioned_world(const SectionedWorld& world);

/// The answers to one pose of every query kind.
struct Answers {
  OverlapResult overlap;
  ContactResult contacts;
  RayResult ray;
  DistanceResult distance;
  SweepResult sweep;
  bool touching = false;
  int touch_hull = -1;
  bool blocked = false; ///< the line of sight (ray_blocked) of the pose's ray
};

/// A seeded pose: a sphere, capsule, box or convex shape, a ray and a sweep,
/// half of them near a section border.
struct Pose {
  QueryShape shape;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d end = Eigen::Isometry3d::Identity();
  RayRequest ray;
};
std::vector<Pose> seeded_poses(std::uint32_t seed, int count);

/// The sweep's touch distance (scene units).
inline constexpr double kTouch = 1e-3;

/// Every query of `pose` on a world (HullWorld or StreamedWorld); the
/// indices of a HullWorld's answers go through `global` when given.
template <typename World>
Answers ask(const World& world, const Pose& p, const std::vector<int>* global = nullptr) {
  Answers a;
  const auto name = [&](int& h) {
    if (global && h >= 0) h = (*global)[h];
  };
  EXPECT_TRUE(world.overlap({p.shape, p.pose}, a.overlap).ok());
  for (int& h : a.overlap.hulls) name(h);
  EXPECT_TRUE(world.contacts({p.shape, p.pose, 6}, a.contacts).ok());
  for (Contact& c : a.contacts.contacts) name(c.hull);
  EXPECT_TRUE(world.ray_cast(p.ray, a.ray).ok());
  name(a.ray.first.hull);
  RayResult blocked; // its own query: on its own snapshot of a world being loaded
  EXPECT_TRUE(world.ray_blocked(p.ray, blocked).ok());
  a.blocked = blocked.hit;
  EXPECT_TRUE(world.distance({p.shape, p.pose}, a.distance).ok());
  name(a.distance.hull);
  SweepRequest sweep{p.shape, p.pose, p.end, 200};
  EXPECT_TRUE(world.sweep(sweep, a.sweep, kTouch).ok());
  name(a.sweep.hull);
  TouchResult touch;
  EXPECT_TRUE(world.touches({p.shape, p.pose}, touch).ok());
  a.touching = touch.touching;
  a.touch_hull = touch.hull;
  name(a.touch_hull);
  return a;
}

/// Whether two answers agree exactly: same hulls, same order, same doubles
/// (the touching hull only has to be one the overlap names), and in each
/// the line of sight is blocked exactly when the ray hits (the queries of
/// one world that does not change). `why` says where they differ first.
bool same_answers(const Answers& x, const Answers& y, std::string* why = nullptr);

/// Whether each query's answer in `a` (each asked on its own, so on its own
/// snapshot of a streamed world) is exactly that query's answer in `x` or
/// in `y`.
bool each_query_as_one_of(const Answers& a, const Answers& x, const Answers& y);

/// Whether a hull of `section` appears anywhere in the answers.
bool names_any_of(const Answers& a, const SectionHulls& section);

} // namespace hullcover::bvh::test
