#pragma once
/// \file movement_merging.h
/// Greedy merging of groups of the faces an agent may touch into hulls that
/// keep the movement covering's promise (movement_validity.h): pairs of
/// groups that share an edge, or whose faces come within the near
/// distance, are tried cheapest first (the paper's cost: the union's
/// outline length over the square root of its area, so compact unions
/// first); a merge is made when the hull of the union passes the proof.
/// Run per region of the scene at once, then at each cut between regions
/// over both sides' groups, for the pairs across the cut. Then every group
/// whose faces all lie inside other hulls is dropped: its faces are
/// covered.

#include "movement/movement_groups.h"

#include "hullcover/covering/covering_types.h"
#include "hullcover/mesh/mesh_connectivity.h"

#include <functional>
#include <vector>

namespace hullcover::detail {

class MovementMerger {
public:
  /// Merges from `groups` (each keeping the promise, no face in two).
  /// With `region` (one per group), the first pairs are those of groups in
  /// different regions only: the pairs within one were tried before; a
  /// merged group then tries all its pairs. Pairs are groups with faces
  /// sharing an edge or within `near_distance` of each other.
  MovementMerger(const MovementContext& context, const MeshConnectivity& connectivity,
                 std::vector<MovementGroup> groups, const std::vector<int>& region, double near_distance,
                 int max_hull_vertices, GroupProver& prover);

  /// Merges until no pair is left; `progress` (may be empty) hears the
  /// fraction of groups merged away.
  void merge(const std::function<void(double)>& progress);
  /// Merges made.
  long long merges() const { return merges_; }
  /// The groups left, in the order they started.
  std::vector<MovementGroup> take_groups();

private:
  struct Entry {
    MovementGroup group;
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

  void push_pair(int a, int b, double shared);
  /// The union of groups a and b as a hull that keeps the promise, if it does.
  bool try_merge(int a, int b, MovementGroup& merged);

  const MovementContext& context_;
  int max_hull_vertices_;
  GroupProver& prover_;
  std::vector<Entry> entries_;
  std::vector<Pair> queue_; // a min-heap by Pair::operator>
  /// The queue's size after its last compaction (push_pair).
  size_t queue_compacted_at_ = 0;
  /// The queue grows by this many entries before its stale ones are dropped.
  static constexpr size_t kQueueGrowthBeforeCompaction = size_t{1} << 22;
  long long merges_ = 0;
};

/// Drops every group of `groups` whose faces each lie inside (or within
/// tol of) the hull of another group that stays; the rest keep their order.
void drop_held_groups(const MovementContext& context, std::vector<MovementGroup>& groups);

/// The covering's hulls of `groups`, ordered by their first face.
std::vector<CoveringHull> hulls_of_groups(const Mesh& mesh, double tol, const std::vector<MovementGroup>& groups);

} // namespace hullcover::detail
