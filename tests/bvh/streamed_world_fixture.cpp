#include "streamed_world_fixture.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace hullcover::bvh::test {
namespace {

Eigen::Matrix3d random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
  return q.normalized().toRotationMatrix();
}

// Mostly within the grid; half the time on a border in x or z.
Eigen::Vector3d place_in_grid(std::mt19937& rng) {
  std::uniform_real_distribution<double> across(0.0, kCells * kCellSize), up(0.0, 6.0), near(-1.5, 1.5);
  std::uniform_int_distribution<int> border(1, kCells - 1), coin(0, 3);
  Eigen::Vector3d p(across(rng), up(rng), across(rng));
  const int c = coin(rng);
  if (c == 1) p.x() = border(rng) * kCellSize + near(rng);
  if (c == 2) p.z() = border(rng) * kCellSize + near(rng);
  return p;
}

std::uint32_t cell_of(const RuntimeHull& h) {
  const Eigen::Vector3d c = 0.5 * (h.box.min + h.box.max);
  const auto index = [](double x) { return std::clamp(static_cast<int>(std::floor(x / kCellSize)), 0, kCells - 1); };
  return static_cast<std::uint32_t>(100 + index(c.x()) * kCells + index(c.z())); // ids need not start at 0
}

} // namespace

SectionedWorld make_sectioned_world(std::uint32_t seed, int hull_count) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> size(0.2, 2.5), corner(-2.0, 2.0);
  std::vector<RuntimeHull> hulls;
  while (static_cast<int>(hulls.size()) < hull_count) {
    const Eigen::Vector3d at = place_in_grid(rng);
    const int kind = static_cast<int>(hulls.size() % 3);
    if (kind == 0) {
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      pose.linear() = random_rotation(rng);
      pose.translation() = at;
      hulls.push_back(placed_box(pose, Eigen::Vector3d(size(rng), size(rng), size(rng))));
    } else if (kind == 1) {
      QueryShape tetra;
      tetra.kind = ShapeKind::convex;
      for (int k = 0; k < 4; ++k) tetra.points.emplace_back(corner(rng), corner(rng), corner(rng));
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      pose.translation() = at;
      if (std::optional<RuntimeHull> h = placed_convex(tetra, pose)) hulls.push_back(std::move(*h));
    } else {
      const Eigen::Vector3d a = at, b = at + Eigen::Vector3d(corner(rng), corner(rng), corner(rng)),
                            c = at + Eigen::Vector3d(corner(rng), corner(rng), corner(rng));
      if ((b - a).cross(c - a).norm() > 0.1) hulls.push_back(flat_triangle_hull(a, b, c));
    }
  }
  std::vector<std::uint32_t> section_of_hull;
  for (const RuntimeHull& h : hulls) section_of_hull.push_back(cell_of(h));

  SectionedWorld world;
  std::string folder = (std::filesystem::temp_directory_path() / "hullcover-streamed-XXXXXX").string();
  EXPECT_NE(mkdtemp(folder.data()), nullptr);
  world.path = folder + "/world.hcw";
  EXPECT_TRUE(write_runtime_file(hulls, world.path, &section_of_hull).ok());
  Result<std::vector<RuntimeHull>> read = read_runtime_file(world.path);
  EXPECT_TRUE(read.ok()) << read.status().message();
  world.hulls = std::move(read).value();
  world.full = HullWorld::build(world.hulls).value();
  Result<std::vector<RuntimeSection>> table = read_runtime_sections(world.path);
  EXPECT_TRUE(table.ok()) << table.status().message();
  for (const RuntimeSection& s : table.value()) {
    Result<SectionHulls> section = read_runtime_section(world.path, s.id);
    EXPECT_TRUE(section.ok()) << section.status().message();
    world.sections.push_back(std::move(section).value());
  }
  return world;
}

void remove_sectioned_world(const SectionedWorld& world) {
  std::error_code ignored;
  std::filesystem::remove_all(std::filesystem::path(world.path).parent_path(), ignored);
}

std::vector<Pose> seeded_poses(std::uint32_t seed, int count) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> radius(0.1, 1.5), half(0.1, 1.5), step(-6.0, 6.0), dir(-1.0, 1.0),
      corner(-1.0, 1.0);
  std::vector<Pose> poses;
  for (int i = 0; i < count; ++i) {
    Pose p;
    switch (i % 4) {
      case 0: p.shape = QueryShape::sphere(radius(rng)); break;
      case 1: p.shape = QueryShape::capsule(radius(rng), half(rng)); break;
      case 2: p.shape = QueryShape::box(Eigen::Vector3d(half(rng), half(rng), half(rng))); break;
      default:
        p.shape.kind = ShapeKind::convex;
        for (int k = 0; k < 5; ++k) p.shape.points.emplace_back(corner(rng), corner(rng), corner(rng));
    }
    p.pose.linear() = random_rotation(rng);
    p.pose.translation() = place_in_grid(rng);
    p.end.linear() = i % 8 < 4 ? p.pose.linear() : random_rotation(rng); // half the sweeps turn
    p.end.translation() = p.pose.translation() + Eigen::Vector3d(step(rng), step(rng) / 4, step(rng));
    // Rays along the ground, many crossing several cells.
    p.ray.origin = place_in_grid(rng);
    p.ray.direction = Eigen::Vector3d(dir(rng), dir(rng) / 4, dir(rng));
    if (p.ray.direction.norm() == 0.0) p.ray.direction = Eigen::Vector3d::UnitX();
    p.ray.max_distance = i % 2 ? 1e30 : 25.0;
    poses.push_back(std::move(p));
  }
  return poses;
}

namespace {
// One query kind's answers compared exactly; nullptr when they agree, else
// what differs.
const char* differs(const Answers& x, const Answers& y, int kind) {
  switch (kind) {
    case 0: return x.overlap.hulls != y.overlap.hulls ? "overlaps" : nullptr;
    case 1:
      if (x.contacts.contacts.size() != y.contacts.contacts.size()) return "contact counts";
      for (size_t k = 0; k < x.contacts.contacts.size(); ++k) {
        const Contact &a = x.contacts.contacts[k], &b = y.contacts.contacts[k];
        if (a.hull != b.hull || a.depth != b.depth || a.normal != b.normal || a.point != b.point) return "contacts";
      }
      return nullptr;
    case 2:
      if (x.ray.hit != y.ray.hit) return "ray hits";
      return x.ray.hit && (x.ray.first.hull != y.ray.first.hull || x.ray.first.t != y.ray.first.t ||
                           x.ray.first.point != y.ray.first.point || x.ray.first.normal != y.ray.first.normal)
                 ? "ray hit details"
                 : nullptr;
    case 3: {
      const DistanceResult &d = x.distance, &e = y.distance;
      return d.touching != e.touching || d.distance != e.distance || d.hull != e.hull || d.on_world != e.on_world ||
                     d.on_shape != e.on_shape
                 ? "distances"
                 : nullptr;
    }
    case 4:
      return x.sweep.hit != y.sweep.hit || x.sweep.fraction != y.sweep.fraction || x.sweep.hull != y.sweep.hull ||
                     x.sweep.normal != y.sweep.normal
                 ? "sweeps"
                 : nullptr;
    case 5: return x.touching != y.touching ? "yes/no touches" : nullptr;
    default: return x.blocked != y.blocked ? "lines of sight" : nullptr;
  }
}
constexpr int kQueryKinds = 7;

bool touch_hull_overlaps(const Answers& a, const Answers& overlap) {
  return !a.touching || std::binary_search(overlap.overlap.hulls.begin(), overlap.overlap.hulls.end(), a.touch_hull);
}
} // namespace

bool same_answers(const Answers& x, const Answers& y, std::string* why) {
  for (int kind = 0; kind < kQueryKinds; ++kind)
    if (const char* what = differs(x, y, kind)) {
      if (why) *why = std::string(what) + " differ";
      return false;
    }
  if (!touch_hull_overlaps(x, x) || !touch_hull_overlaps(y, y)) {
    if (why) *why = "a touching hull is not in the overlap";
    return false;
  }
  if (x.blocked != x.ray.hit || y.blocked != y.ray.hit) {
    if (why) *why = "a line of sight is not blocked exactly when the ray hits";
    return false;
  }
  return true;
}

bool each_query_as_one_of(const Answers& a, const Answers& x, const Answers& y) {
  for (int kind = 0; kind < kQueryKinds; ++kind)
    if (differs(a, x, kind) && differs(a, y, kind)) return false;
  return touch_hull_overlaps(a, x) || touch_hull_overlaps(a, y);
}

bool names_any_of(const Answers& a, const SectionHulls& section) {
  const auto in = [&](int h) { return std::binary_search(section.indices.begin(), section.indices.end(), h); };
  for (int h : a.overlap.hulls)
    if (in(h)) return true;
  for (const Contact& c : a.contacts.contacts)
    if (in(c.hull)) return true;
  return (a.ray.hit && in(a.ray.first.hull)) || in(a.distance.hull) || in(a.sweep.hull) || in(a.touch_hull);
}

} // namespace hullcover::bvh::test
