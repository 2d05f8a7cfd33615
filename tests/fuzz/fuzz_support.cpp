#include "fuzz_support.h"

#include "hullcover/bvh/hull_world.h"
#include "hullcover/mesh/scene_builder.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace hullcover::fuzz {
namespace {

// The scratch folder of this process: made once (mkdtemp, so two fuzzers
// or two replay tests running side by side never share one), removed when
// the process exits normally. A crashing input leaves it behind in the
// temp folder, with the input in it.
class ScratchFolder {
public:
  ScratchFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "hullcover-fuzz-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot create a scratch folder in " + pattern);
    path_ = pattern;
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::string& path() const { return path_; }

private:
  std::string path_;
};

const std::string& scratch_folder() {
  static const ScratchFolder folder;
  return folder.path();
}

} // namespace

std::string write_scratch_file(const std::string& name, const std::uint8_t* data, std::size_t size) {
  const std::string path = scratch_folder() + "/" + name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out) throw std::runtime_error("cannot write " + path);
  return path;
}

void apply_byte_edits(std::string& bytes, const std::uint8_t* data, std::size_t size) {
  for (std::size_t e = 0; e < size / kEditBytes; ++e) {
    const std::uint8_t* edit = data + kEditBytes * e;
    bytes[(edit[0] | (static_cast<std::size_t>(edit[1]) << 8)) % bytes.size()] = static_cast<char>(edit[2]);
  }
}

void remove_scratch_file(const std::string& path) {
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
}

Mesh small_scene_in_cells() {
  Mesh m;
  const std::vector<double> xs = {0.0, 1.0, 2.0, 3.0, 4.0}, zs = {0.0, 1.0, 2.0, 3.0};
  add_height_field(m, xs, zs, [](double x, double z) { return 0.1 * x * z; });
  add_box(m, {1.0, 0.5, 1.0}, {2.0, 1.5, 2.0});
  add_box(m, {5.0, 0.0, 0.0}, {7.0, 2.0, 3.0}, false);
  return m;
}

void query_hulls(std::vector<bvh::RuntimeHull> hulls) {
  if (hulls.empty()) return;
  // Halves first: min + max can overflow where each is finite.
  const Aabb first = hulls.front().box;
  const Eigen::Vector3d centre = 0.5 * first.min + 0.5 * first.max;
  const double size = first.diagonal();
  Result<std::shared_ptr<const bvh::HullWorld>> built = bvh::HullWorld::build(std::move(hulls));
  if (!built.ok()) return;
  const bvh::HullWorld& world = *built.value();
  // Shapes sized to the hull, so they reach it; a refused shape or pose
  // (non-finite after the arithmetic above) is a Status, which is fine.
  const double radius = size > 0.0 ? 0.25 * size : 1.0;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = centre;

  bvh::OverlapRequest touch;
  touch.shape = bvh::QueryShape::sphere(radius);
  touch.pose = pose;
  bvh::TouchResult touched;
  static_cast<void>(world.touches(touch, touched));

  bvh::ContactRequest contact;
  contact.shape = bvh::QueryShape::capsule(radius, radius);
  contact.pose = pose;
  bvh::ContactResult contacts;
  static_cast<void>(world.contacts(contact, contacts));

  bvh::RayRequest ray;
  ray.origin = centre - Eigen::Vector3d::UnitX() * (2.0 * size);
  ray.direction = Eigen::Vector3d(1.0, 0.25, 0.125);
  bvh::RayResult hit;
  static_cast<void>(world.ray_cast(ray, hit));

  bvh::DistanceRequest distance;
  distance.shape = bvh::QueryShape::box(Eigen::Vector3d::Constant(radius));
  distance.pose.translation() = centre + Eigen::Vector3d::UnitZ() * (2.0 * size);
  bvh::DistanceResult gap;
  static_cast<void>(world.distance(distance, gap));
}

} // namespace hullcover::fuzz
