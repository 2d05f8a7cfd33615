#include "hullcover/validate/hull_set.h"

#include "hull_groups.h"

#include "hullcover/bvh/runtime_file.h"
#include "hullcover/covering/convex_hull_3d.h"
#include "hullcover/geometry/planar_hull.h"
#include "hullcover/geometry/regular_file.h"
#include "hullcover/geometry/tolerances.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

namespace hullcover::validate {
namespace {

using detail::HullGroup;
using detail::HullGroups;

// Scenes are read as float32, so no hull that stands for one lies farther
// out; beyond it the hull builder's products of three coordinates would
// overflow a double (Qhull crashed on 1e300).
constexpr double kLargestHullCoordinate = std::numeric_limits<float>::max();

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The plane of a group's points, fitted through three far-apart ones (the
// first, the farthest from it, the farthest from the line through both),
// facing the way the group's faces wind. A zero normal when the points are
// collinear or one.
Plane group_plane(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& winding) {
  const Eigen::Vector3d& a = points.front();
  const auto farthest = [&](const auto& distance) {
    return *std::max_element(points.begin(), points.end(), [&](const Eigen::Vector3d& p, const Eigen::Vector3d& q) {
      return distance(p) < distance(q);
    });
  };
  const Eigen::Vector3d b = farthest([&](const Eigen::Vector3d& p) { return (p - a).squaredNorm(); });
  const Eigen::Vector3d c = farthest([&](const Eigen::Vector3d& p) { return (p - a).cross(b - a).squaredNorm(); });
  Eigen::Vector3d n = (b - a).cross(c - a);
  if (n.squaredNorm() == 0.0) return {Eigen::Vector3d::Zero(), 0.0};
  n.normalize();
  if (n.dot(winding) < 0.0) n = -n;
  return {n, n.dot(a)};
}

// One OBJ group as a hull: the convex hull of its vertices, or, when they
// lie in one plane, a convex polygon of thickness 0 (what hullcover's OBJ
// writes for a flat hull: its front polygon). "In one plane" is within
// kDefaultRelativeTolerance of the group's own extent, the same fraction
// that gives a scene its default tol: the set carries no scene tolerance.
// Nothing for points that span no area (collinear, or one point).
std::optional<bvh::RuntimeHull> group_hull(ConvexHullBuilder& builder, const std::vector<Eigen::Vector3d>& vertices,
                                           const HullGroup& group) {
  std::vector<int> ids = group.vertices;
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  // The hull is made about the centre of its box, then moved back: Qhull
  // and the planes then round at the hull's size, not at its distance from
  // the origin (a map at 1e6 reads as it does at 0).
  std::vector<Eigen::Vector3d> points;
  for (int v : ids) points.push_back(vertices[v]);
  const Aabb box = bounding_box_of(points);
  const Eigen::Vector3d centre = 0.5 * (box.min + box.max);
  for (Eigen::Vector3d& p : points) p -= centre;
  const double flatness = kDefaultRelativeTolerance * box.diagonal();
  const Plane plane = group_plane(points, group.winding);
  const bool in_plane = std::all_of(points.begin(), points.end(), [&](const Eigen::Vector3d& p) {
    return std::abs(plane.signed_distance(p)) <= flatness;
  });
  std::optional<ConvexPolytope> made;
  if (!in_plane) {
    Result<ConvexPolytope> solid = builder.build(points);
    if (!solid.ok()) return std::nullopt;
    made = std::move(solid).value();
  } else {
    if (plane.normal.squaredNorm() == 0.0) return std::nullopt;
    std::vector<int> local_ids(points.size());
    for (size_t i = 0; i < local_ids.size(); ++i) local_ids[i] = static_cast<int>(i);
    const FlatPolygon polygon = make_flat_polygon(points, local_ids, plane.normal, flatness);
    if (polygon.corners.size() < 3) return std::nullopt;
    made = flat_polytope(polygon, true);
  }
  move_polytope(*made, centre);
  return bvh::make_runtime_hull(std::move(*made), 0);
}

Result<HullGroups> read_obj_groups(const std::string& path, const std::string& content) {
  std::istringstream in(content);
  std::vector<Eigen::Vector3d> vertices;
  std::vector<HullGroup> groups(1); // group 0: faces before any o/g line
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
      if (v.cwiseAbs().maxCoeff() > kLargestHullCoordinate)
        return Status{StatusCode::unreadable_file,
                      path + ":" + std::to_string(number) + ": vertex beyond the float32 range a scene can have"};
      vertices.push_back(v);
    } else if (tag == "o" || tag == "g") {
      if (!groups.back().vertices.empty()) groups.emplace_back();
      std::string name;
      std::getline(words >> std::ws, name);
      while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back()))) name.pop_back();
      groups.back().name = name;
    } else if (tag == "f") {
      std::string corner;
      std::vector<Eigen::Vector3d> face;
      while (words >> corner) {
        const long index = std::strtol(corner.c_str(), nullptr, 10); // "7/2/5" reads as 7
        const long resolved = index < 0 ? static_cast<long>(vertices.size()) + index : index - 1;
        if (index == 0 || resolved < 0 || resolved >= static_cast<long>(vertices.size()))
          return Status{StatusCode::unreadable_file,
                        path + ":" + std::to_string(number) + ": face corner " + corner + " names no vertex"};
        groups.back().vertices.push_back(static_cast<int>(resolved));
        face.push_back(vertices[resolved]);
      }
      // Newell's normal: the face's winding, whatever its corner count;
      // about the first corner, so that it rounds at the face's size, not at
      // its distance from the origin.
      for (size_t i = 1; i + 1 < face.size(); ++i)
        groups.back().winding += (face[i] - face[0]).cross(face[i + 1] - face[0]);
    }
  }
  return HullGroups{std::move(vertices), std::move(groups)};
}

Result<HullSet> hulls_of_groups(const std::string& path, HullGroups groups) {
  detail::keep_named_colliders(groups);
  HullSet set;
  ConvexHullBuilder builder;
  for (const HullGroup& group : groups.groups) {
    if (group.vertices.empty()) continue;
    std::optional<bvh::RuntimeHull> hull = group_hull(builder, groups.positions, group);
    if (hull)
      set.hulls.push_back(std::move(*hull));
    else
      ++set.groups_without_area;
  }
  if (set.hulls.empty()) return Status{StatusCode::empty_scene, path + ": no group spans an area: no hull"};
  return set;
}

} // namespace

namespace detail {

void keep_named_colliders(HullGroups& groups) {
  const auto keep_if = [&](const auto& named) {
    if (std::none_of(groups.groups.begin(), groups.groups.end(), named)) return false;
    groups.groups.erase(
        std::remove_if(groups.groups.begin(), groups.groups.end(), [&](const HullGroup& g) { return !named(g); }),
        groups.groups.end());
    return true;
  };
  if (keep_if([](const HullGroup& g) { return g.name.rfind("UCX_", 0) == 0; })) return;
  keep_if([](const HullGroup& g) { return ends_with(g.name, "-convcolonly") || ends_with(g.name, "-convcol"); });
}

} // namespace detail

Result<HullSet> load_hull_set(const std::string& path) {
  if (ends_with(path, ".hcw")) {
    Result<std::vector<bvh::RuntimeHull>> hulls = bvh::read_runtime_file(path);
    if (!hulls.ok()) return hulls.status();
    HullSet set;
    set.hulls = std::move(hulls).value();
    return set;
  }
  const Result<std::string> content = read_regular_file(path);
  if (!content.ok()) return content.status();
  try {
    Result<HullGroups> groups = ends_with(path, ".glb") ? detail::read_glb_hull_groups(path, content.value())
                                                        : read_obj_groups(path, content.value());
    if (!groups.ok()) return groups.status();
    return hulls_of_groups(path, std::move(groups).value());
  } catch (const std::exception& e) {
    return Status{StatusCode::unreadable_file, path + ": cannot read: " + e.what()};
  }
}

} // namespace hullcover::validate
