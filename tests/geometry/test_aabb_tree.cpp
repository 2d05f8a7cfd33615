// AabbTree (aabb_tree.h) against brute force over seeded random boxes.
//
// overlapping: must report exactly the non-empty boxes sharing a point with
// the query, closed boxes (touching counts), each once. Boxes on an integer
// grid make touching frequent and exact; point and flat boxes and empty
// boxes (never reported) are mixed in.
//
// nearest_along_segment: the validity checks' rays rely on it calling
// meet(i) for every item whose grown box the segment crosses and enters no
// later than the first meeting + slack, and never twice for one item nor
// for an empty box (it should not call it for boxes the segment misses
// either: see the skipped test). Checked with a meet() that returns where
// the segment enters the item's own (ungrown) box.

#include "hullcover/geometry/aabb_tree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>

namespace hullcover {
namespace {

using V = Eigen::Vector3d;
constexpr double kInf = std::numeric_limits<double>::infinity();

Aabb box(const V& min, const V& max) {
  Aabb b;
  b.min = min;
  b.max = max;
  return b;
}

// Written apart from boxes_overlap: non-empty, and the closed intervals
// intersect on every axis.
bool reference_overlap(const Aabb& a, const Aabb& b) {
  for (int k = 0; k < 3; ++k) {
    if (a.min[k] > a.max[k] || b.min[k] > b.max[k]) return false;
    if (std::max(a.min[k], b.min[k]) > std::min(a.max[k], b.max[k])) return false;
  }
  return true;
}

// Boxes with integer corners in [0, 16]: extents 0 to 4 per axis (0: flat or
// a point), one in ten empty (inverted on one axis, or the default box).
Aabb random_grid_box(std::mt19937& rng, bool allow_empty) {
  std::uniform_int_distribution<int> corner(0, 16), size(0, 4), kind(0, 9);
  Aabb b;
  for (int k = 0; k < 3; ++k) {
    b.min[k] = corner(rng);
    b.max[k] = b.min[k] + size(rng);
  }
  if (allow_empty && kind(rng) == 0) {
    if (kind(rng) < 5) return Aabb{};
    const int axis = kind(rng) % 3;
    b.max[axis] = b.min[axis] - 1.0 - size(rng);
  }
  return b;
}

std::vector<int> sorted(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  return v;
}

TEST(AabbTree, OverlappingMatchesBruteForceOnGridBoxes) {
  std::mt19937 rng(21);
  for (int count : {0, 1, 3, 5, 17, 200, 2000}) {
    std::vector<Aabb> boxes;
    for (int i = 0; i < count; ++i) boxes.push_back(random_grid_box(rng, true));
    const AabbTree tree(boxes);
    int touching = 0;
    for (int q = 0; q < 300; ++q) {
      const Aabb query = random_grid_box(rng, false);
      std::vector<int> expected;
      for (int i = 0; i < count; ++i)
        if (reference_overlap(boxes[i], query)) {
          expected.push_back(i);
          // Touching: sharing a face plane.
          bool touch = false;
          for (int k = 0; k < 3; ++k) touch |= boxes[i].max[k] == query.min[k] || boxes[i].min[k] == query.max[k];
          touching += touch;
        }
      std::vector<int> got = {-7}; // appends: what is already there stays
      tree.overlapping(query, got);
      ASSERT_EQ(got.front(), -7);
      got.erase(got.begin());
      ASSERT_EQ(sorted(got), expected) << "count " << count << " query " << q;
    }
    if (count >= 200) {
      EXPECT_GT(touching, 50) << "the grid should make touching common";
    }
  }
}

TEST(AabbTree, AnyOverlappingVisitsWhatOverlappingListsAndStopsAtTheFirstYes) {
  std::mt19937 rng(29);
  std::vector<Aabb> boxes;
  for (int i = 0; i < 2000; ++i) boxes.push_back(random_grid_box(rng, true));
  const AabbTree tree(boxes);
  int stopped_early = 0;
  for (int q = 0; q < 300; ++q) {
    const Aabb query = random_grid_box(rng, false);
    std::vector<int> listed;
    tree.overlapping(query, listed);
    // Never stopping: every listed box, in the listed order.
    std::vector<int> visited;
    EXPECT_FALSE(tree.any_overlapping(query, [&](int i) {
      visited.push_back(i);
      return false;
    }));
    ASSERT_EQ(visited, listed) << "query " << q;
    // Stopping at items divisible by 7: yes exactly when one is listed, and
    // nothing visited after it.
    visited.clear();
    const bool any = tree.any_overlapping(query, [&](int i) {
      visited.push_back(i);
      return i % 7 == 0;
    });
    const auto first = std::find_if(listed.begin(), listed.end(), [](int i) { return i % 7 == 0; });
    EXPECT_EQ(any, first != listed.end());
    ASSERT_EQ(visited, std::vector<int>(listed.begin(), first == listed.end() ? first : first + 1)) << "query " << q;
    stopped_early += first != listed.end() && first + 1 != listed.end();
  }
  EXPECT_GT(stopped_early, 30); // the early stop was put to the test
}

TEST(AabbTree, OverlappingMatchesBruteForceOnContinuousBoxes) {
  std::mt19937 rng(22);
  std::uniform_real_distribution<double> u(-10.0, 10.0), size(0.0, 2.0);
  std::vector<Aabb> boxes;
  for (int i = 0; i < 1500; ++i) {
    const V min(u(rng), u(rng), u(rng));
    boxes.push_back(box(min, min + V(size(rng), size(rng), size(rng))));
  }
  // Many boxes on one centre: the median split must still separate them.
  for (int i = 0; i < 300; ++i) boxes.push_back(box(V(1, 1, 1), V(2, 2, 2)));
  const AabbTree tree(boxes);
  for (int q = 0; q < 400; ++q) {
    const V min(u(rng), u(rng), u(rng));
    const Aabb query = box(min, min + 3.0 * V(size(rng), size(rng), size(rng)));
    std::vector<int> expected, got;
    for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
      if (reference_overlap(boxes[i], query)) expected.push_back(i);
    tree.overlapping(query, got);
    ASSERT_EQ(sorted(got), expected) << "query " << q;
  }
  std::vector<int> all;
  tree.overlapping(box(V::Constant(-20), V::Constant(20)), all);
  EXPECT_EQ(all.size(), boxes.size());
}

// The tree keeps its inner boxes in floats (aabb_tree.h): far from the
// origin a float is ~0.03 apart, a double ~1e-11. A query touching a box at
// a coordinate no float holds must still find it, and one missing it by a
// hair of a double must not: inner boxes only ever round outward.
TEST(AabbTree, OverlappingIsExactWhereFloatsCannotHoldTheCorners) {
  const double base = 1.0e6 / 3.0; // float spacing 0.03125 here
  std::vector<Aabb> boxes;
  for (int i = 0; i < 64; ++i) {
    const V min(base + 0.1 * i + 0.01, base - 0.05 * i, base + 1e-3 * i);
    boxes.push_back(box(min, min + V(0.07, 0.03, 0.0013)));
  }
  const AabbTree tree(boxes);
  const double hair = 1e-9; // far above a double's spacing here, far below a float's
  for (int i = 0; i < 64; ++i) {
    for (int axis = 0; axis < 3; ++axis) {
      for (bool above : {true, false}) {
        // A thin query on the box's face, reaching away from it.
        Aabb touch = boxes[i];
        if (above) {
          touch.min[axis] = boxes[i].max[axis];
          touch.max[axis] = boxes[i].max[axis] + hair;
        } else {
          touch.max[axis] = boxes[i].min[axis];
          touch.min[axis] = boxes[i].min[axis] - hair;
        }
        Aabb apart = touch;
        apart.min[axis] += above ? hair : -hair;
        apart.max[axis] += above ? hair : -hair;
        std::vector<int> expected_touch, expected_apart, got_touch, got_apart;
        for (int j = 0; j < 64; ++j) {
          if (reference_overlap(boxes[j], touch)) expected_touch.push_back(j);
          if (reference_overlap(boxes[j], apart)) expected_apart.push_back(j);
        }
        ASSERT_TRUE(std::count(expected_touch.begin(), expected_touch.end(), i) == 1);
        ASSERT_TRUE(std::count(expected_apart.begin(), expected_apart.end(), i) == 0);
        tree.overlapping(touch, got_touch);
        tree.overlapping(apart, got_apart);
        ASSERT_EQ(sorted(got_touch), expected_touch) << "box " << i << " axis " << axis;
        ASSERT_EQ(sorted(got_apart), expected_apart) << "box " << i << " axis " << axis;
      }
    }
  }
}

TEST(AabbTree, EmptyBoxesAreNeverReported) {
  std::vector<Aabb> boxes(5);                    // default boxes: empty
  boxes.push_back(box(V(0, 0, 0), V(1, -1, 1))); // inverted on y
  boxes.push_back(box(V(0, 0, 0), V(0, 0, 0)));  // a point: not empty
  const AabbTree tree(boxes);
  EXPECT_FALSE(tree.empty());
  std::vector<int> got;
  tree.overlapping(box(V::Constant(-1e300), V::Constant(1e300)), got);
  EXPECT_EQ(got, std::vector<int>{6});
  const AabbTree none(std::vector<Aabb>(3));
  EXPECT_TRUE(none.empty());
  got.clear();
  none.overlapping(box(V::Constant(-1e300), V::Constant(1e300)), got);
  EXPECT_TRUE(got.empty());
}

TEST(AabbTree, AnEmptyQueryOverlapsNothing) {
  // Found by this test: an inverted query box was reported as overlapping.
  std::vector<Aabb> boxes = {box(V(0, 0, 0), V(10, 10, 10))};
  const AabbTree tree(boxes);
  std::vector<int> got;
  tree.overlapping(box(V(5, 5, 5), V(3, 3, 3)), got); // min > max: no point
  EXPECT_TRUE(got.empty());
}

TEST(AabbTree, BoxesSpreadEachTwiceAsFarAsTheLastKeepTheTreeShallow) {
  // Centres at 2^i: every surface-area split parts the farthest box from
  // the rest, a tree one level per box, deeper than a walk's stack. The
  // builder turns to median splits below a fixed depth (found by writing
  // this test: without that, a walk overran its stack, which the assertion
  // on its depth caught).
  constexpr int kBoxes = 1000;
  std::vector<Aabb> boxes;
  for (int i = 0; i < kBoxes; ++i) {
    const double at = std::ldexp(1.0, i);
    boxes.push_back(box(V(at, 0, 0), V(1.5 * at, 1, 1)));
  }
  const AabbTree tree(boxes);
  for (int i = 0; i < kBoxes; ++i) {
    std::vector<int> got;
    tree.overlapping(boxes[i], got);
    ASSERT_EQ(got, std::vector<int>{i});
  }
  // A segment along all of them, meeting none: every box is asked once.
  std::vector<int> asked;
  tree.nearest_along_segment(V(0, 0.5, 0.5), V(std::ldexp(1.0, kBoxes), 0.5, 0.5), 0.0, 0.0, [&](int i) {
    asked.push_back(i);
    return kInf;
  });
  ASSERT_EQ(asked.size(), size_t(kBoxes));
  std::sort(asked.begin(), asked.end());
  for (int i = 0; i < kBoxes; ++i) EXPECT_EQ(asked[i], i);
}

TEST(AabbTree, BoxesWithInfiniteCornersOrCentresASubnormalApartAreStillFound) {
  // A box reaching to infinity has a NaN centre, and centres a subnormal
  // apart give an infinite bin scale: the surface-area split must not turn
  // either into a bin index (found in review: it cast them to int).
  std::vector<Aabb> boxes;
  for (int i = 0; i < 8; ++i) boxes.push_back(box(V(i, 0, 0), V(i + 0.5, 1, 1)));
  boxes.push_back(box(V::Constant(-kInf), V::Constant(kInf)));
  for (int i = 0; i < 8; ++i) boxes.push_back(box(V(5e-324 * i, 2, 2), V(5e-324 * i, 3, 3)));
  const AabbTree tree(boxes);
  for (size_t q = 0; q < boxes.size(); ++q) {
    std::vector<int> got, expected;
    tree.overlapping(boxes[q], got);
    for (size_t i = 0; i < boxes.size(); ++i)
      if (boxes_overlap(boxes[i], boxes[q])) expected.push_back(static_cast<int>(i));
    ASSERT_EQ(sorted(got), expected) << "query " << q;
  }
}

// Where segment from-to (s in [0, 1]) enters `b` grown by `margin`, 0 when
// it starts inside, infinity when it misses: clipped by division per axis.
double reference_entry(const V& from, const V& to, const Aabb& b, double margin) {
  if (b.empty()) return kInf;
  double enter = 0.0, leave = 1.0;
  for (int k = 0; k < 3; ++k) {
    const double low = b.min[k] - margin, high = b.max[k] + margin, d = to[k] - from[k];
    if (d == 0.0) {
      if (from[k] < low || from[k] > high) return kInf;
      continue;
    }
    const double s0 = (low - from[k]) / d, s1 = (high - from[k]) / d;
    enter = std::max(enter, std::min(s0, s1));
    leave = std::min(leave, std::max(s0, s1));
  }
  return enter <= leave ? enter : kInf;
}

// Seeded random boxes and segments in a 20-unit cube centred at `offset`
// on every axis. Far from the origin (offset 3e6: float spacing 0.25, more
// than many boxes' sizes) the inner boxes round out a lot; the walk must
// still meet every candidate and find the first meeting.
void check_nearest_along_segment(double offset, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(offset - 10.0, offset + 10.0), size(0.0, 1.5), unit(0.0, 1.0);
  std::uniform_int_distribution<int> kind(0, 9);
  // Rounding apart from the tree's own slab test: a double's spacing at the
  // offset, over segments as short as ~0.1.
  const double kEps = 1e-9 + 1e-14 * offset;
  long must_total = 0, called_total = 0;
  for (int scene = 0; scene < 6; ++scene) {
    std::vector<Aabb> boxes;
    for (int i = 0; i < 600; ++i) {
      const V min(u(rng), u(rng), u(rng));
      V extent(size(rng), size(rng), size(rng));
      if (kind(rng) == 0) extent.setZero();             // a point
      if (kind(rng) == 0) extent[kind(rng) % 3] = -1.0; // empty
      boxes.push_back(box(min, min + extent));
    }
    const AabbTree tree(boxes);
    for (int q = 0; q < 150; ++q) {
      const double margin = std::vector<double>{0.0, 0.05, 0.5}[q % 3];
      const double slack = std::vector<double>{0.0, 0.02, 0.3, 2.0}[q % 4];
      const V from(u(rng), u(rng), u(rng));
      V to(u(rng), u(rng), u(rng));
      switch (q % 5) {
        case 0: to[q % 3] = from[q % 3]; break; // flat on one axis
        case 1:
          to = from;
          to[q % 3] += u(rng) - offset;
          break;                  // along one axis
        case 2: to = from; break; // a point
        default: break;
      }
      std::vector<int> calls;
      double tree_best = kInf;
      const auto meet = [&](int i) {
        calls.push_back(i);
        const double s = reference_entry(from, to, boxes[i], 0.0);
        const double met = s <= 1.0 ? s : kInf;
        tree_best = std::min(tree_best, met);
        return met;
      };
      tree.nearest_along_segment(from, to, margin, slack, meet);
      double best = kInf; // the first meeting, over all items
      for (const Aabb& b : boxes) best = std::min(best, reference_entry(from, to, b, 0.0));
      std::vector<char> called(boxes.size(), 0);
      for (int i : calls) {
        ASSERT_FALSE(called[i]) << "meet called twice for " << i;
        ASSERT_FALSE(boxes[i].empty()) << "meet called for empty box " << i;
        called[i] = 1;
      }
      called_total += static_cast<long>(calls.size());
      for (int i = 0; i < static_cast<int>(boxes.size()); ++i) {
        const double entry = reference_entry(from, to, boxes[i], margin - kEps);
        if (entry < kInf && entry <= best + slack - kEps) {
          ++must_total;
          EXPECT_TRUE(called[i]) << "scene " << scene << " query " << q << ": box " << i << " entered at " << entry
                                 << ", first meeting " << best << ", slack " << slack;
        }
      }
      EXPECT_EQ(tree_best, best) << "the first meeting found";
    }
  }
  EXPECT_GT(must_total, 500) << "the queries should reach many boxes";
  EXPECT_LT(called_total, 30 * must_total) << "the tree should prune";
}

TEST(AabbTree, NearestAlongSegmentMeetsEveryCandidateNearerThanTheFirstMeetingPlusSlack) {
  check_nearest_along_segment(0.0, 23);
}

TEST(AabbTree, NearestAlongSegmentMeetsEveryCandidateFarFromTheOrigin) { check_nearest_along_segment(3.0e6, 25); }

// Coordinates beyond the float range (a hostile or corrupt file that got
// past the readers): the inner boxes clamp to the largest float or
// infinity, outward, and queries stay exact on the items.
TEST(AabbTree, BoxesBeyondTheFloatRangeAreStillFound) {
  std::vector<Aabb> boxes;
  for (int i = 0; i < 40; ++i) {
    const double x = (i % 2 == 0 ? 1.0 : -1.0) * 1e39 * (1 + i); // |x| > FLT_MAX (3.4e38)
    boxes.push_back(box(V(x, 0, 0), V(x + 1e30, 1, 1)));
  }
  boxes.push_back(box(V(-1e300, -1e300, -1e300), V(-1e299, -1e299, -1e299)));
  const AabbTree tree(boxes);
  for (int i = 0; i < static_cast<int>(boxes.size()); ++i) {
    std::vector<int> got;
    tree.overlapping(box(boxes[i].max, boxes[i].max), got); // touching its far corner
    EXPECT_EQ(got, std::vector<int>{i}) << "box " << i;
    got.clear();
    Aabb beyond = box(boxes[i].max, boxes[i].max);
    beyond.min[1] = beyond.max[1] = std::nextafter(boxes[i].max[1], kInf);
    tree.overlapping(beyond, got);
    EXPECT_TRUE(got.empty()) << "box " << i;
  }
  // Along the x axis through the boxes of the first 40: every one is met,
  // and the nearest is found.
  std::vector<int> calls;
  const V from(-1e41, 0.5, 0.5), to(1e41, 0.5, 0.5);
  double best = kInf;
  tree.nearest_along_segment(from, to, 0.0, 2.0, [&](int i) {
    calls.push_back(i);
    const double s = reference_entry(from, to, boxes[i], 0.0);
    best = std::min(best, s);
    return s;
  });
  std::vector<int> expected(40);
  for (int i = 0; i < 40; ++i) expected[i] = i;
  EXPECT_EQ(sorted(calls), expected);
  EXPECT_EQ(best, reference_entry(from, to, boxes[39], 0.0)); // -4e40, the leftmost
}

// Exact coordinates: integer boxes, axis-aligned segments of power-of-two
// length (so the slab test rounds nothing), margin 0 and no pruning (slack
// larger than the segment). `calls` gets the boxes met, `touched` those the
// closed segment touches.
void grid_segment_queries(
    const std::function<void(const std::vector<int>& calls, const std::vector<int>& touched, int query)>& check) {
  std::mt19937 rng(24);
  std::vector<Aabb> boxes;
  for (int i = 0; i < 400; ++i) boxes.push_back(random_grid_box(rng, true));
  const AabbTree tree(boxes);
  std::uniform_int_distribution<int> coordinate(0, 16), axis_of(0, 2), power(0, 3);
  for (int q = 0; q < 300; ++q) {
    const V from(coordinate(rng), coordinate(rng), coordinate(rng));
    V to = from;
    to[axis_of(rng)] += (q % 2 == 0 ? 1 : -1) * (1 << power(rng));
    std::vector<int> calls;
    tree.nearest_along_segment(from, to, 0.0, 4.0, [&](int i) {
      calls.push_back(i);
      return 0.5;
    });
    Aabb segment;
    segment.extend(from);
    segment.extend(to);
    std::vector<int> touched;
    for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
      if (reference_overlap(boxes[i], segment)) touched.push_back(i);
    check(sorted(calls), touched, q);
  }
}

TEST(AabbTree, NearestAlongSegmentOnTheGridMeetsEveryTouchedBox) {
  int touched_total = 0;
  grid_segment_queries([&](const std::vector<int>& calls, const std::vector<int>& touched, int q) {
    touched_total += static_cast<int>(touched.size());
    EXPECT_TRUE(std::includes(calls.begin(), calls.end(), touched.begin(), touched.end())) << "query " << q;
  });
  EXPECT_GT(touched_total, 300);
}

TEST(AabbTree, NearestAlongSegmentNeverMeetsABoxTheSegmentMisses) {
  // Found by this test: every item of a leaf opened before the first meeting
  // was met (a missed box's entry, infinity, passed 'entry <= best + slack'
  // while best was infinity).
  grid_segment_queries([](const std::vector<int>& calls, const std::vector<int>& touched, int q) {
    EXPECT_EQ(calls, touched) << "query " << q;
  });
}

// nearest_to_point: items are points inside their boxes (so no nearer than
// their boxes, as the contract asks). Its answer must be the brute-force
// minimum over every item, capped at limit^2; each item asked at most once,
// and never an empty box's. Far from the origin (offset) inner boxes round
// outward to floats ~0.06 apart, coarser than the points' spacing.
void check_nearest_to_point(double offset, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-10.0, 10.0), size(0.0, 2.0), share(0.0, 1.0);
  std::vector<Aabb> boxes;
  std::vector<V> points;
  for (int i = 0; i < 1200; ++i) {
    const V min = V::Constant(offset) + V(u(rng), u(rng), u(rng));
    const V extent(size(rng), size(rng), size(rng));
    boxes.push_back(box(min, min + extent));
    points.push_back(min + V(share(rng), share(rng), share(rng)).cwiseProduct(extent));
    if (i % 10 == 0) boxes.back() = Aabb{}; // empty: never asked
  }
  const AabbTree tree(boxes);
  for (int q = 0; q < 300; ++q) {
    const V p = V::Constant(offset) + 1.5 * V(u(rng), u(rng), u(rng));
    const double limit = q % 3 == 0 ? 0.5 : (q % 3 == 1 ? 3.0 : kInf);
    double expected = limit * limit;
    for (size_t i = 0; i < boxes.size(); ++i)
      if (!boxes[i].empty()) expected = std::min(expected, (points[i] - p).squaredNorm());
    std::vector<int> asked;
    const double got = tree.nearest_to_point(p, limit, [&](int i) {
      asked.push_back(i);
      return (points[i] - p).squaredNorm();
    });
    ASSERT_EQ(got, expected) << "query " << q << " limit " << limit;
    const std::vector<int> once = sorted(asked);
    ASSERT_TRUE(std::adjacent_find(once.begin(), once.end()) == once.end()) << "an item asked twice";
    for (int i : asked) ASSERT_FALSE(boxes[i].empty()) << "an empty box asked";
    if (std::isinf(limit)) {
      EXPECT_LT(asked.size(), boxes.size() / 4) << "the walk should prune far boxes";
    }
  }
}

TEST(AabbTree, NearestToPointIsTheMinimumOverEveryItem) { check_nearest_to_point(0.0, 31); }

TEST(AabbTree, NearestToPointIsTheMinimumFarFromTheOrigin) { check_nearest_to_point(1.0e6, 32); }

} // namespace
} // namespace hullcover
