#include "hullcover/geometry/convex_polytope.h"

#include "hullcover/geometry/aabb.h"
#include "hullcover/geometry/tolerances.h"
#include "hullcover/geometry/triangle_distance.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hullcover {

void move_polytope(ConvexPolytope& polytope, const Eigen::Vector3d& offset) {
  for (Eigen::Vector3d& v : polytope.vertices) v += offset;
  for (Plane& plane : polytope.planes) plane.offset += plane.normal.dot(offset);
}

double deepest_signed_distance(const std::vector<Plane>& planes, const Eigen::Vector3d& p) {
  double deepest = -std::numeric_limits<double>::infinity();
  for (const Plane& plane : planes) deepest = std::max(deepest, plane.signed_distance(p));
  return deepest;
}

double distance_to_facet_fans(const ConvexPolytope& polytope, const Eigen::Vector3d& p) {
  double nearest_squared = std::numeric_limits<double>::infinity();
  for (const std::vector<int>& facet : polytope.facets)
    for (size_t i = 1; i + 1 < facet.size(); ++i) {
      const Eigen::Vector3d q = closest_point_on_triangle(p, polytope.vertices[facet[0]], polytope.vertices[facet[i]],
                                                          polytope.vertices[facet[i + 1]]);
      nearest_squared = std::min(nearest_squared, (q - p).squaredNorm());
    }
  return std::sqrt(nearest_squared);
}

namespace {

// Whether `box` (centre and half extents) lies in front of the plane's copy
// shrunk by tol, with the slack region_outside_interior promises.
bool box_outside_plane(const Plane& plane, const Eigen::Vector3d& magnitude, const Eigen::Vector3d& centre,
                       const Eigen::Vector3d& half, double tol) {
  // The box's point deepest behind the plane is at its centre less the
  // half extents along the normal's signs.
  const double deepest = plane.normal.dot(centre) - plane.offset - magnitude.dot(half);
  const double needed = -tol + kRegionOutsideSlackInTolerances * tol;
  if (deepest < needed) return false; // most boxes a walk opens: no need to bound the rounding
  // Every term above, and the point tests it stands for, round at the
  // magnitude of what they add up.
  const double size = std::abs(plane.offset) + magnitude.dot(centre.cwiseAbs() + half);
  const double rounding = 2.0 * kRoundingErrorsPerPlaneTest * std::numeric_limits<double>::epsilon() * size;
  return deepest >= needed + rounding;
}

} // namespace

bool region_outside_interior(const std::vector<Plane>& planes, const Aabb& box, double tol) {
  if (box.empty()) return false;
  const Eigen::Vector3d centre = 0.5 * (box.min + box.max), half = 0.5 * (box.max - box.min);
  for (const Plane& plane : planes)
    if (box_outside_plane(plane, plane.normal.cwiseAbs(), centre, half, tol)) return true;
  return false;
}

InteriorRegionTest::InteriorRegionTest(const ConvexPolytope& hull, const Aabb& box, double tol) : tol_(tol) {
  // Facet areas, each about its first corner (far from the origin an area
  // about the origin loses its digits), and the volume, as the cones from
  // the hull's first vertex over its facets.
  std::vector<std::pair<double, int>> by_area;
  double six_volumes = 0.0;
  for (size_t f = 0; f < hull.facets.size() && f < hull.planes.size(); ++f) {
    const std::vector<int>& facet = hull.facets[f];
    if (facet.empty()) continue;
    Eigen::Vector3d twice = Eigen::Vector3d::Zero();
    for (size_t i = 1; i + 1 < facet.size(); ++i)
      twice += (hull.vertices[facet[i]] - hull.vertices[facet[0]])
                   .cross(hull.vertices[facet[i + 1]] - hull.vertices[facet[0]]);
    by_area.push_back({-twice.norm(), static_cast<int>(f)});
    six_volumes += std::abs(twice.dot(hull.vertices[facet[0]] - hull.vertices.front()));
  }
  const Eigen::Vector3d extent = box.empty() ? Eigen::Vector3d::Zero() : Eigen::Vector3d(box.max - box.min);
  worthwhile_ = six_volumes / 6.0 <= kMostFilledFraction * extent.prod();
  const size_t kept = std::min<size_t>(kPlanes, by_area.size());
  std::partial_sort(by_area.begin(), by_area.begin() + static_cast<std::ptrdiff_t>(kept), by_area.end());
  for (size_t i = 0; i < kept; ++i) {
    const Plane& plane = hull.planes[by_area[i].second];
    planes_[count_++] = {plane, plane.normal.cwiseAbs()};
  }
}

bool InteriorRegionTest::outside(const Aabb& box) const {
  if (box.empty()) return false;
  const Eigen::Vector3d centre = 0.5 * (box.min + box.max), half = 0.5 * (box.max - box.min);
  for (int i = 0; i < count_; ++i)
    if (box_outside_plane(planes_[i].plane, planes_[i].magnitude, centre, half, tol_)) return true;
  return false;
}

bool segment_enters_interior(const std::vector<Plane>& planes, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                             double tol) {
  // Cyrus-Beck clipping of the parameter interval against each shrunk plane.
  double enter = 0.0, leave = 1.0;
  for (const Plane& plane : planes) {
    const double da = plane.signed_distance(a) + tol;
    const double db = plane.signed_distance(b) + tol;
    if (da >= 0.0 && db >= 0.0) return false;
    if (da < 0.0 && db < 0.0) continue;
    const double t = da / (da - db);
    if (da >= 0.0)
      enter = std::max(enter, t);
    else
      leave = std::min(leave, t);
    if (enter >= leave) return false;
  }
  return enter < leave;
}

void clip_polygon_into(const std::vector<Eigen::Vector3d>& polygon, const Plane& plane, double inset,
                       std::vector<Eigen::Vector3d>& out) {
  out.clear();
  const size_t n = polygon.size();
  if (n == 0) return;
  out.reserve(n + 1);
  // Each corner's distance is computed once and carried to the next edge.
  const double first = plane.signed_distance(polygon[0]) + inset;
  double dp = first;
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& p = polygon[i];
    const Eigen::Vector3d& q = polygon[(i + 1) % n];
    const double dq = i + 1 < n ? plane.signed_distance(q) + inset : first;
    if (dp <= 0.0) out.push_back(p);
    if ((dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0)) out.push_back(p + (q - p) * (dp / (dp - dq)));
    dp = dq;
  }
}

bool corners_strictly_inside(const std::vector<Eigen::Vector3d>& polygon, const Plane& plane, double inset) {
  bool all_inside = true;
  for (const Eigen::Vector3d& p : polygon) all_inside &= plane.signed_distance(p) + inset < 0.0;
  return all_inside;
}

void clip_polygon_in_place(std::vector<Eigen::Vector3d>& polygon, const Plane& plane, double inset,
                           std::vector<Eigen::Vector3d>& spare) {
  // Every corner strictly inside keeps every corner and makes no crossing.
  if (corners_strictly_inside(polygon, plane, inset)) return;
  clip_polygon_into(polygon, plane, inset, spare);
  polygon.swap(spare);
}

void split_polygon(const std::vector<Eigen::Vector3d>& polygon, const Plane& plane, std::vector<Eigen::Vector3d>& inner,
                   std::vector<Eigen::Vector3d>& outer) {
  inner.clear();
  outer.clear();
  const size_t n = polygon.size();
  if (n == 0) return;
  inner.reserve(n + 1);
  outer.reserve(n + 1);
  // clip_polygon_into on both sides at once: the flipped plane's distances
  // are these negated exactly, and so are both sides' crossing points.
  const double first = plane.signed_distance(polygon[0]);
  double dp = first;
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& p = polygon[i];
    const Eigen::Vector3d& q = polygon[(i + 1) % n];
    const double dq = i + 1 < n ? plane.signed_distance(q) : first;
    if (dp <= 0.0) inner.push_back(p);
    if (dp >= 0.0) outer.push_back(p);
    if ((dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0)) {
      const Eigen::Vector3d crossing = p + (q - p) * (dp / (dp - dq));
      inner.push_back(crossing);
      outer.push_back(crossing);
    }
    dp = dq;
  }
}

std::vector<Eigen::Vector3d> clip_polygon(const std::vector<Eigen::Vector3d>& polygon, const Plane& plane,
                                          double inset) {
  std::vector<Eigen::Vector3d> out;
  clip_polygon_into(polygon, plane, inset, out);
  return out;
}

std::vector<Eigen::Vector3d> clip_polygon_to_planes(std::vector<Eigen::Vector3d> polygon,
                                                    const std::vector<Plane>& planes, double inset) {
  std::vector<Eigen::Vector3d> spare;
  clip_polygon_to_planes_in_place(polygon, planes, inset, spare);
  return polygon;
}

void clip_polygon_to_planes_in_place(std::vector<Eigen::Vector3d>& polygon, const std::vector<Plane>& planes,
                                     double inset, std::vector<Eigen::Vector3d>& spare) {
  for (const Plane& plane : planes) {
    if (polygon.empty()) return;
    clip_polygon_in_place(polygon, plane, inset, spare);
  }
}

double thinnest_width(const ConvexPolytope& hull, Eigen::Vector3d* across) {
  double thinnest = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < hull.facets.size() && i < hull.planes.size(); ++i) {
    if (!hull.planes[i].normal.allFinite()) continue;
    double width = 0.0;
    for (const Eigen::Vector3d& v : hull.vertices) width = std::max(width, -hull.planes[i].signed_distance(v));
    if (width < thinnest) {
      thinnest = width;
      if (across) *across = hull.planes[i].normal;
    }
  }
  return thinnest;
}

double polytope_volume(const ConvexPolytope& polytope) {
  if (polytope.vertices.empty()) return 0.0;
  const Eigen::Vector3d& apex = polytope.vertices.front();
  double six_volume = 0.0;
  for (const std::vector<int>& facet : polytope.facets)
    for (size_t k = 1; k + 1 < facet.size(); ++k) {
      const Eigen::Vector3d a = polytope.vertices[facet[0]] - apex;
      const Eigen::Vector3d b = polytope.vertices[facet[k]] - apex;
      const Eigen::Vector3d c = polytope.vertices[facet[k + 1]] - apex;
      six_volume += a.dot(b.cross(c));
    }
  return std::max(0.0, six_volume / 6.0);
}

HullInterior hull_interior(const ConvexPolytope& hull, double tol) {
  HullInterior interior;
  for (const Plane& p : hull.planes) interior.planes.push_back({p.normal, p.offset - tol});
  // Facet k of the shrunk hull: its whole shrunk plane, cut by every other
  // shrunk plane. Not facet k moved in by tol: where two facets meet at a
  // shallow angle (a grown hull's nearly coplanar triangles) their shrunk
  // edge moves by tol / sin(angle / 2), far beyond either facet, and one
  // facet may vanish while its neighbour takes its place; rays leaving
  // there would go unjudged.
  const Aabb box = bounding_box_of(hull.vertices);
  const Eigen::Vector3d centre = 0.5 * (box.min + box.max);
  const double half = (box.max - box.min).norm() + tol;
  std::vector<std::vector<Eigen::Vector3d>> squares;
  for (const Plane& p : interior.planes) {
    const Eigen::Vector3d on = centre - p.signed_distance(centre) * p.normal;
    const Eigen::Vector3d u = p.normal.unitOrthogonal() * half;
    const Eigen::Vector3d v = p.normal.cross(u);
    squares.push_back({on - u - v, on + u - v, on + u + v, on - u + v});
  }
  // Planes within kOnePlaneInTolerances of each other across the hull (a
  // grown hull's coplanar triangles) are one: cutting each by the other
  // would leave the facet to rounding. The first holds it; the facets are
  // those of the holders' polytope (a superset of the interior by at most
  // that fraction of tol), each holder's square cut by every other holder
  // and by no plane that is not one. Cutting a facet by a plane that is one
  // with another holder leaves a gap: two planes a tol/16 apart cross a
  // third at a shallow angle along lines metres apart (a grown wall's
  // triangles on sauerbraten-fdm6), and rays entering between the two
  // lines lay on no facet, so no sweep judged them.
  const auto within = [&](size_t j, size_t k) {
    for (const Eigen::Vector3d& c : squares[k])
      if (std::abs(interior.planes[j].signed_distance(c)) > kOnePlaneInTolerances * tol) return false;
    return true;
  };
  // Both ways round, so that two holders are never one.
  const auto same_plane = [&](size_t j, size_t k) { return within(j, k) || within(k, j); };
  std::vector<bool> holds(interior.planes.size(), true);
  for (size_t k = 0; k < interior.planes.size(); ++k)
    for (size_t j = 0; j < k && holds[k]; ++j) holds[k] = !(holds[j] && same_plane(j, k));
  std::vector<Eigen::Vector3d> clipped;
  interior.facets.reserve(interior.planes.size());
  for (size_t k = 0; k < interior.planes.size(); ++k) {
    std::vector<Eigen::Vector3d> facet = holds[k] ? squares[k] : std::vector<Eigen::Vector3d>{};
    for (size_t j = 0; j < interior.planes.size() && !facet.empty(); ++j)
      if (j != k && holds[j]) {
        clip_polygon_into(facet, interior.planes[j], 0.0, clipped);
        facet.swap(clipped);
      }
    if (facet.size() < 3) facet.clear();
    interior.facets.push_back(std::move(facet));
  }
  return interior;
}

} // namespace hullcover
