#include "export/flat_hull_thickening.h"

#include "hullcover/geometry/aabb_tree.h"
#include "hullcover/geometry/planar_hull.h"

#include <Eigen/Geometry>

#include <cmath>

namespace hullcover::app {
namespace {

// A slab of `polygon` (corners counter-clockwise about `normal`) from
// `behind` below its plane to `ahead` above it.
ConvexPolytope polygon_slab(const std::vector<Eigen::Vector3d>& polygon, const Eigen::Vector3d& normal, double ahead,
                            double behind) {
  const int n = static_cast<int>(polygon.size());
  ConvexPolytope slab;
  for (const Eigen::Vector3d& p : polygon) slab.vertices.push_back(p + ahead * normal);
  for (const Eigen::Vector3d& p : polygon) slab.vertices.push_back(p - behind * normal);
  std::vector<int> top, bottom;
  for (int i = 0; i < n; ++i) top.push_back(i);
  for (int i = n - 1; i >= 0; --i) bottom.push_back(n + i);
  slab.facets = {top, bottom};
  // Each side seen from outside: up the near corner, along the top edge
  // backwards, down (counter-clockwise about its outward normal).
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    slab.facets.push_back({i, n + i, n + j, j});
  }
  for (const std::vector<int>& facet : slab.facets) {
    const Eigen::Vector3d& a = slab.vertices[facet[0]];
    Eigen::Vector3d area = Eigen::Vector3d::Zero();
    for (size_t k = 0; k < facet.size(); ++k)
      area += slab.vertices[facet[k]].cross(slab.vertices[facet[(k + 1) % facet.size()]]);
    const Eigen::Vector3d out = area.normalized();
    slab.planes.push_back({out, out.dot(a)});
  }
  return slab;
}

std::vector<Eigen::Vector3d> front_polygon(const ConvexPolytope& flat) {
  std::vector<Eigen::Vector3d> corners;
  for (int v : flat.facets[0]) corners.push_back(flat.vertices[v]);
  return corners;
}

// Whether flat polygon `other` lies in `flat`'s plane facing the other way
// and shares area with it (deeper than tol inside its rim).
bool faces_it_back(const ConvexPolytope& flat, const ConvexPolytope& other, double tol) {
  const Plane& front = flat.planes[0];
  const Plane& back = other.planes[0];
  // Facing away from each other; that they share the plane is decided by
  // every corner of `other` lying within tol of it.
  if (!(front.normal.dot(back.normal) < 0.0)) return false;
  for (const Eigen::Vector3d& p : other.vertices)
    if (std::abs(front.signed_distance(p)) > tol) return false;
  const std::vector<Eigen::Vector3d> corners = front_polygon(flat);
  const std::vector<Plane> sides = polygon_side_planes(corners, front.normal);
  const std::vector<Eigen::Vector3d> shared = clip_polygon_to_planes(front_polygon(other), sides, tol);
  if (shared.size() < 3) return false;
  Eigen::Vector3d area = Eigen::Vector3d::Zero();
  for (size_t k = 0; k < shared.size(); ++k) area += shared[k].cross(shared[(k + 1) % shared.size()]);
  return 0.5 * area.norm() > tol * tol;
}

} // namespace

bool is_flat_polygon(const ConvexPolytope& shape) {
  return shape.facets.size() == 2 && shape.planes.size() >= 2 && shape.facets[0].size() >= 3 &&
         shape.planes[0].normal.dot(shape.planes[1].normal) < 0.0;
}

ThickenedHulls thicken_flat_hulls(const std::vector<bvh::RuntimeHull>& hulls, double thickness, double tol) {
  ThickenedHulls out;
  out.thickness = thickness;
  // The flat hulls in a tree of their boxes, to find a sheet's other side.
  std::vector<int> flat_ids;
  std::vector<Aabb> boxes;
  for (size_t h = 0; h < hulls.size(); ++h)
    if (is_flat_polygon(hulls[h].shape)) {
      flat_ids.push_back(static_cast<int>(h));
      boxes.push_back(grown(hulls[h].box, tol));
    }
  const AabbTree tree(boxes);
  std::vector<int> near;
  for (size_t h = 0; h < hulls.size(); ++h) {
    const ConvexPolytope& shape = hulls[h].shape;
    if (!is_flat_polygon(shape)) {
      out.hulls.push_back(shape);
      continue;
    }
    near.clear();
    tree.overlapping(grown(hulls[h].box, tol), near);
    bool double_sided = false;
    for (int k : near) {
      const int other = flat_ids[k];
      if (other != static_cast<int>(h) && faces_it_back(shape, hulls[other].shape, tol)) {
        double_sided = true;
        break;
      }
    }
    ++out.flat;
    out.split += double_sided;
    const double ahead = double_sided ? 0.5 * thickness : 0.0;
    out.hulls.push_back(polygon_slab(front_polygon(shape), shape.planes[0].normal, ahead, thickness - ahead));
  }
  return out;
}

} // namespace hullcover::app
