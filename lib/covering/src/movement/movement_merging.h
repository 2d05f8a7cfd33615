#pragma once
/// \file movement_merging.h
/// Greedy merging of the faces an agent may touch into hulls that keep the
/// movement covering's promise (movement_validity.h): every face starts as
/// its own flat hull; pairs of groups that share an edge, or whose faces
/// come within the near distance, are tried cheapest first (the paper's
/// cost: the union's outline length over the square root of its area, so
/// compact unions first); a merge is made when the
/// hull of the union passes the proof. Then every group whose faces all
/// lie inside other hulls is dropped: its faces are covered.

#include "movement/movement_validity.h"

#include "hullcover/covering/convex_hull_3d.h"
#include "hullcover/covering/covering_types.h"
#include "hullcover/covering/movement_options.h"
#include "hullcover/mesh/mesh_connectivity.h"

#include <functional>
#include <vector>

namespace hullcover::detail {

class MovementMerger {
public:
  /// Groups start as the faces `faces` (ascending), each alone. Pairs are
  /// faces sharing an edge or within `near_distance` of each other.
  MovementMerger(const MovementContext& context, const MeshConnectivity& connectivity, const std::vector<int>& faces,
                 double near_distance, int max_hull_vertices, MovementStatistics& statistics,
                 std::function<void(double)> progress);

  /// Merges until no pair is left, then drops the groups other hulls hold.
  void run();
  /// The hulls of the groups left, ordered by their first face.
  std::vector<CoveringHull> hulls() const;

private:
  struct Group {
    std::vector<int> faces;
    std::vector<int> corners; ///< mesh vertex ids of its hull's corners
    ConvexPolytope hull;
    bool flat = true;
    Aabb box;
    double area = 0.0;
    Eigen::Vector3d area_vector = Eigen::Vector3d::Zero(); ///< sum of face normals x areas
    double boundary = 0.0; ///< length of its faces' outline (edges not shared within it)
    /// Groups it may merge with, ascending, each with the length of the
    /// edges they share (0 for groups only near it).
    std::vector<std::pair<int, double>> neighbours;
    int version = 0;
    bool alive = true;
  };
  struct Pair {
    double cost;
    int a, b, version_a, version_b;
    bool operator>(const Pair& o) const {
      if (cost != o.cost) return cost > o.cost;
      if (a != o.a) return a > o.a;
      return b > o.b;
    }
  };

  /// The group of face `f` alone, or nothing for a face with no area.
  bool start_group(int f, Group& group) const;
  void push_pair(int a, int b, double shared);
  /// The union of groups a and b as a hull that keeps the promise, if it does.
  bool try_merge(int a, int b, Group& merged);
  /// Drops every group whose faces each lie inside another group's hull.
  void drop_held_groups();

  const MovementContext& context_;
  int max_hull_vertices_;
  MovementStatistics& statistics_;
  std::function<void(double)> progress_;
  std::vector<Group> groups_;
  std::vector<Pair> queue_; // a min-heap by Pair::operator>
  /// The queue's size after its last compaction (push_pair).
  size_t queue_compacted_at_ = 0;
  /// The queue grows by this many entries before its stale ones are dropped.
  static constexpr size_t kQueueGrowthBeforeCompaction = size_t{1} << 22;
  ConvexHullBuilder builder_;
  UncoveredBoundary boundary_;
};

} // namespace hullcover::detail
