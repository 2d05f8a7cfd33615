#include "hullcover/validate/behaviour_equivalence.h"

#include "enclosed_space.h"
#include "probe_rays.h"

#include "hullcover/geometry/tolerances.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>

namespace hullcover::validate {
namespace {

// Default proxy size as a fraction of the scene's diagonal.
constexpr double kDefaultProxyRelative = 0.005;
// Contacts compared per pose, deepest first.
constexpr int kContactsCompared = 16;

// Is `p` in accessible space: is the ray from it along `dir` open? The
// probe's rule, the strict definition's (probe::ends_on_backs): enclosed
// only when every face within `tol` of its first hit is met from behind.
// `free_to` is how far along the ray (infinite when it meets nothing).
bool accessible(const bvh::TriangleWorld& triangles, const Mesh& mesh, const Eigen::Vector3d& p,
                const Eigen::Vector3d& dir, double reach, double tol, double& free_to) {
  bvh::RayResult hit;
  free_to = std::numeric_limits<double>::infinity();
  if (!triangles.ray_cast({p, dir, reach}, hit).ok() || !hit.hit) return true;
  free_to = hit.first.t;
  return !probe::ends_on_backs(triangles, mesh, p, dir, hit.first.t, tol);
}

// Samples of a proxy per axis of its bounding box when its reach into a
// solid hull is judged: 9 x 9 x 9 points, of which those inside the proxy
// and deeper than tol in the hull are judged.
constexpr int kReachSamplesPerAxis = 9;

// Points of `shape` at `pose`: a grid over its bounding box, kept where
// inside the shape.
std::vector<Eigen::Vector3d> proxy_samples(const bvh::QueryShape& shape, const Eigen::Isometry3d& pose) {
  Eigen::Vector3d half = shape.half_extents;
  if (shape.kind != bvh::ShapeKind::box) half = Eigen::Vector3d(shape.radius, shape.radius, shape.radius);
  if (shape.kind == bvh::ShapeKind::capsule) half.z() += shape.half_height;
  std::vector<Eigen::Vector3d> samples;
  const int n = kReachSamplesPerAxis;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const Eigen::Vector3d unit(2.0 * i / (n - 1) - 1.0, 2.0 * j / (n - 1) - 1.0, 2.0 * k / (n - 1) - 1.0);
        const Eigen::Vector3d local = unit.cwiseProduct(half);
        if (shape.kind == bvh::ShapeKind::sphere && local.norm() > shape.radius) continue;
        if (shape.kind == bvh::ShapeKind::capsule) {
          const double along = std::clamp(local.z(), -shape.half_height, shape.half_height);
          if ((local - Eigen::Vector3d(0.0, 0.0, along)).norm() > shape.radius) continue;
        }
        samples.push_back(pose * local);
      }
  return samples;
}

// Does the proxy's reach into the hull lie in enclosed space? A proxy can
// pass an opening in a closed object without touching a triangle (a rail
// whose side against a wall is left out, the wall's floor and ceiling
// running on behind it: Red Eclipse's deathtrap), and a hull may fill what
// lies behind such an opening, the strict definition's enclosed space.
//
// Judged where it reaches deepest (the contact point pushed in by the
// depth) and half way there, and, for a hull with an inside deeper than
// tol, at the proxy's sample points: each judged point of a solid hull
// must lie deeper than tol inside it (a contact's normal is the surface's,
// not the smallest push: its depth can run past what the proxy holds
// inside the hull). When no point qualifies, the two along the contact are
// judged as they are. Any judged point free makes the contact lost.
bool reach_is_enclosed(const probe::EnclosedSpace& enclosed, const bvh::RuntimeHull& hull, const bvh::QueryShape& shape,
                       const Eigen::Isometry3d& pose, const bvh::Contact& deepest, double tol) {
  const bool solid = !hull_interior(hull.shape, tol).empty();
  const auto inside = [&](const Eigen::Vector3d& p) { return deepest_signed_distance(hull.shape.planes, p) < -tol; };
  const Eigen::Vector3d inward = -deepest.normal;
  std::vector<Eigen::Vector3d> along; // the deepest point and half way there
  for (const double share : {1.0, 0.5})
    if (share * deepest.depth > tol) along.push_back(deepest.point + share * deepest.depth * inward);
  int judged = 0;
  const auto free_at = [&](const Eigen::Vector3d& p) {
    ++judged;
    return !enclosed.holds(p, tol);
  };
  for (const Eigen::Vector3d& p : along)
    if ((!solid || inside(p)) && free_at(p)) return false;
  if (solid)
    for (const Eigen::Vector3d& p : proxy_samples(shape, pose))
      if (inside(p) && free_at(p)) return false;
  // No point of the proxy found inside the hull (an overlap thinner than
  // the samples' spacing): the points along the contact are judged as they
  // are, so nothing passes unjudged.
  if (judged == 0)
    for (const Eigen::Vector3d& p : along)
      if (free_at(p)) return false;
  return true;
}

} // namespace

Result<BehaviourReport> compare_behaviour(const PreparedMesh& prepared, const bvh::TriangleWorld& triangles,
                                          const bvh::HullWorld& hulls, const BehaviourOptions& options) {
  BehaviourReport report;
  report.size = options.size.value_or(kDefaultProxyRelative * prepared.tolerance.diagonal);
  if (options.proxies < 1 || !(report.size > 0.0) || !std::isfinite(report.size))
    return Status{StatusCode::invalid_argument, "proxies must be at least 1 and their size a positive length"};
  const Mesh& mesh = prepared.mesh;
  std::vector<int> faces;
  for (int f = 0; f < static_cast<int>(mesh.triangles.size()); ++f)
    if (!prepared.connectivity.zero_area[f]) faces.push_back(f);
  if (faces.empty()) return Status{StatusCode::invalid_argument, "the mesh has no face with a surface"};

  std::mt19937_64 rng(options.seed);
  std::uniform_int_distribution<size_t> pick(0, faces.size() - 1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g(0.0, 1.0);
  const double s = report.size;
  double angle_sum = 0.0;
  std::optional<probe::EnclosedSpace> enclosed; // built at the first deep false contact
  try {
    for (int i = 0; i < options.proxies; ++i) {
      const int f = faces[pick(rng)];
      const Eigen::Vector3i& t = mesh.triangles[f];
      double a = u(rng), b = u(rng);
      if (a + b > 1.0) a = 1.0 - a, b = 1.0 - b;
      const Eigen::Vector3d n = triangle_area_vector(mesh, f).normalized();
      const Eigen::Vector3d on_face = mesh.positions[t[0]] + a * (mesh.positions[t[1]] - mesh.positions[t[0]]) +
                                      b * (mesh.positions[t[2]] - mesh.positions[t[0]]);
      // From just touching to 0.5 size into the surface, and up to 1.5 size clear of it.
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      const double lift = s * (2.0 * u(rng) - 0.5);
      pose.translation() = on_face + n * lift;
      pose.linear() =
          Eigen::Quaterniond(Eigen::Vector4d(g(rng), g(rng), g(rng), g(rng)).normalized()).toRotationMatrix();
      const double tol = prepared.face_tolerance(f); // the place's: the pose sits at face f
      const double stand_off = kRayStandOffInTolerances * tol;
      double free_to = 0.0;
      if (!accessible(triangles, mesh, on_face + n * stand_off, n, prepared.tolerance.diagonal, tol, free_to)) continue;
      // Its centre on the face's open front ray: a point of accessible space.
      // One behind the face (a box proxy can sit wholly inside a closed
      // object past the face's edge) touches no triangle yet stands in no
      // free space.
      const bool centre_free = lift > stand_off && lift < stand_off + free_to;
      const bvh::QueryShape shape = i % 3 == 0   ? bvh::QueryShape::sphere(s)
                                    : i % 3 == 1 ? bvh::QueryShape::capsule(0.6 * s, s)
                                                 : bvh::QueryShape::box(Eigen::Vector3d(s, 0.7 * s, 0.5 * s));
      bvh::ContactResult on_triangles, on_hulls;
      if (!triangles.contacts({shape, pose, kContactsCompared}, on_triangles).ok() ||
          !hulls.contacts({shape, pose, kContactsCompared}, on_hulls).ok())
        continue;
      ++report.poses;
      const bool t_touch = !on_triangles.contacts.empty(), h_touch = !on_hulls.contacts.empty();
      if (t_touch && h_touch) {
        ++report.both_touch;
        // The hulls' deepest push against the triangle push nearest to it in
        // direction (a proxy in a corner touches several faces; any of them
        // may be deepest).
        double best = -1.0;
        for (const bvh::Contact& c : on_triangles.contacts)
          best = std::max(best, c.normal.dot(on_hulls.contacts[0].normal));
        const double angle = std::acos(std::clamp(best, -1.0, 1.0)) * 180.0 / M_PI;
        report.max_normal_angle = std::max(report.max_normal_angle, angle);
        angle_sum += angle;
      } else if (t_touch) {
        ++report.missed;
      } else if (h_touch) {
        ++report.false_contacts;
        // A proxy clear of every triangle yet deeper than tol in a hull
        // stands in space the hull takes (docs/definitions-and-proofs.md, "behaviour"): lost
        // when free, allowed when enclosed. Every hull it reaches into is
        // judged, deepest first.
        const bvh::Contact& deepest = on_hulls.contacts[0];
        if (centre_free && deepest.depth > tol) {
          if (!enclosed) enclosed.emplace(prepared, triangles);
          const bvh::Contact* lost = nullptr;
          for (const bvh::Contact& c : on_hulls.contacts)
            if (c.depth > tol && !reach_is_enclosed(*enclosed, hulls.hulls()[c.hull], shape, pose, c, tol)) {
              lost = &c;
              break;
            }
          if (!lost) {
            ++report.enclosed_false_contacts;
          } else {
            ++report.deep_false_contacts;
            if (shape.kind == bvh::ShapeKind::box) ++report.deep_false_boxes;
            if (lost->depth > report.deepest_false.depth)
              report.deepest_false = {lost->hull, f, pose.translation(), lost->point, lost->depth};
          }
        }
        report.max_false_depth = std::max(report.max_false_depth, deepest.depth);
      } else {
        ++report.neither_touches;
      }
    }
  } catch (const std::exception& e) {
    return Status{StatusCode::internal_error, std::string("behaviour comparison failed: ") + e.what()};
  }
  if (report.both_touch > 0) report.mean_normal_angle = angle_sum / report.both_touch;
  return report;
}

} // namespace hullcover::validate
