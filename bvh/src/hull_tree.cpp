#include "hull_tree.h"

#include <fcl/broadphase/detail/hierarchy_tree.h>

#include <cmath>
#include <stdexcept>

namespace hullcover::bvh::detail {

HullTree::HullTree(const std::vector<RuntimeHull>& hulls) {
  if (hulls.size() > static_cast<size_t>(std::numeric_limits<std::int32_t>::max() / 2))
    throw std::length_error("more hulls than a packed tree indexes");
  // FCL builds the tree: its dynamic AABB tree, as its broad-phase manager
  // does, from leaves it then owns. (The array form's init leaks the 16
  // nodes its clear() allocates; this form's does not.)
  using Tree = fcl::detail::HierarchyTree<fcl::AABBd>;
  using Node = Tree::NodeType;
  std::vector<int> index(hulls.size());
  std::vector<Node*> leaves;
  leaves.reserve(hulls.size());
  Tree tree;
  try {
    for (size_t i = 0; i < hulls.size(); ++i) {
      index[i] = static_cast<int>(i);
      leaves.push_back(new Node);
      leaves.back()->bv = fcl::AABBd(hulls[i].box.min, hulls[i].box.max);
      leaves.back()->parent = nullptr;
      leaves.back()->children[1] = nullptr;
      leaves.back()->data = &index[i];
    }
  } catch (...) {
    for (Node* leaf : leaves) delete leaf;
    throw;
  }
  // FCL's Morton-order build: on the shared scenes its tree has a fifth to
  // two fifths fewer nodes in reach of a query than its median split
  // (measured by counting the nodes a sphere and a ray walk visits).
  constexpr int kMortonBuild = 2;
  tree.init(leaves, kMortonBuild);
  height_ = tree.getMaxHeight();
  pack(*tree.getRoot());
}

HullTree::HullTree(const FclTreeNode& root, size_t height) : height_(height) { pack(root); }

void HullTree::pack(const FclTreeNode& root) {
  nodes_.clear();
  if (root.isLeaf()) {
    // One hull: a root with one child.
    WideNode n{};
    n.count = 1;
    n.child[0] = ~*static_cast<const int*>(root.data);
    n.min_x[0] = float_at_or_below(root.bv.min_[0]);
    n.min_y[0] = float_at_or_below(root.bv.min_[1]);
    n.min_z[0] = float_at_or_below(root.bv.min_[2]);
    n.max_x[0] = float_at_or_above(root.bv.max_[0]);
    n.max_y[0] = float_at_or_above(root.bv.max_[1]);
    n.max_z[0] = float_at_or_above(root.bv.max_[2]);
    nodes_.push_back(n);
  } else {
    pack_node(root);
  }
  const WideNode& top = nodes_.front();
  for (int k = 0; k < 3; ++k) {
    bounds_.min[k] = std::numeric_limits<double>::infinity();
    bounds_.max[k] = -std::numeric_limits<double>::infinity();
  }
  for (int i = 0; i < top.count; ++i) {
    const Eigen::Vector3d lo(top.min_x[i], top.min_y[i], top.min_z[i]), hi(top.max_x[i], top.max_y[i], top.max_z[i]);
    bounds_.min = bounds_.min.cwiseMin(lo);
    bounds_.max = bounds_.max.cwiseMax(hi);
  }
}

std::int32_t HullTree::pack_node(const FclTreeNode& node) {
  // The node's four-wide form: its two children, each inner one with the
  // largest box opened into its own two until four are gathered (the usual
  // collapse of a binary tree, keeping the big boxes apart).
  const FclTreeNode* kids[4] = {node.children[0], node.children[1], nullptr, nullptr};
  int count = 2;
  while (count < 4) {
    int widest = -1;
    double widest_area = -1.0;
    for (int i = 0; i < count; ++i) {
      if (kids[i]->isLeaf()) continue;
      const Eigen::Vector3d e = kids[i]->bv.max_ - kids[i]->bv.min_;
      const double area = e.x() * e.y() + e.y() * e.z() + e.z() * e.x();
      if (area > widest_area) {
        widest_area = area;
        widest = i;
      }
    }
    if (widest < 0) break;
    const FclTreeNode* opened = kids[widest];
    kids[widest] = opened->children[0];
    kids[count++] = opened->children[1];
  }
  const std::int32_t at = static_cast<std::int32_t>(nodes_.size());
  nodes_.emplace_back();
  nodes_[at].count = count;
  for (int i = 0; i < count; ++i) {
    const FclTreeNode& k = *kids[i];
    const std::int32_t child = k.isLeaf() ? ~*static_cast<const int*>(k.data) : pack_node(k);
    WideNode& n = nodes_[at];  // after the recursion: nodes_ may have moved
    n.child[i] = child;
    n.min_x[i] = float_at_or_below(k.bv.min_[0]);
    n.min_y[i] = float_at_or_below(k.bv.min_[1]);
    n.min_z[i] = float_at_or_below(k.bv.min_[2]);
    n.max_x[i] = float_at_or_above(k.bv.max_[0]);
    n.max_y[i] = float_at_or_above(k.bv.max_[1]);
    n.max_z[i] = float_at_or_above(k.bv.max_[2]);
  }
  return at;
}

} // namespace hullcover::bvh::detail
