#pragma once
/// \file region_tree.h
/// The regions a movement covering merges in, and the order their groups
/// join: the touchable faces' box is halved at the median of their
/// centroids along its longest side until each part holds at most a given
/// number of faces (a region); each halving is then a join, where the
/// groups of its two halves merge across the cut, as soon as both halves
/// are merged (run_regions_and_joins).

#include "hullcover/geometry/mesh.h"

#include <functional>
#include <vector>

namespace hullcover::detail {

/// One halving: the regions [first, split) on one side of the cut,
/// [split, end) on the other.
struct RegionJoin {
  int first = 0, split = 0, end = 0;
  int height = 0; ///< 1 + the larger of its halves' (a region's is 0)
};

struct RegionTree {
  std::vector<int> region_of; ///< per face of the faces split, its region
  int regions = 0;
  std::vector<RegionJoin> joins; ///< every halving, by height, lowest first
};

/// Splits `faces` (indices into `mesh`) into regions of at most `most`
/// (>= 1) faces. Regions are numbered depth first, so each join's regions
/// are consecutive; ties in the median are broken by face, so the regions
/// are the same on every machine.
RegionTree split_into_regions(const Mesh& mesh, const std::vector<int>& faces, int most);

/// Runs `region(i)` for every region and `join(j)` for every join of
/// `tree`, on up to `threads` threads (the caller's one of them): a join
/// once both its halves are done, their regions and the joins under them,
/// so no thread waits for a whole height to finish. Each call sees its
/// halves' results whatever thread ran them. The first exception a call
/// throws is rethrown once every thread has stopped; calls not yet started
/// then never start.
void run_regions_and_joins(const RegionTree& tree, int threads, const std::function<void(int)>& region,
                           const std::function<void(int)>& join);

} // namespace hullcover::detail
