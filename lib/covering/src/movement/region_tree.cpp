#include "movement/region_tree.h"

#include "hullcover/geometry/aabb.h"
#include "hullcover/geometry/parallel_for.h"

#include <algorithm>
#include <condition_variable>
#include <deque>
#include <exception>
#include <map>
#include <mutex>
#include <utility>

namespace hullcover::detail {
namespace {

struct Splitter {
  const std::vector<Eigen::Vector3d>& centroid;
  int most;
  std::vector<int>& order;
  RegionTree& tree;

  // Numbers the regions of order[begin, end) and returns the height of
  // their part of the tree. Depth is about log2 of the face count.
  int split(int begin, int end) {
    if (end - begin <= most) {
      for (int i = begin; i < end; ++i) tree.region_of[order[i]] = tree.regions;
      ++tree.regions;
      return 0;
    }
    Aabb box;
    for (int i = begin; i < end; ++i) box.extend(centroid[order[i]]);
    int axis = 0;
    (box.max - box.min).maxCoeff(&axis);
    const int middle = begin + (end - begin) / 2;
    std::nth_element(order.begin() + begin, order.begin() + middle, order.begin() + end, [&](int x, int y) {
      return centroid[x][axis] != centroid[y][axis] ? centroid[x][axis] < centroid[y][axis] : x < y;
    });
    RegionJoin join;
    join.first = tree.regions;
    const int low = split(begin, middle);
    join.split = tree.regions;
    const int high = split(middle, end);
    join.end = tree.regions;
    join.height = 1 + std::max(low, high);
    tree.joins.push_back(join);
    return join.height;
  }
};

} // namespace

RegionTree split_into_regions(const Mesh& mesh, const std::vector<int>& faces, int most) {
  RegionTree tree;
  tree.region_of.assign(faces.size(), 0);
  if (faces.empty()) return tree;
  std::vector<Eigen::Vector3d> centroid(faces.size());
  for (size_t i = 0; i < faces.size(); ++i) {
    const Eigen::Vector3i& t = mesh.triangles[faces[i]];
    centroid[i] = (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3.0;
  }
  std::vector<int> order(faces.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  Splitter{centroid, std::max(1, most), order, tree}.split(0, static_cast<int>(order.size()));
  std::stable_sort(tree.joins.begin(), tree.joins.end(),
                   [](const RegionJoin& a, const RegionJoin& b) { return a.height < b.height; });
  return tree;
}

void run_regions_and_joins(const RegionTree& tree, int threads, const std::function<void(int)>& region,
                           const std::function<void(int)>& join) {
  const int regions = tree.regions;
  const int joins = static_cast<int>(tree.joins.size());
  // Task t < regions is region t; t >= regions is join t - regions. Each
  // task's parent is the join of the range it covers with its sibling's.
  std::map<std::pair<int, int>, int> task_of_range;
  for (int r = 0; r < regions; ++r) task_of_range[{r, r + 1}] = r;
  for (int j = 0; j < joins; ++j) task_of_range[{tree.joins[j].first, tree.joins[j].end}] = regions + j;
  std::vector<int> parent(regions + joins, -1);
  for (int j = 0; j < joins; ++j) {
    const RegionJoin& g = tree.joins[j];
    parent[task_of_range.at({g.first, g.split})] = regions + j;
    parent[task_of_range.at({g.split, g.end})] = regions + j;
  }
  std::vector<int> halves_left(joins, 2);
  std::deque<int> ready;
  for (int r = 0; r < regions; ++r) ready.push_back(r);
  int unfinished = regions + joins;
  std::exception_ptr failure;
  std::mutex mutex;
  std::condition_variable changed;
  const auto work = [&] {
    std::unique_lock<std::mutex> lock(mutex);
    for (;;) {
      changed.wait(lock, [&] { return !ready.empty() || unfinished == 0 || failure; });
      if (unfinished == 0 || failure) return;
      const int task = ready.front();
      ready.pop_front();
      lock.unlock();
      std::exception_ptr thrown;
      try {
        if (task < regions)
          region(task);
        else
          join(task - regions);
      } catch (...) {
        thrown = std::current_exception();
      }
      lock.lock();
      if (thrown && !failure) failure = thrown;
      --unfinished;
      const int up = parent[task];
      if (up >= 0 && --halves_left[up - regions] == 0) ready.push_back(up);
      changed.notify_all();
    }
  };
  run_together(std::min(threads, regions), work);
  if (failure) std::rethrow_exception(failure);
}

} // namespace hullcover::detail
