#include "hullcover/bvh/streamed_world.h"

#include "hull_tree.h"
#include "packed_planes.h"
#include "query_guard.h"
#include "collected_queries.h"

#include <map>
#include <unordered_set>

namespace hullcover::bvh {
namespace detail {

/// One loaded section: its hulls, their global indices, their packed tree
/// and planes. Immutable once built; snapshots share it.
struct StreamSection {
  std::uint32_t id;
  std::vector<int> indices;
  std::vector<RuntimeHull> hulls;
  HullTree tree;
  PackedPlanes planes;

  explicit StreamSection(SectionHulls&& s)
      : id(s.id), indices(std::move(s.indices)), hulls(std::move(s.hulls)), tree(hulls), planes(hulls) {}

  PlanesOf planes_of(int h) const { return {&planes, h}; }
};

/// The loaded sections as queries see them. Never changed once published.
struct StreamSnapshot {
  /// Ascending id; sections[s] is leaf s of `top`.
  std::vector<std::shared_ptr<const StreamSection>> sections;
  /// A tree of the sections' boxes (leaf s: sections[s]); null when none is loaded.
  std::unique_ptr<const HullTree> top;
};

// A snapshot (or none: nothing loaded yet) as a hull source
// (world_queries.h) of two levels, section boxes then each section's hulls,
// answering with global indices.
struct SnapshotSource {
  std::shared_ptr<const StreamSnapshot> snapshot;

  const HullTree* top() const { return snapshot ? snapshot->top.get() : nullptr; }

  template <typename Visit>
  bool in_box(const Aabb& box, Visit&& visit) const {
    return top() && top()->find_in_box(box, [&](int s) {
      const StreamSection& section = *snapshot->sections[s];
      return section.tree.find_in_box(
          box, [&](int h) { return visit(section.indices[h], section.hulls[h], section.planes_of(h)); });
    });
  }
  // A section's box holds its hulls' boxes, so the sphere's test on it
  // never drops a section holding a hull the test on hulls would keep.
  template <typename Visit>
  bool near_point(const Eigen::Vector3d& centre, double radius, Visit&& visit) const {
    return top() && top()->find_near_point(centre, radius, [&](int s) {
      const StreamSection& section = *snapshot->sections[s];
      return section.tree.find_near_point(
          centre, radius, [&](int h) { return visit(section.indices[h], section.hulls[h], section.planes_of(h)); });
    });
  }
  // The same for a capsule's axis.
  template <typename Visit>
  bool near_segment(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius, Visit&& visit) const {
    return top() && top()->find_near_segment(a, b, radius, [&](int s) {
      const StreamSection& section = *snapshot->sections[s];
      return section.tree.find_near_segment(
          a, b, radius, [&](int h) { return visit(section.indices[h], section.hulls[h], section.planes_of(h)); });
    });
  }
  // One reach for both levels: a hit in one section prunes the others.
  template <typename Visit>
  void along_ray(const Eigen::Vector3d& origin, const Eigen::Vector3d& inverse, double& reach, Visit&& visit) const {
    if (!top()) return;
    top()->walk_ray(origin, inverse, reach, [&](int s, double& best) {
      const StreamSection& section = *snapshot->sections[s];
      section.tree.walk_ray(origin, inverse, best, [&](int h, double& b) {
        visit(section.indices[h], section.hulls[h], section.planes_of(h), b);
      });
    });
  }
  std::optional<Aabb> bounds() const {
    if (!top()) return std::nullopt;
    return top()->bounds();
  }
};

/// The writer's side of a streamed world: the loaded sections by id (each
/// publish builds the snapshot's top tree over their boxes), and who holds
/// which hull.
class SectionIndex {
public:
  std::map<std::uint32_t, std::shared_ptr<const StreamSection>> loaded;
  std::unordered_set<int> hulls; // global indices of every loaded hull
};

namespace {
// Fails as StreamedWorld::add_section documents for a section's own content.
Status check_section(const SectionHulls& s) {
  const std::string name = "section " + std::to_string(s.id);
  if (s.hulls.empty()) return {StatusCode::invalid_argument, name + " has no hull"};
  if (s.indices.size() != s.hulls.size())
    return {StatusCode::invalid_argument, name + " has " + std::to_string(s.indices.size()) + " indices for " +
                                              std::to_string(s.hulls.size()) + " hulls"};
  for (size_t i = 0; i < s.indices.size(); ++i)
    if (s.indices[i] < 0 || (i > 0 && s.indices[i] <= s.indices[i - 1]))
      return {StatusCode::invalid_argument, name + ": hull indices must be >= 0 and ascending"};
  if (Status st = check_hulls(s.hulls, &s.indices); !st.ok()) return {st.code(), name + ": " + st.message()};
  return Status::success();
}
} // namespace
} // namespace detail

StreamedWorld::StreamedWorld() noexcept = default;
StreamedWorld::~StreamedWorld() = default;

void StreamedWorld::publish() {
  auto next = std::make_shared<detail::StreamSnapshot>();
  next->sections.reserve(index_->loaded.size());
  std::vector<Aabb> boxes;
  boxes.reserve(index_->loaded.size());
  for (const auto& [id, section] : index_->loaded) {
    next->sections.push_back(section);
    boxes.push_back(section->tree.bounds());
  }
  if (!boxes.empty()) next->top = std::make_unique<const detail::HullTree>(boxes);
  std::atomic_store(&current_, std::shared_ptr<const detail::StreamSnapshot>(std::move(next)));
}

Status StreamedWorld::add_section(SectionHulls section) {
  return detail::guarded("adding a section", [&]() -> Status {
    if (Status s = detail::check_section(section); !s.ok()) return s;
    const std::uint32_t id = section.id;
    // The heavy part, with no lock held: queries and other loads go on.
    auto built = std::make_shared<const detail::StreamSection>(std::move(section));

    const std::lock_guard<std::mutex> lock(writer_);
    if (!index_) index_ = std::make_unique<detail::SectionIndex>();
    detail::SectionIndex& index = *index_;
    if (index.loaded.count(id))
      return {StatusCode::invalid_argument, "section " + std::to_string(id) + " is already loaded"};
    for (int h : built->indices)
      if (index.hulls.count(h))
        return {StatusCode::invalid_argument, "section " + std::to_string(id) + ": hull " + std::to_string(h) +
                                                  " belongs to a section already loaded"};
    index.loaded[id] = built;
    try {
      index.hulls.insert(built->indices.begin(), built->indices.end());
      publish();
    } catch (...) { // out of memory: leave the world as it was
      for (int h : built->indices) index.hulls.erase(h);
      index.loaded.erase(id);
      throw;
    }
    return Status::success();
  });
}

Status StreamedWorld::remove_section(std::uint32_t id) {
  return detail::guarded("removing a section", [&]() -> Status {
    const std::lock_guard<std::mutex> lock(writer_);
    const Status not_loaded{StatusCode::invalid_argument, "section " + std::to_string(id) + " is not loaded"};
    if (!index_) return not_loaded;
    detail::SectionIndex& index = *index_;
    const auto found = index.loaded.find(id);
    if (found == index.loaded.end()) return not_loaded;
    const std::shared_ptr<const detail::StreamSection> section = found->second;
    index.loaded.erase(found);
    try {
      publish();
    } catch (...) { // out of memory: put it back as it was
      index.loaded[id] = section;
      throw;
    }
    for (int h : section->indices) index.hulls.erase(h);
    return Status::success();
  });
}

Result<std::vector<std::uint32_t>> StreamedWorld::loaded_sections() const {
  return detail::guarded("listing the loaded sections", [&]() -> Result<std::vector<std::uint32_t>> {
    std::vector<std::uint32_t> ids;
    if (const auto snap = std::atomic_load(&current_))
      for (const auto& section : snap->sections) ids.push_back(section->id);
    return ids;
  });
}

// The snapshot is held for the whole call: a section removed meanwhile
// stays alive until the query returns.
detail::SnapshotSource StreamedWorld::source() const { return {std::atomic_load(&current_)}; }

template class HullQueries<StreamedWorld>;

} // namespace hullcover::bvh
