// A program using the runtime, built twice by the tests (tests/CMakeLists.txt):
// with the library's own flags, when it must link and answer right, and
// with AVX, which lays Eigen's fixed-size types out to 32 bytes where the
// library's SSE2 build lays them to 16, when it must fail to link, naming
// the alignment it was built with (query_shape.h), instead of handing the
// library its requests at the wrong offsets.

#include "box_hulls.h"
#include "hullcover/bvh/hull_world.h"

#include <cstdio>

int main() {
  using hullcover::bvh::HullWorld;
  std::vector<hullcover::bvh::RuntimeHull> hulls;
  hulls.push_back(hullcover::test::box_hull(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1)));
  const auto world = HullWorld::build(std::move(hulls));
  if (!world.ok()) return 1;
  // A sphere of radius 0.5 centred 0.4 above the box's top touches it; one
  // centred 0.6 above does not.
  hullcover::bvh::TouchResult near, far;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(0.5, 0.5, 1.4);
  const hullcover::bvh::QueryShape sphere = hullcover::bvh::QueryShape::sphere(0.5);
  if (!world.value()->touches({sphere, pose}, near).ok()) return 1;
  pose.translation().z() = 1.6;
  if (!world.value()->touches({sphere, pose}, far).ok()) return 1;
  std::printf("touching at 0.4 above: %d, at 0.6 above: %d\n", near.touching ? 1 : 0, far.touching ? 1 : 0);
  return near.touching && !far.touching ? 0 : 1;
}
