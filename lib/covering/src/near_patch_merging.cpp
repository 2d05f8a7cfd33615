// Near merges, the pass that follows the paper's greedy merging
// (patch_merging.h): once the paper's pass has stopped, patches that share
// no edge but lie close are tried as pairs too, under the same conditions
// (the validity conditions never asked for a shared edge: the paper merges
// across edges only to keep its search local).

#include "patch_merging.h"

#include <algorithm>

namespace hullcover::detail {

int PatchMerger::push_near_pairs() {
  const int patch_count = static_cast<int>(patches_.size());
  const std::vector<Aabb> boxes = near_boxes();
  const AabbTree tree(boxes);
  int pushed = 0;
  std::vector<int> near;
  for (int a = 0; a < patch_count; ++a) {
    const Patch& pa = patches_[a];
    if (!pa.alive) continue;
    near.clear();
    tree.overlapping(boxes[a], near);
    for (int b : near) {
      const Patch& pb = patches_[b];
      if (b <= a || pa.shared_length.count(b)) continue;
      if (!near_pairs_tried_.insert({a, pa.version, b, pb.version}).second) continue;
      if (!patches_support_each_other(index_, pa, pb)) continue;
      push_pair(a, b);
      ++pushed;
    }
  }
  return pushed;
}

} // namespace hullcover::detail
