#include "hullcover/lib/exact_conditions.h"

#include "hullcover/lib/mesh_ray.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace hullcover {
namespace {

Plane plane_through(const Eigen::Vector3d& normal, const Eigen::Vector3d& point) {
  return {normal, normal.dot(point)};
}

// Where the ray from `origin` along unit `dir` first lies strictly behind
// every plane (of an interior, already shrunk by tol), if it ever does
// (Cyrus-Beck on t >= 0).
std::optional<double> ray_entry(const std::vector<Plane>& planes, const Eigen::Vector3d& origin,
                                const Eigen::Vector3d& dir) {
  double enter = 0.0, leave = std::numeric_limits<double>::infinity();
  for (const Plane& plane : planes) {
    const double start = plane.signed_distance(origin);  // must become < 0
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

// Quick rejection: a plane of the interior with every corner of the sweep
// on its far side, or a plane of the sweep with the whole interior beyond.
bool separated(const FreeSpaceSweep& sweep, const HullInterior& interior) {
  for (const Plane& plane : interior.planes) {
    bool all_out = true;
    for (const Eigen::Vector3d& c : sweep.corners) all_out &= plane.signed_distance(c) >= 0.0;
    if (all_out) return true;
  }
  for (size_t i = 0; i < sweep.planes.size(); ++i) {
    bool all_out = true;
    for (const std::vector<Eigen::Vector3d>& facet : interior.facets)
      for (const Eigen::Vector3d& v : facet) all_out &= sweep.planes[i].signed_distance(v) + sweep.insets[i] > 0.0;
    if (all_out) return true;
  }
  return false;
}

// The outward planes of the column that convex polygon `outline` sweeps
// along `dir` (edges running along dir bound nothing and are skipped).
std::vector<Plane> column_planes(const std::vector<Eigen::Vector3d>& outline, const Eigen::Vector3d& dir, double tol) {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& v : outline) centre += v;
  centre /= static_cast<double>(outline.size());
  std::vector<Plane> planes;
  for (size_t i = 0; i < outline.size(); ++i) {
    const Eigen::Vector3d& u = outline[i];
    const Eigen::Vector3d& v = outline[(i + 1) % outline.size()];
    const Eigen::Vector3d side = (v - u).cross(dir);
    if (side.norm() <= tol * (v - u).norm()) continue;
    Plane plane = plane_through(side.normalized(), u);
    if (plane.signed_distance(centre) > 0.0) plane = {-plane.normal, -plane.offset};
    planes.push_back(plane);
  }
  return planes;
}

// The part of `region` from which rays along `dir` leave the interior
// through its facet j: `region` clipped to facet j's column along dir.
std::vector<Eigen::Vector3d> leaving_through(const std::vector<Eigen::Vector3d>& region, const HullInterior& interior,
                                             size_t j, const Eigen::Vector3d& dir, double tol) {
  return clip_polygon_to_planes(region, column_planes(interior.facets[j], dir, tol), 0.0);
}

// `region` cut along the shadow (the column along dir) of a triangle: the
// part inside it and the parts beside each of its sides (no empty pieces).
// The triangle is grown by tol in its plane, as rays meet it (mesh_ray.h).
struct ShadowSplit {
  std::vector<Eigen::Vector3d> inside;
  std::vector<std::vector<Eigen::Vector3d>> beside;
};

ShadowSplit split_by_shadow(const std::vector<Eigen::Vector3d>& region, const std::vector<Eigen::Vector3d>& triangle,
                            const Eigen::Vector3d& dir, double tol) {
  const Eigen::Vector3d normal = (triangle[1] - triangle[0]).cross(triangle[2] - triangle[0]).normalized();
  ShadowSplit split;
  split.inside = region;
  for (Plane plane : column_planes(triangle, dir, tol)) {
    // The side's edge moved out by tol in the triangle's plane moves the
    // column's side by tol times the cosine between the two outward
    // normals (the edge's, in the plane, is the side's projected into it).
    const double across = plane.normal.dot(normal);
    plane.offset += tol * std::sqrt(std::max(0.0, 1.0 - across * across));
    std::vector<Eigen::Vector3d> beside = clip_polygon(split.inside, {-plane.normal, -plane.offset}, 0.0);
    if (beside.size() >= 3) split.beside.push_back(std::move(beside));
    split.inside = clip_polygon(split.inside, plane, 0.0);
  }
  if (split.inside.size() < 3) split.inside.clear();
  return split;
}

double polygon_area(const std::vector<Eigen::Vector3d>& polygon) {
  Eigen::Vector3d twice = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < polygon.size(); ++i) twice += polygon[i].cross(polygon[(i + 1) % polygon.size()]);
  return 0.5 * twice.norm();
}

Eigen::Vector3d centroid(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) c += p;
  return c / static_cast<double>(points.size());
}

// Witness rays sit on a grid of this many steps a side per fan triangle of
// a region, pulled this fraction of the way toward its middle.
constexpr int kWitnessGridSteps = 2;
constexpr double kWitnessInset = 0.05;

// What one witness ray found: whether it loses space, and the face that
// kept it from doing so (met before the hull, or met from behind inside
// it), -1 for none.
struct WitnessRay {
  bool loses = false;
  int deciding_face = -1;
  double enclosed_at = 0.0;  ///< where an enclosed ray met its face, from the base; 0 when not enclosed
};

// The probe's verdict on the sweep's ray through `point`: it starts on the
// base (standing off it like the probe's rays), runs to its first mesh hit
// or the reach, and loses space when it lies deeper than tol inside the
// hull on the way - unless it first meets a face from behind (enclosed
// space), where the sweep allows that.
WitnessRay witness_ray(const SceneIndex& index, const FreeSpaceSweep& sweep, const HullInterior& interior,
                       const Eigen::Vector3d& point, std::vector<int>& scratch) {
  const double tol = index.tol();
  const Eigen::Vector3d& dir = sweep.direction;
  const Eigen::Vector3d base = point + sweep.start.signed_distance(point) * dir;
  const double stand_off = kRayStandOffInTolerances * tol;
  const std::optional<double> inside_from = ray_entry(interior.planes, base + stand_off * dir, dir);
  if (!inside_from) return {};
  const double enter = stand_off + *inside_from;
  if (enter > sweep.reach) return {};
  // The mesh ends the free space before the hull: most rays, found on a
  // short stretch.
  if (const std::optional<MeshRayHit> hit = first_mesh_hit(index, base, dir, stand_off, enter, scratch))
    return {false, hit->face};
  if (!sweep.enclosed_allowed) return {true, -1};
  const std::optional<MeshRayHit> hit = first_mesh_hit(index, base, dir, enter, index.prepared->tolerance.diagonal, scratch);
  // Enclosed space, when the first face is met from behind.
  if (hit && hit->from_behind) return {false, hit->face, hit->t};
  return {true, -1};
}

// How many times a region is cut along the shadow of a face its witnesses
// met, at most.
constexpr int kShadowSplits = 3;

bool pieces_lose_space(const SceneIndex& index, const FreeSpaceSweep& sweep, const HullInterior& interior,
                       ShadowSplit split, std::vector<int>& scratch, int splits_left);

// A region of rays ends differently where different faces stand in their
// way: judged by rays on a grid over it (each fan triangle from its middle
// cut kWitnessGridSteps times a side), pulled in off its edges, where the
// mesh's own edges lie. Where a face that kept witnesses from losing space
// does not shadow the whole region, the region is cut along that shadow's
// sides and each piece judged again, so a face covering only part of it
// cannot speak for the rest.
bool region_loses_space(const SceneIndex& index, const FreeSpaceSweep& sweep, const HullInterior& interior,
                        const std::vector<Eigen::Vector3d>& region, std::vector<int>& scratch,
                        int splits_left = kShadowSplits) {
  const double tol = index.tol();
  std::vector<int> deciding;
  double enclosed_to = 0.0;
  const auto judge = [&](const Eigen::Vector3d& point) {
    const WitnessRay ray = witness_ray(index, sweep, interior, point, scratch);
    enclosed_to = std::max(enclosed_to, ray.enclosed_at);
    if (ray.deciding_face >= 0 && std::find(deciding.begin(), deciding.end(), ray.deciding_face) == deciding.end())
      deciding.push_back(ray.deciding_face);
    return ray.loses;
  };
  const Eigen::Vector3d middle = centroid(region);
  if (judge(middle)) return true;
  constexpr int m = kWitnessGridSteps;
  for (size_t e = 0; e < region.size(); ++e) {
    const Eigen::Vector3d u = region[e] - middle;
    const Eigen::Vector3d v = region[(e + 1) % region.size()] - middle;
    // (i, j) with i + j <= m, i >= 1 (i = 0 is the previous fan triangle's edge).
    for (int i = 1; i <= m; ++i)
      for (int j = 0; i + j <= m; ++j) {
        const Eigen::Vector3d offset = (static_cast<double>(i) * u + static_cast<double>(j) * v) / m;
        if (judge(middle + (1.0 - kWitnessInset) * offset)) return true;
      }
  }
  if (splits_left == 0) return false;
  const Mesh& mesh = index.mesh();
  std::vector<Eigen::Vector3d> triangle(3);
  for (int f : deciding) {
    for (int k = 0; k < 3; ++k) triangle[k] = mesh.positions[mesh.triangles[f][k]];
    ShadowSplit split = split_by_shadow(region, triangle, sweep.direction, tol);
    // f shadows all of it, or (met within tol of its edges) none of it.
    if (split.beside.empty() || split.inside.empty()) continue;
    return pieces_lose_space(index, sweep, interior, std::move(split), scratch, splits_left - 1);
  }
  if (enclosed_to == 0.0) return false;
  // Rays met from behind are enclosed only if no face met from the front
  // comes first: one that shadows part of the region between the hull and
  // the faces closing it, missed by every witness, cuts the region too.
  Aabb column;
  for (const Eigen::Vector3d& c : region) {
    column.extend(c);
    column.extend(c + (sweep.start.signed_distance(c) + enclosed_to) * sweep.direction);
  }
  std::vector<int> near;
  index.face_tree.overlapping(grown(column, tol), near);
  for (int f : near) {
    if (index.face_normals[f].dot(sweep.direction) >= 0.0) continue;  // met from behind, or zero area
    for (int k = 0; k < 3; ++k) triangle[k] = mesh.positions[mesh.triangles[f][k]];
    ShadowSplit split = split_by_shadow(region, triangle, sweep.direction, tol);
    if (split.beside.empty() || split.inside.empty()) continue;
    return pieces_lose_space(index, sweep, interior, std::move(split), scratch, splits_left - 1);
  }
  return false;
}

bool pieces_lose_space(const SceneIndex& index, const FreeSpaceSweep& sweep, const HullInterior& interior,
                       ShadowSplit split, std::vector<int>& scratch, int splits_left) {
  const double tol = index.tol();
  split.beside.push_back(std::move(split.inside));
  for (const std::vector<Eigen::Vector3d>& piece : split.beside)
    if (polygon_area(piece) > tol * tol && region_loses_space(index, sweep, interior, piece, scratch, splits_left))
      return true;
  return false;
}

} // namespace

FreeSpaceSweep front_space_sweep(const std::vector<Eigen::Vector3d>& corners, const Eigen::Vector3d& normal,
                                 double reach, double tol) {
  FreeSpaceSweep sweep;
  sweep.direction = normal;
  // The probe's rays start a stand-off from the face and run the reach
  // from there.
  reach += kRayStandOffInTolerances * tol;
  sweep.reach = reach;
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
  sweep.base = corners;
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
  reach += kRayStandOffInTolerances * tol;
  sweep.reach = reach;
  // A strip in the face's plane: kept within tol of it either side.
  sweep.planes = {plane_through(face_normal, p0), plane_through(-face_normal, p0), plane_through(along, p1),
                  plane_through(-along, p0)};
  sweep.insets = {-tol, -tol, 0.0, 0.0};
  sweep.start = plane_through(-out, p0);
  sweep.planes.push_back(sweep.start);
  sweep.insets.push_back(-tol);
  sweep.planes.push_back(plane_through(out, p0 + reach * out));
  sweep.insets.push_back(0.0);
  sweep.base = {p0, p1};
  sweep.corners = {p0, p1, p1 + reach * out, p0 + reach * out};
  return sweep;
}

HullInterior hull_interior(const ConvexPolytope& hull, double tol) {
  HullInterior interior;
  for (const Plane& p : hull.planes) interior.planes.push_back({p.normal, p.offset - tol});
  // Facet k shrunk: facet k moved in by tol holds it; the other shrunk
  // planes cut it to size - all but those of facets in its own plane (a
  // hull grown point by point keeps coplanar triangles), which would cut it
  // away by rounding. Planes closer than this in direction (1 - cos) differ
  // by less than tol over the hull.
  Aabb box;
  for (const Eigen::Vector3d& v : hull.vertices) box.extend(v);
  const double ratio = tol / std::max((box.max - box.min).norm(), tol);
  const double same_plane_gap = 0.5 * ratio * ratio;
  for (size_t k = 0; k < hull.facets.size(); ++k) {
    std::vector<Eigen::Vector3d> facet;
    for (int v : hull.facets[k]) facet.push_back(hull.vertices[v] - tol * hull.planes[k].normal);
    for (size_t j = 0; j < interior.planes.size() && !facet.empty(); ++j)
      if (j != k && hull.planes[j].normal.dot(hull.planes[k].normal) < 1.0 - same_plane_gap)
        facet = clip_polygon(facet, interior.planes[j], 0.0);
    if (facet.size() < 3) facet.clear();
    interior.facets.push_back(std::move(facet));
  }
  return interior;
}

bool sweep_enters_hull(const SceneIndex& index, const FreeSpaceSweep& sweep, const HullInterior& interior,
                       std::vector<int>& scratch) {
  if (interior.empty() || separated(sweep, interior)) return false;
  const Eigen::Vector3d& dir = sweep.direction;
  std::vector<Eigen::Vector3d> part;
  for (size_t k = 0; k < interior.facets.size(); ++k) {
    // The sweep enters through facets it meets from their outer side.
    if (interior.facets[k].empty() || interior.planes[k].normal.dot(dir) >= 0.0) continue;
    part = interior.facets[k];
    for (size_t i = 0; i < sweep.planes.size() && !part.empty(); ++i)
      part = clip_polygon(part, sweep.planes[i], sweep.insets[i]);
    if (part.empty()) continue;
    if (!sweep.enclosed_allowed) {
      if (region_loses_space(index, sweep, interior, part, scratch)) return true;
      continue;
    }
    // Rays leaving through different facets may end differently: one
    // witness grid per way out.
    for (size_t j = 0; j < interior.facets.size(); ++j) {
      if (interior.facets[j].empty() || interior.planes[j].normal.dot(dir) <= 0.0) continue;
      const std::vector<Eigen::Vector3d> through = leaving_through(part, interior, j, dir, index.tol());
      if (!through.empty() && region_loses_space(index, sweep, interior, through, scratch)) return true;
    }
  }
  return false;
}

bool crossing_face_leaks(const SceneIndex& index, const FreeSpaceSweep& sweep, const HullInterior& interior,
                         std::vector<int>& scratch) {
  if (interior.empty()) return false;
  for (const Plane& plane : interior.planes) {
    bool beyond = true;
    for (const Eigen::Vector3d& c : sweep.base) beyond &= plane.signed_distance(c) > 0.0;
    if (beyond) return false;
  }
  const std::vector<Eigen::Vector3d> inside = clip_polygon_to_planes(sweep.base, interior.planes, 0.0);
  if (inside.empty()) return false;
  for (size_t j = 0; j < interior.facets.size(); ++j) {
    if (interior.facets[j].empty() || interior.planes[j].normal.dot(sweep.direction) <= 0.0) continue;
    const std::vector<Eigen::Vector3d> through = leaving_through(inside, interior, j, sweep.direction, index.tol());
    if (!through.empty() && region_loses_space(index, sweep, interior, through, scratch)) return true;
  }
  return false;
}

bool sheet_enters_interior(const std::vector<Plane>& planes, const std::vector<Eigen::Vector3d>& sheet, double tol) {
  return !clip_polygon_to_planes(sheet, planes, tol).empty();
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
  return meets_polygon_interior(polygon, sheet, tol);
}

} // namespace hullcover
