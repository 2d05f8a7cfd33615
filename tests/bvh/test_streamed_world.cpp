// StreamedWorld (streamed_world.h) against HullWorld: with every section
// loaded it answers as the whole file's world does, hull for hull and
// double for double; with a section removed, as a world of the others.

#include "streamed_world_fixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <set>

namespace hullcover::bvh {
namespace {

using test::Answers;
using test::ask;
using test::same_answers;

// A HullWorld of every section but `skipped`, and its hulls' global indices.
std::shared_ptr<const HullWorld> world_without(const test::SectionedWorld& w, std::uint32_t skipped,
                                               std::vector<int>& global) {
  std::vector<RuntimeHull> kept;
  global.clear();
  for (size_t h = 0; h < w.hulls.size(); ++h) {
    bool in_skipped = false;
    for (const SectionHulls& s : w.sections)
      in_skipped = in_skipped || (s.id == skipped && std::binary_search(s.indices.begin(), s.indices.end(), int(h)));
    if (in_skipped) continue;
    kept.push_back(w.hulls[h]);
    global.push_back(static_cast<int>(h));
  }
  return HullWorld::build(std::move(kept)).value();
}

TEST(StreamedWorld, AllSectionsLoadedAnswersAsTheWholeFile) {
  const test::SectionedWorld w = test::make_sectioned_world(19, 420);
  ASSERT_EQ(w.sections.size(), static_cast<size_t>(test::kCells * test::kCells));
  StreamedWorld streamed;
  for (const SectionHulls& s : w.sections) ASSERT_TRUE(streamed.add_section(s).ok());
  const std::vector<test::Pose> poses = test::seeded_poses(7, 800);
  int touching = 0, hits = 0, swept_hits = 0, multi_section_overlaps = 0;
  for (size_t i = 0; i < poses.size(); ++i) {
    const Answers whole = ask(*w.full, poses[i]);
    const Answers cells = ask(streamed, poses[i]);
    std::string why;
    ASSERT_TRUE(same_answers(whole, cells, &why)) << "pose " << i << ": " << why;
    touching += whole.touching;
    hits += whole.ray.hit;
    swept_hits += whole.sweep.hit;
    // An overlap with hulls of two sections crosses a border.
    std::set<std::uint32_t> sections;
    for (int h : whole.overlap.hulls)
      for (const SectionHulls& s : w.sections)
        if (std::binary_search(s.indices.begin(), s.indices.end(), h)) sections.insert(s.id);
    multi_section_overlaps += sections.size() > 1;
  }
  // The poses reach what they are meant to: contacts, hits, border crossings.
  EXPECT_GT(touching, 200);
  EXPECT_GT(hits, 200);
  EXPECT_GT(swept_hits, 200);
  EXPECT_GT(multi_section_overlaps, 40);
  test::remove_sectioned_world(w);
}

TEST(StreamedWorld, RemovedSectionIsGoneAndReAddingRestoresTheAnswers) {
  const test::SectionedWorld w = test::make_sectioned_world(23, 300);
  StreamedWorld streamed;
  for (const SectionHulls& s : w.sections) ASSERT_TRUE(streamed.add_section(s).ok());
  const std::vector<test::Pose> poses = test::seeded_poses(11, 300);
  for (const SectionHulls& removed : {w.sections[5], w.sections[10], w.sections[0]}) {
    ASSERT_TRUE(streamed.remove_section(removed.id).ok());
    std::vector<int> global;
    const auto rest = world_without(w, removed.id, global);
    int changed = 0;
    for (size_t i = 0; i < poses.size(); ++i) {
      const Answers without = ask(streamed, poses[i]);
      EXPECT_FALSE(test::names_any_of(without, removed)) << "pose " << i;
      std::string why;
      ASSERT_TRUE(same_answers(ask(*rest, poses[i], &global), without, &why)) << "pose " << i << ": " << why;
      const Answers whole = ask(*w.full, poses[i]);
      changed += !same_answers(whole, without);
    }
    // A few poses are enough to show the removal was seen (how many reach a
    // corner section depends on the platform's order of random draws).
    EXPECT_GT(changed, 3) << "the removed section " << removed.id << " mattered to some poses";
    ASSERT_TRUE(streamed.add_section(removed).ok());
    for (size_t i = 0; i < poses.size(); ++i) {
      std::string why;
      ASSERT_TRUE(same_answers(ask(*w.full, poses[i]), ask(streamed, poses[i]), &why)) << "pose " << i << ": " << why;
    }
  }
  const Result<std::vector<std::uint32_t>> loaded = streamed.loaded_sections();
  ASSERT_TRUE(loaded.ok());
  EXPECT_EQ(loaded.value().size(), w.sections.size());
  EXPECT_TRUE(std::is_sorted(loaded.value().begin(), loaded.value().end()));
  test::remove_sectioned_world(w);
}

TEST(StreamedWorld, EmptyWorldFindsNothing) {
  StreamedWorld empty;
  const test::Pose p = test::seeded_poses(1, 1).front();
  const Answers a = ask(empty, p);
  EXPECT_TRUE(a.overlap.hulls.empty());
  EXPECT_TRUE(a.contacts.contacts.empty());
  EXPECT_FALSE(a.ray.hit);
  EXPECT_EQ(a.distance.hull, -1);
  EXPECT_EQ(a.distance.distance, std::numeric_limits<double>::infinity());
  EXPECT_FALSE(a.sweep.hit);
  EXPECT_FALSE(a.touching);
  EXPECT_FALSE(a.blocked);
  ASSERT_TRUE(empty.loaded_sections().ok());
  EXPECT_TRUE(empty.loaded_sections().value().empty());
  // Bad requests fail as on a HullWorld, loaded or not.
  ContactResult contacts;
  EXPECT_EQ(empty.contacts({QueryShape::sphere(-1.0)}, contacts).code(), StatusCode::invalid_argument);
  RayResult ray;
  EXPECT_EQ(empty.ray_cast({Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()}, ray).code(),
            StatusCode::invalid_argument);
}

TEST(StreamedWorld, BadSectionsAreRefusedAndLoadNothing) {
  const test::SectionedWorld w = test::make_sectioned_world(29, 120);
  StreamedWorld streamed;
  const SectionHulls& first = w.sections[0];
  ASSERT_TRUE(streamed.add_section(first).ok());
  const auto refused = [&](SectionHulls s, const std::string& words) {
    const Status status = streamed.add_section(std::move(s));
    EXPECT_EQ(status.code(), StatusCode::invalid_argument) << words;
    EXPECT_NE(status.message().find(words), std::string::npos) << status.message();
  };
  refused(first, "already loaded");
  SectionHulls other_id = first;
  other_id.id = 9999;
  refused(other_id, "belongs to a section already loaded");
  SectionHulls unsorted = w.sections[1];
  ASSERT_GE(unsorted.indices.size(), 2u);
  std::swap(unsorted.indices[0], unsorted.indices[1]);
  refused(unsorted, "ascending");
  SectionHulls short_indices = w.sections[1];
  short_indices.indices.pop_back();
  refused(short_indices, "indices for");
  SectionHulls none{77, {}, {}};
  refused(none, "has no hull");
  SectionHulls broken = w.sections[1];
  broken.hulls[0].shape.vertices[0].x() = std::numeric_limits<double>::quiet_NaN();
  refused(broken, "non-finite");
  EXPECT_EQ(streamed.remove_section(w.sections[1].id).code(), StatusCode::invalid_argument);
  // Nothing of the refused sections was loaded.
  ASSERT_EQ(streamed.loaded_sections().value(), std::vector<std::uint32_t>{first.id});
  ASSERT_TRUE(streamed.remove_section(first.id).ok());
  EXPECT_EQ(streamed.remove_section(first.id).code(), StatusCode::invalid_argument);
  EXPECT_TRUE(streamed.loaded_sections().value().empty());
  test::remove_sectioned_world(w);
}

} // namespace
} // namespace hullcover::bvh
