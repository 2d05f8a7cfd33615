#pragma once
// Union-find, internal to lib/mesh: islands join pieces with it, the
// tolerance joins islands whose boxes meet into places.

#include <algorithm>
#include <numeric>
#include <vector>

namespace hullcover::detail {

// Union-find with path halving; the smaller root wins, so roots are the
// lowest member and the result does not depend on the order of unions.
struct DisjointSets {
  std::vector<int> parent;
  explicit DisjointSets(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void join(int a, int b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

} // namespace hullcover::detail
