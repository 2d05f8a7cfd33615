#include "allowance_judge.h"

#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/geometry/planar_hull.h"
#include "hullcover/geometry/tolerances.h"
#include "hullcover/geometry/triangle_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

namespace hullcover::validate::probe {
namespace {

// The largest value a 1-Lipschitz function can take between two points
// `length` apart whose values are at most `a` and `b`.
double lipschitz_max(double a, double b, double length) { return 0.5 * (a + b + length); }
// The smallest, for values at least `a` and `b`.
double lipschitz_min(double a, double b, double length) { return 0.5 * (a + b - length); }

// Everything the bisection keeps between intervals: a stack instead of
// recursion, so a long ray cannot run the call stack out.
struct Interval {
  Sample a, b;
};

// The nearest of `world`'s hulls to point p, as a sphere of radius tol sees
// it: the query shape must have a size.
bvh::DistanceResult distance_from(const bvh::HullWorld& world, const Eigen::Vector3d& p, double tol) {
  bvh::DistanceResult r;
  const bvh::DistanceRequest request{bvh::QueryShape::sphere(tol), Eigen::Isometry3d(Eigen::Translation3d(p))};
  if (!world.distance(request, r).ok()) throw std::runtime_error("point distance query failed");
  return r;
}

// What a sphere of radius tol at p tells of p's distance: exact while apart
// (its gap plus tol), "within tol" when it touches, infinite when nothing
// was found.
DistanceBounds bounds_of(const bvh::DistanceResult& r, double tol) {
  if (r.hull < 0) return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  if (r.touching) return {0.0, tol};
  return {r.distance + tol, r.distance + tol};
}

std::vector<Aabb> hull_boxes(const bvh::HullWorld& hulls) {
  std::vector<Aabb> boxes;
  for (const bvh::RuntimeHull& h : hulls.hulls()) boxes.push_back(h.box);
  return boxes;
}

// The part of start + t dir, t in [from, to], behind every plane moved out
// by `grow`: it holds every point within `grow` of the hull (and more, near
// its edges and corners). Empty (from > to) when there is none.
std::pair<double, double> within_grown_planes(const std::vector<Plane>& planes, const Eigen::Vector3d& start,
                                              const Eigen::Vector3d& dir, double from, double to, double grow) {
  for (const Plane& p : planes) {
    const double at_start = p.signed_distance(start) - grow, rate = p.normal.dot(dir);
    if (rate == 0.0) {
      if (at_start > 0.0) return {1.0, 0.0};
      continue;
    }
    const double crossing = -at_start / rate;
    if (rate > 0.0)
      to = std::min(to, crossing);
    else
      from = std::max(from, crossing);
    if (from > to) break;
  }
  return {from, to};
}

// The point of `interior` nearest `c`: c itself inside it, else the nearest
// point of its facet polygons (each fanned into triangles). Any point found
// lies in the interior (up to rounding); infinity away when it is empty.
Eigen::Vector3d nearest_interior_point(const HullInterior& interior, const Eigen::Vector3d& c) {
  if (interior.empty()) return Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  if (deepest_signed_distance(interior.planes, c) <= 0.0) return c;
  Eigen::Vector3d best = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  double best2 = std::numeric_limits<double>::infinity();
  for (const std::vector<Eigen::Vector3d>& facet : interior.facets)
    for (size_t i = 2; i < facet.size(); ++i) {
      const Eigen::Vector3d q = closest_point_on_triangle(c, facet[0], facet[i - 1], facet[i]);
      if ((q - c).squaredNorm() < best2) best2 = (q - c).squaredNorm(), best = q;
    }
  return best;
}

// Counts a ray out of evaluations, and keeps where the first one was.
void note_undecided(const ProbeRay& ray, const Eigen::Vector3d& at, AllowanceReport& out) {
  if (out.undecided++ == 0) out.first_undecided = {at, ray.face, ray.opening};
}

} // namespace

AllowanceJudge::AllowanceJudge(const PreparedMesh& prepared, const bvh::TriangleWorld& triangles,
                               const bvh::HullWorld& hulls, const std::vector<double>& hull_tolerance,
                               const AllowanceOptions& options)
    : prepared_(prepared), hulls_(hulls), hull_tree_(hull_boxes(hulls)), enclosed_(prepared, triangles),
      options_(options) {
  const Mesh& mesh = prepared.mesh;
  std::vector<bvh::RuntimeHull> faces;
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (prepared.connectivity.zero_area[f]) continue;
    const Eigen::Vector3i& t = mesh.triangles[f];
    const std::vector<Eigen::Vector3d> corners = {mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]};
    faces.push_back(bvh::flat_triangle_hull(corners[0], corners[1], corners[2]));
    face_of_.push_back(static_cast<int>(f));
  }
  Result<std::shared_ptr<const bvh::HullWorld>> world = bvh::HullWorld::build(faces);
  if (!world.ok()) throw std::runtime_error("the mesh's faces as flat hulls: " + world.status().message());
  mesh_ = std::move(world).value();
  // What a ball must reach into to take space: each hull shrunk by the
  // probe's stand-off and the tolerance (the margin balls_over allows).
  if (options_.agent_radius)
    for (size_t h = 0; h < hulls.hulls().size(); ++h)
      interiors_.push_back(hull_interior(hulls.hulls()[h].shape, (kRayStandOffInTolerances + 1.0) * hull_tolerance[h]));
}

DistanceBounds AllowanceJudge::to_mesh(const Eigen::Vector3d& p, double tol, int* face) const {
  const bvh::DistanceResult r = distance_from(*mesh_, p, tol);
  if (face) *face = r.hull < 0 ? -1 : face_of_[r.hull];
  return bounds_of(r, tol);
}

DistanceBounds AllowanceJudge::to_hulls(const Eigen::Vector3d& p, double tol, int& hull,
                                        Eigen::Vector3d& nearest) const {
  const bvh::DistanceResult r = distance_from(hulls_, p, tol);
  hull = r.hull;
  nearest = r.on_world;
  return bounds_of(r, tol);
}

void AllowanceJudge::judge(const ProbeRay& ray, const Eigen::Vector3d& start, double length, double stand_off,
                           const std::vector<std::pair<std::pair<double, double>, int>>& stretches,
                           AllowanceReport& out) const {
  const double tol = prepared_.face_tolerance(ray.face);
  // The stretches run from the ray's origin (the strict probe judges hulls
  // from there); the balls from `start`, the stand-off.
  for (const auto& [stretch, hull] : stretches)
    farthest_lost(ray, ray.origin, stretch.first, stretch.second, hull, tol, out);
  if (const std::optional<double> r = options_.agent_radius) {
    // Nearer than r - stand-off to its own face, no point of the ray has
    // clearance r.
    const double from = std::max(0.0, *r - stand_off);
    if (from < length) reachable_balls(ray, start, from, length, tol, out);
  }
}

// The farthest point of stretch [from, to] from the mesh, within tol; with
// E, also whether some point lies farther than E + tol.
void AllowanceJudge::farthest_lost(const ProbeRay& ray, const Eigen::Vector3d& start, double from, double to, int hull,
                                   double tol, AllowanceReport& out) const {
  ++out.lost_stretches;
  // With E the stretch is judged against E + tol; with r alone only
  // measured (an infinite limit is never broken).
  const double limit = options_.max_deviation ? *options_.max_deviation + tol : std::numeric_limits<double>::infinity();
  const auto sample = [&](double t) {
    Sample s;
    s.t = t;
    s.mesh = to_mesh(start + t * ray.direction, tol, &s.face);
    return s;
  };
  double best = -1.0;
  Sample best_sample;
  const auto keep = [&](const Sample& s) {
    if (s.mesh.low > best) best = s.mesh.low, best_sample = s;
  };
  std::vector<Interval> open = {{sample(from), sample(to)}};
  keep(open.back().a);
  keep(open.back().b);
  int evaluations = 2;
  std::optional<double> given_up_at; // where the interval being halved began
  while (!open.empty()) {
    const Interval i = open.back();
    open.pop_back();
    const double length = i.b.t - i.a.t;
    const double highest = most_clear_between(start, ray.direction, i.a, i.b);
    // Done with this interval once it cannot beat the best by more than
    // tol, and (with a bound to judge) cannot break it, or it already broke.
    const bool judged = highest <= limit || best > limit;
    if ((highest <= best + tol && judged) || length <= tol) continue;
    if (++evaluations > options_.max_evaluations_per_ray) {
      given_up_at = i.a.t;
      break;
    }
    const Sample mid = sample(0.5 * (i.a.t + i.b.t));
    keep(mid);
    open.push_back({i.a, mid});
    open.push_back({mid, i.b});
  }
  // Out of evaluations matters only where the stretch is judged; measured
  // alone, the figure is a lower bound then.
  if (given_up_at && std::isfinite(limit)) note_undecided(ray, start + *given_up_at * ray.direction, out);
  if (best > limit) ++out.beyond_deviation;
  if (best > out.max_lost_deviation) {
    out.max_lost_deviation = best;
    out.farthest_point = start + best_sample.t * ray.direction;
    out.farthest_face = ray.face;
    out.farthest_hull = hull;
  }
}

// The stretches of [from, to] within r of some hull (a superset: each
// hull's planes moved out by r), merged: the only places a ball can break.
std::vector<std::pair<double, double>> AllowanceJudge::near_hulls(const Eigen::Vector3d& start,
                                                                  const Eigen::Vector3d& dir, double from,
                                                                  double to) const {
  const double grow = *options_.agent_radius;
  std::vector<std::pair<double, double>> near;
  hull_tree_.nearest_along_segment(start + from * dir, start + to * dir, grow, 0.0, [&](int h) {
    const auto stretch = within_grown_planes(hulls_.hulls()[h].shape.planes, start, dir, from, to, grow);
    if (stretch.first <= stretch.second) near.push_back(stretch);
    return std::numeric_limits<double>::infinity(); // visit every hull along the segment
  });
  std::sort(near.begin(), near.end());
  std::vector<std::pair<double, double>> merged;
  for (const auto& s : near)
    if (!merged.empty() && s.first <= merged.back().second)
      merged.back().second = std::max(merged.back().second, s.second);
    else
      merged.push_back(s);
  return merged;
}

// Where the ball of radius r around c meets a hull deeper than the margin,
// at the point of each hull's interior nearest c, in free space? The
// distance query only says the ball comes within the margin of a hull's
// boundary; a thin hull (a wedge's edge) may hold no point that deep, and a
// point the ball reaches just under a face's edge would be judged on that
// face's ray by the ray casts' tolerance. Judged at a point genuinely inside.
AllowanceJudge::BallReach AllowanceJudge::ball_takes_free_space(const Eigen::Vector3d& c, double r, double tol) const {
  std::vector<int> near;
  Aabb around;
  around.extend(c);
  hull_tree_.overlapping(grown(around, r), near);
  BallReach reach = BallReach::not_deep;
  for (int h : near) {
    const Eigen::Vector3d q = nearest_interior_point(interiors_[h], c);
    if (!((q - c).norm() < r)) continue;
    if (!enclosed_.holds(q, tol)) return BallReach::free;
    reach = BallReach::enclosed;
  }
  return reach;
}

// The most clearance any point between samples a and b can have: the
// Lipschitz bound, or, tighter, the distance to either end's nearest face,
// which is convex along the ray (so at most its larger end value). A ray
// running along a wall at a steady distance is settled at once.
double AllowanceJudge::most_clear_between(const Eigen::Vector3d& start, const Eigen::Vector3d& dir, const Sample& a,
                                          const Sample& b) const {
  double most = lipschitz_max(a.mesh.high, b.mesh.high, b.t - a.t);
  const auto to_face = [&](int f, double t) {
    const Eigen::Vector3i& tri = prepared_.mesh.triangles[f];
    const std::vector<Eigen::Vector3d>& x = prepared_.mesh.positions;
    const Eigen::Vector3d p = start + t * dir;
    return (closest_point_on_triangle(p, x[tri[0]], x[tri[1]], x[tri[2]]) - p).norm();
  };
  if (a.face >= 0) most = std::min(most, std::max(a.mesh.high, to_face(a.face, b.t)));
  if (b.face >= 0) most = std::min(most, std::max(b.mesh.high, to_face(b.face, a.t)));
  return most;
}

// Every centre on [from, to] with clearance >= r must lie at least r - tol
// from every hull (unless the ball reaches in only where the strict
// definition's space is enclosed). The first centre that breaks it ends the ray.
void AllowanceJudge::reachable_balls(const ProbeRay& ray, const Eigen::Vector3d& start, double from, double to,
                                     double tol, AllowanceReport& out) const {
  ++out.centre_rays;
  int evaluations = 0;
  for (const auto& [a, b] : near_hulls(start, ray.direction, from, to)) {
    const long lost = out.reach_lost, undecided = out.undecided;
    balls_over(ray, start, a, b, tol, evaluations, out);
    if (out.reach_lost != lost || out.undecided != undecided) return;
  }
}

void AllowanceJudge::balls_over(const ProbeRay& ray, const Eigen::Vector3d& start, double from, double to, double tol,
                                int& evaluations, AllowanceReport& out) const {
  const double r = *options_.agent_radius;
  // A centre nearer any hull than this puts its ball deeper than tol into it
  // beyond the probe's stand-off: the strict definition's rays start that
  // far off a face, so a ball resting on the face may meet a hull that
  // lies as far above it (and a face may lie that deep inside its hull).
  const double needed = r - (kRayStandOffInTolerances + 1.0) * tol;
  const auto sample = [&](double t) {
    ++evaluations;
    Sample s;
    s.t = t;
    const Eigen::Vector3d c = start + t * ray.direction;
    s.mesh = to_mesh(c, tol, &s.face);
    s.hulls = to_hulls(c, tol, s.hull, s.nearest);
    return s;
  };
  // A centre whose ball reaches deeper than tol into a hull, in space the
  // strict definition calls free: reported, and the ray is done.
  const auto breaks = [&](const Sample& s) {
    if (!(s.mesh.low >= r && s.hulls.high < needed)) return false;
    const Eigen::Vector3d c = start + s.t * ray.direction;
    switch (ball_takes_free_space(c, r, tol)) {
      case BallReach::not_deep: return false;
      case BallReach::enclosed: ++out.enclosed_balls; return false;
      case BallReach::free: break;
    }
    ++out.reach_lost;
    const double depth = r - s.hulls.high;
    if (depth > out.deepest_reach.depth) out.deepest_reach = {c, ray.face, s.hull, depth, s.mesh.low, ray.opening};
    return true;
  };
  std::vector<Interval> open = {{sample(from), sample(to)}};
  for (const Sample& s : {open.back().a, open.back().b})
    if (breaks(s)) return;
  while (!open.empty()) {
    const Interval i = open.back();
    open.pop_back();
    const double length = i.b.t - i.a.t;
    const double most_clear = most_clear_between(start, ray.direction, i.a, i.b);
    const bool no_clear_centre = most_clear < r;
    const bool far_from_hulls = lipschitz_min(i.a.hulls.low, i.b.hulls.low, length) >= needed;
    if (no_clear_centre || far_from_hulls || length <= tol) continue;
    if (evaluations >= options_.max_evaluations_per_ray) {
      note_undecided(ray, start + i.a.t * ray.direction, out);
      return;
    }
    const Sample mid = sample(0.5 * (i.a.t + i.b.t));
    if (breaks(mid)) return;
    open.push_back({i.a, mid});
    open.push_back({mid, i.b});
  }
}

void add_allowance_figures(AllowanceReport& total, const AllowanceReport& part) {
  total.lost_stretches += part.lost_stretches;
  total.beyond_deviation += part.beyond_deviation;
  total.centre_rays += part.centre_rays;
  total.reach_lost += part.reach_lost;
  total.enclosed_balls += part.enclosed_balls;
  if (total.undecided == 0 && part.undecided > 0) total.first_undecided = part.first_undecided;
  total.undecided += part.undecided;
  if (part.max_lost_deviation > total.max_lost_deviation) {
    total.max_lost_deviation = part.max_lost_deviation;
    total.farthest_point = part.farthest_point;
    total.farthest_face = part.farthest_face;
    total.farthest_hull = part.farthest_hull;
  }
  if (part.deepest_reach.depth > total.deepest_reach.depth) total.deepest_reach = part.deepest_reach;
}

} // namespace hullcover::validate::probe
