#include "hullcover/validate/hull_set.h"

#include "hullcover/bvh/runtime_file.h"
#include "hullcover/covering/convex_hull_3d.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace hullcover::validate {
namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

Result<HullSet> read_obj_groups(const std::string& path) {
  std::ifstream in(path);
  if (!in) return Status{StatusCode::file_not_found, path + ": no such file"};
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::vector<int>> groups(1);  // group 0: faces before any o/g line
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag == "v") {
      Eigen::Vector3d v;
      if (!(words >> v.x() >> v.y() >> v.z()) || !v.allFinite())
        return Status{StatusCode::unreadable_file, path + ":" + std::to_string(number) + ": bad vertex"};
      vertices.push_back(v);
    } else if (tag == "o" || tag == "g") {
      if (!groups.back().empty()) groups.emplace_back();
    } else if (tag == "f") {
      std::string corner;
      while (words >> corner) {
        const long index = std::strtol(corner.c_str(), nullptr, 10);  // "7/2/5" reads as 7
        const long resolved = index < 0 ? static_cast<long>(vertices.size()) + index : index - 1;
        if (index == 0 || resolved < 0 || resolved >= static_cast<long>(vertices.size()))
          return Status{StatusCode::unreadable_file,
                        path + ":" + std::to_string(number) + ": face corner " + corner + " names no vertex"};
        groups.back().push_back(static_cast<int>(resolved));
      }
    }
  }
  HullSet set;
  ConvexHullBuilder builder;
  for (std::vector<int>& group : groups) {
    if (group.empty()) continue;
    std::sort(group.begin(), group.end());
    group.erase(std::unique(group.begin(), group.end()), group.end());
    std::vector<Eigen::Vector3d> points;
    for (int v : group) points.push_back(vertices[v]);
    Result<ConvexPolytope> hull = builder.build(points);
    if (!hull.ok()) {
      ++set.groups_without_volume;
      continue;
    }
    set.hulls.push_back(bvh::make_runtime_hull(std::move(hull).value(), 0));
  }
  if (set.hulls.empty()) return Status{StatusCode::empty_scene, path + ": no group spans a volume: no hull"};
  return set;
}

} // namespace

Result<HullSet> load_hull_set(const std::string& path) {
  if (ends_with(path, ".hcw")) {
    Result<std::vector<bvh::RuntimeHull>> hulls = bvh::read_runtime_file(path);
    if (!hulls.ok()) return hulls.status();
    HullSet set;
    set.hulls = std::move(hulls).value();
    return set;
  }
  try {
    return read_obj_groups(path);
  } catch (const std::exception& e) {
    return Status{StatusCode::unreadable_file, path + ": cannot read: " + e.what()};
  }
}

} // namespace hullcover::validate
