#include "witness_rays.h"

#include "mesh_ray.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace hullcover::detail {

std::vector<Plane> column_planes(const std::vector<Eigen::Vector3d>& outline, const Eigen::Vector3d& dir) {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& v : outline) centre += v;
  centre /= static_cast<double>(outline.size());
  std::vector<Plane> planes;
  for (size_t i = 0; i < outline.size(); ++i) {
    const Eigen::Vector3d& u = outline[i];
    const Eigen::Vector3d& v = outline[(i + 1) % outline.size()];
    const Eigen::Vector3d side = (v - u).cross(dir);
    if (side.norm() <= kParallelSine * (v - u).norm()) continue;
    Plane plane{side.normalized(), side.normalized().dot(u)};
    if (plane.signed_distance(centre) > 0.0) plane = {-plane.normal, -plane.offset};
    planes.push_back(plane);
  }
  return planes;
}

namespace {

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
  for (Plane plane : column_planes(triangle, dir)) {
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
  const std::optional<MeshRayHit> hit = first_mesh_hit(index, base, dir, enter, index.prepared->tolerance.diagonal, scratch);
  // Enclosed space, when the first face is met from behind.
  if (hit && hit->from_behind) return {false, hit->face, hit->t};
  return {true, -1};
}

bool pieces_lose_space(const SceneIndex& index, const FreeSpaceSweep& sweep, const HullInterior& interior,
                       ShadowSplit split, std::vector<int>& scratch, int splits_left);

bool sampled_region_loses_space(const SceneIndex& index, const FreeSpaceSweep& sweep, const HullInterior& interior,
                                const std::vector<Eigen::Vector3d>& region, std::vector<int>& scratch,
                                int splits_left);

// The face plane's distance t along the sweep's ray through `point` (a
// point where it enters the interior) from the ray's base, and the
// entry's own distance.
struct RayDistances {
  double to_entry = 0.0;
  double to_face = 0.0;
};

RayDistances distances_at(const FreeSpaceSweep& sweep, const Plane& face, const Eigen::Vector3d& point) {
  const double to_entry = -sweep.start.signed_distance(point);
  const Eigen::Vector3d base = point - to_entry * sweep.direction;
  return {to_entry, -face.signed_distance(base) / face.normal.dot(sweep.direction)};
}


// Whether face f keeps every ray through `piece` (inside f's shadow, grown
// as rays meet faces) from losing space, exactly: the distances to the
// entry and to f's plane are affine over the piece, so its corners decide.
// Blocked: f lies between the ray's stand-off and the hull for every corner.
// Enclosed: f lies beyond the entry, met from behind, and no face met from
// the front stands between the entry and f anywhere in the piece (faces met
// from behind there enclose the space as well).
struct Settling {
  bool settled = false;
  int obstacle = -1;  ///< unsettled by this face met from the front in part of the piece; -1 for another reason
};

Settling settle_by_face(const SceneIndex& index, const FreeSpaceSweep& sweep, const std::vector<Eigen::Vector3d>& piece,
                        int f, bool enclosed) {
  const Mesh& mesh = index.mesh();
  const double tol = index.tol();
  const Plane face{index.face_normals[f], index.face_normals[f].dot(mesh.positions[mesh.triangles[f][0]])};
  const double slope = face.normal.dot(sweep.direction);
  if (std::abs(slope) < kSettlingSlope || (enclosed && slope <= 0.0)) return {};
  const double stand_off = kRayStandOffInTolerances * tol;
  double farthest = 0.0;
  for (const Eigen::Vector3d& p : piece) {
    const RayDistances d = distances_at(sweep, face, p);
    if (enclosed ? d.to_face < d.to_entry : (d.to_face < stand_off || d.to_face > d.to_entry)) return {};
    farthest = std::max(farthest, d.to_face);
  }
  if (!enclosed) return {true, -1};
  Aabb column;
  for (const Eigen::Vector3d& p : piece) {
    column.extend(p);
    column.extend(p + (farthest + sweep.start.signed_distance(p)) * sweep.direction);
  }
  std::vector<int> near;
  index.face_tree.overlapping(grown(column, tol), near);
  std::vector<Eigen::Vector3d> triangle(3);
  for (int g : near) {
    if (g == f || index.face_normals[g].dot(sweep.direction) >= 0.0) continue;  // met from behind, or zero area
    for (int k = 0; k < 3; ++k) triangle[k] = mesh.positions[mesh.triangles[g][k]];
    const ShadowSplit split = split_by_shadow(piece, triangle, sweep.direction, tol);
    if (split.inside.empty()) continue;
    const Plane other{index.face_normals[g], index.face_normals[g].dot(triangle[0])};
    if (std::abs(other.normal.dot(sweep.direction)) < kSettlingSlope) return {};
    // g stands clear when it lies beyond f, or before the entry (there it
    // blocks), over all of its part of the piece.
    bool beyond = true, before = true;
    for (const Eigen::Vector3d& p : split.inside) {
      const double to_other = distances_at(sweep, other, p).to_face;
      const RayDistances d = distances_at(sweep, face, p);
      beyond &= to_other > d.to_face + tol;
      before &= to_other < d.to_entry;
    }
    if (!beyond && !before) return {false, g};
  }
  return {true, -1};
}

} // namespace

bool region_loses_space(const SceneIndex& index, const FreeSpaceSweep& sweep, const HullInterior& interior,
                        const std::vector<Eigen::Vector3d>& region, std::vector<int>& scratch, int splits_left) {
  const WitnessRay ray = witness_ray(index, sweep, interior, centroid(region), scratch);
  if (ray.loses) return true;
  if (ray.deciding_face < 0 || splits_left == 0)
    return sampled_region_loses_space(index, sweep, interior, region, scratch, splits_left);
  // Cut the region along the shadow of the face that decided its middle:
  // inside it, that face decides every ray, exactly; beside it, each piece
  // is a region of its own.
  const Mesh& mesh = index.mesh();
  const double tol = index.tol();
  std::vector<Eigen::Vector3d> triangle(3);
  for (int k = 0; k < 3; ++k) triangle[k] = mesh.positions[mesh.triangles[ray.deciding_face][k]];
  ShadowSplit split = split_by_shadow(region, triangle, sweep.direction, tol);
  if (!split.inside.empty()) {
    const Settling settling = settle_by_face(index, sweep, split.inside, ray.deciding_face, ray.enclosed_at > 0.0);
    if (!settling.settled) {
      if (settling.obstacle < 0 || splits_left == 1)
        return sampled_region_loses_space(index, sweep, interior, split.inside, scratch, splits_left - 1) ||
               pieces_lose_space(index, sweep, interior, {{}, std::move(split.beside)}, scratch, splits_left - 1);
      // A face met from the front in part of the piece: cut along its shadow.
      for (int k = 0; k < 3; ++k) triangle[k] = mesh.positions[mesh.triangles[settling.obstacle][k]];
      ShadowSplit cut = split_by_shadow(split.inside, triangle, sweep.direction, tol);
      if (pieces_lose_space(index, sweep, interior, std::move(cut), scratch, splits_left - 1)) return true;
    }
  }
  return pieces_lose_space(index, sweep, interior, {{}, std::move(split.beside)}, scratch, splits_left - 1);
}

namespace {

// The fallback where a region is not settled exactly: witness rays on a
// grid over it (each fan triangle from its middle cut kWitnessGridSteps
// times a side), pulled in off its edges; where a face that kept witnesses
// from losing space does not shadow it all, or a face met from the front
// shadows part of an enclosed region, it is cut along that shadow and each
// piece judged again.
bool sampled_region_loses_space(const SceneIndex& index, const FreeSpaceSweep& sweep, const HullInterior& interior,
                                const std::vector<Eigen::Vector3d>& region, std::vector<int>& scratch,
                                int splits_left) {
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

} // namespace hullcover::detail
