#include "hullcover/lib/exact_conditions.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace hullcover {
namespace {

std::vector<Eigen::Vector3d> clip_to_planes(std::vector<Eigen::Vector3d> part, const std::vector<Plane>& planes,
                                            double inset) {
  for (const Plane& plane : planes) {
    if (part.empty()) break;
    part = clip_polygon(part, plane, inset);
  }
  return part;
}

Plane plane_through(const Eigen::Vector3d& normal, const Eigen::Vector3d& point) {
  return {normal, normal.dot(point)};
}

// Where the ray from `origin` along unit `dir` first lies deeper than tol
// behind every plane, if it ever does (Cyrus-Beck on t >= 0).
std::optional<double> ray_entry(const std::vector<Plane>& planes, const Eigen::Vector3d& origin,
                                const Eigen::Vector3d& dir, double tol) {
  double enter = 0.0, leave = std::numeric_limits<double>::infinity();
  for (const Plane& plane : planes) {
    const double start = plane.signed_distance(origin) + tol;  // must become < 0
    const double rate = plane.normal.dot(dir);
    if (rate == 0.0) {
      if (start >= 0.0) return std::nullopt;
      continue;
    }
    const double t = -start / rate;
    if (rate < 0.0)
      enter = std::max(enter, t);
    else
      leave = std::min(leave, t);
    if (enter >= leave) return std::nullopt;
  }
  return enter;
}

// Does facet k lie in the plane of one of the patch's faces, facing the
// same way? Then the hull's surface there is the mesh's own.
bool facet_carries_face(const ConvexPolytope& hull, size_t k, const std::vector<Plane>& face_planes, double tol) {
  for (const Plane& q : face_planes) {
    if (q.normal.dot(hull.planes[k].normal) <= 0.0) continue;
    bool on = true;
    for (int v : hull.facets[k]) on &= std::abs(q.signed_distance(hull.vertices[v])) <= tol;
    if (on) return true;
  }
  return false;
}

// Quick rejection: a hull plane with every corner of the sweep on its far
// side (beyond -tol) keeps the sweep out of the interior.
bool separated(const FreeSpaceSweep& sweep, const ConvexPolytope& hull, double tol) {
  for (const Plane& plane : hull.planes) {
    bool all_out = true;
    for (const Eigen::Vector3d& c : sweep.corners) all_out &= plane.signed_distance(c) >= -tol;
    if (all_out) return true;
  }
  for (size_t i = 0; i < sweep.planes.size(); ++i) {
    bool all_out = true;
    for (const Eigen::Vector3d& v : hull.vertices) all_out &= sweep.planes[i].signed_distance(v) + sweep.insets[i] > 0.0;
    if (all_out) return true;
  }
  return false;
}

// The part of `region` (in an entry facet) from which rays along `dir` leave
// the hull through facet j: `region` clipped to facet j's column along dir.
std::vector<Eigen::Vector3d> leaving_through(std::vector<Eigen::Vector3d> region, const ConvexPolytope& hull, size_t j,
                                             const Eigen::Vector3d& dir, double tol) {
  const std::vector<int>& facet = hull.facets[j];
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int v : facet) centre += hull.vertices[v];
  centre /= static_cast<double>(facet.size());
  for (size_t i = 0; i < facet.size() && !region.empty(); ++i) {
    const Eigen::Vector3d& u = hull.vertices[facet[i]];
    const Eigen::Vector3d& v = hull.vertices[facet[(i + 1) % facet.size()]];
    const Eigen::Vector3d side = (v - u).cross(dir);
    if (side.norm() <= tol * (v - u).norm()) continue;  // an edge along dir bounds nothing
    Plane plane = plane_through(side.normalized(), u);
    if (plane.signed_distance(centre) > 0.0) plane = {-plane.normal, -plane.offset};
    region = clip_polygon(region, plane, tol);
  }
  return region;
}

Eigen::Vector3d centroid(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) c += p;
  return c / static_cast<double>(points.size());
}

} // namespace

FreeSpaceSweep front_space_sweep(const std::vector<Eigen::Vector3d>& corners, const Eigen::Vector3d& normal,
                                 double reach, double tol) {
  FreeSpaceSweep sweep;
  sweep.direction = normal;
  sweep.enclosed_allowed = true;
  const Eigen::Vector3d centre = (corners[0] + corners[1] + corners[2]) / 3.0;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d& a = corners[k];
    const Eigen::Vector3d& b = corners[(k + 1) % 3];
    Eigen::Vector3d out = (b - a).cross(normal).normalized();
    if (out.dot(centre - a) > 0.0) out = -out;
    sweep.planes.push_back(plane_through(out, a));
    sweep.insets.push_back(0.0);
  }
  sweep.start = plane_through(-normal, corners[0]);
  sweep.planes.push_back(sweep.start);
  sweep.insets.push_back(-tol);
  sweep.planes.push_back(plane_through(normal, corners[0] + reach * normal));
  sweep.insets.push_back(0.0);
  for (const Eigen::Vector3d& c : corners) {
    sweep.corners.push_back(c);
    sweep.corners.push_back(c + reach * normal);
  }
  return sweep;
}

FreeSpaceSweep opening_sweep(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& inner,
                             const Eigen::Vector3d& face_normal, double reach, double tol) {
  FreeSpaceSweep sweep;
  const Eigen::Vector3d along = (p1 - p0).normalized();
  Eigen::Vector3d out = along.cross(face_normal).normalized();
  if (out.dot(inner - p0) > 0.0) out = -out;
  sweep.direction = out;
  // A strip in the face's plane: kept within tol of it either side.
  sweep.planes = {plane_through(face_normal, p0), plane_through(-face_normal, p0), plane_through(along, p1),
                  plane_through(-along, p0)};
  sweep.insets = {-tol, -tol, 0.0, 0.0};
  sweep.start = plane_through(-out, p0);
  sweep.planes.push_back(sweep.start);
  sweep.insets.push_back(-tol);
  sweep.planes.push_back(plane_through(out, p0 + reach * out));
  sweep.insets.push_back(0.0);
  sweep.corners = {p0, p1, p1 + reach * out, p0 + reach * out};
  return sweep;
}

bool sweep_enters_hull(const FreeSpaceSweep& sweep, const ConvexPolytope& hull, const std::vector<Plane>& face_planes,
                       double tol, const SegmentBlocked& blocked) {
  // The witness ray through `region` (in the entry facet): reaching deeper
  // than tol, with nothing in its way from the base.
  const auto witness = [&](const std::vector<Eigen::Vector3d>& region) {
    const Eigen::Vector3d entry = centroid(region);
    if (!ray_entry(hull.planes, entry, sweep.direction, tol)) return false;
    const Eigen::Vector3d base = entry + sweep.start.signed_distance(entry) * sweep.direction;
    return !blocked || !blocked(base, entry);
  };
  if (separated(sweep, hull, tol)) return false;
  const Eigen::Vector3d& dir = sweep.direction;
  std::vector<Eigen::Vector3d> part;
  for (size_t k = 0; k < hull.facets.size(); ++k) {
    // The sweep enters through facets it meets from their outer side.
    if (hull.planes[k].normal.dot(dir) >= 0.0) continue;
    part.clear();
    for (int v : hull.facets[k]) part.push_back(hull.vertices[v]);
    for (size_t i = 0; i < sweep.planes.size() && !part.empty(); ++i)
      part = clip_polygon(part, sweep.planes[i], sweep.insets[i]);
    if (part.empty()) continue;
    // Met from the front away from the base, a face of the patch ends the
    // free space there; met at the base (a face coincident with it, facing
    // the other way) it does not.
    const double t = -sweep.start.signed_distance(centroid(part));
    if (t > tol && facet_carries_face(hull, k, face_planes, tol)) continue;
    if (!sweep.enclosed_allowed) {
      if (witness(part)) return true;
      continue;
    }
    for (size_t j = 0; j < hull.facets.size(); ++j) {
      if (hull.planes[j].normal.dot(dir) <= 0.0 || facet_carries_face(hull, j, face_planes, tol)) continue;
      const std::vector<Eigen::Vector3d> through = leaving_through(part, hull, j, dir, tol);
      if (!through.empty() && witness(through)) return true;
    }
  }
  return false;
}

bool mesh_blocks_segment(const SceneIndex& index, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                         std::vector<int>& scratch) {
  const Mesh& mesh = index.mesh();
  const double tol = index.tol();
  Aabb box;
  box.extend(from);
  box.extend(to);
  scratch.clear();
  index.face_tree.overlapping(grown(box, tol), scratch);
  for (int g : scratch) {
    if (index.prepared->connectivity.zero_area[g]) continue;
    const Eigen::Vector3i& t = mesh.triangles[g];
    const Eigen::Vector3d& n = index.face_normals[g];
    const double d0 = n.dot(from - mesh.positions[t[0]]), d1 = n.dot(to - mesh.positions[t[0]]);
    if (!((d0 > tol && d1 <= tol) || (d0 < -tol && d1 >= -tol))) continue;
    const Eigen::Vector3d crossing = from + (to - from) * std::clamp(d0 / (d0 - d1), 0.0, 1.0);
    bool inside = true;
    for (int k = 0; k < 3 && inside; ++k) {
      const Eigen::Vector3d& a = mesh.positions[t[k]];
      const Eigen::Vector3d& b = mesh.positions[t[(k + 1) % 3]];
      inside = (b - a).cross(n).normalized().dot(crossing - a) <= tol;
    }
    if (inside) return true;
  }
  return false;
}

bool sheet_enters_interior(const std::vector<Plane>& planes, const std::vector<Eigen::Vector3d>& sheet, double tol) {
  return !clip_to_planes(sheet, planes, tol).empty();
}

bool triangle_enters_interior(const std::vector<Plane>& planes, const std::vector<Eigen::Vector3d>& corners,
                              double tol) {
  for (const Plane& plane : planes) {
    bool beyond = true;
    for (const Eigen::Vector3d& c : corners) beyond &= plane.signed_distance(c) > -tol;
    if (beyond) return false;
  }
  return !clip_to_planes(corners, planes, tol).empty();
}

bool bar_crosses_polygon(const FlatPolygon& polygon, const BoundaryBar& bar, double tol) {
  if (!bar.is_sheet()) {
    const double da = polygon.plane.signed_distance(bar.a);
    const double db = polygon.plane.signed_distance(bar.b);
    if ((da > tol && db > tol) || (da < -tol && db < -tol)) return false;
    if (std::abs(da - db) <= tol) return false;
    const Eigen::Vector3d crossing = bar.a + (bar.b - bar.a) * (da / (da - db));
    return deepest_signed_distance(polygon.sides, crossing) < -tol;
  }
  // A sheet crosses only when it reaches beyond tol on both sides: one that
  // ends on the plane (a door jamb's sheet standing on the floor that runs
  // through the doorway) touches it and closes nothing.
  const std::vector<Eigen::Vector3d> sheet = bar.outline();
  double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
  for (const Eigen::Vector3d& p : sheet) {
    lowest = std::min(lowest, polygon.plane.signed_distance(p));
    highest = std::max(highest, polygon.plane.signed_distance(p));
  }
  if (lowest >= -tol || highest <= tol) return false;
  std::vector<Eigen::Vector3d> on_plane = clip_polygon(sheet, polygon.plane, -tol);
  on_plane = clip_polygon(on_plane, {-polygon.plane.normal, -polygon.plane.offset}, -tol);
  return !clip_to_planes(on_plane, polygon.sides, tol).empty();
}

} // namespace hullcover
