#include "hullcover/bvh/hull_world.h"

#include "hull_tree.h"
#include "query_guard.h"

#include "hullcover/geometry/point_hull.h"
#include "hullcover/geometry/tolerances.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

namespace hullcover::bvh {

HullWorld::~HullWorld() = default;

Result<std::shared_ptr<const HullWorld>> HullWorld::build(std::vector<RuntimeHull> hulls) {
  using Built = Result<std::shared_ptr<const HullWorld>>;
  return detail::guarded("building the hull world", [&]() -> Built {
    if (hulls.empty()) return Status{StatusCode::invalid_argument, "a hull world needs at least one hull"};
    for (size_t i = 0; i < hulls.size(); ++i) {
      const ConvexPolytope& s = hulls[i].shape;
      bool finite = !s.vertices.empty() && s.facets.size() >= 2 && s.planes.size() >= s.facets.size();
      for (const Eigen::Vector3d& v : s.vertices) finite = finite && v.allFinite();
      for (const Plane& p : s.planes) finite = finite && p.normal.allFinite() && std::isfinite(p.offset);
      if (!finite)
        return Status{StatusCode::invalid_argument, "hull " + std::to_string(i) + " has no facets or non-finite data"};
      if (!hulls[i].surface_planes.empty() && hulls[i].surface_planes.size() != s.planes.size())
        return Status{StatusCode::invalid_argument,
                      "hull " + std::to_string(i) + " has surface flags neither absent nor one per plane"};
    }
    std::shared_ptr<HullWorld> world(new HullWorld());
    world->hulls_ = std::move(hulls);
    world->tree_ = std::make_unique<detail::HullTree>(world->hulls_);
    return std::shared_ptr<const HullWorld>(std::move(world));
  });
}

void HullWorld::candidates(const Aabb& box, std::vector<int>& out) const {
  tree_->find_in_box(box, [&](int h) {
    out.push_back(h);
    return false;
  });
  std::sort(out.begin(), out.end());
}

namespace {
// The capsule's axis end points in the world.
std::pair<Eigen::Vector3d, Eigen::Vector3d> capsule_ends(const QueryShape& s, const Eigen::Isometry3d& pose) {
  const Eigen::Vector3d axis = pose.linear().col(2) * s.half_height;
  return {pose.translation() - axis, pose.translation() + axis};
}

// A query shape placed at its pose, ready for the yes/no test and the
// contact against any number of hulls (a capsule's ends found and a convex
// shape hulled once).
struct PlacedShape {
  const QueryShape& shape;
  const Eigen::Isometry3d& pose;
  Eigen::Vector3d a, b;                // capsule axis ends; a sphere's centre twice
  std::optional<RuntimeHull> convex;  // a convex shape's hull in the world

  bool touches(const RuntimeHull& hull) const {
    switch (shape.kind) {
      case ShapeKind::sphere: return sphere_touches(hull, a, shape.radius);
      case ShapeKind::capsule: return capsule_touches(hull, a, b, shape.radius);
      case ShapeKind::box: return box_touches(hull, pose, shape.half_extents);
      case ShapeKind::convex: return convex_touches(hull, *convex);
    }
    return false;
  }

  std::optional<Contact> contact(const RuntimeHull& hull) const {
    switch (shape.kind) {
      case ShapeKind::sphere: return sphere_contact(hull, a, shape.radius);
      case ShapeKind::capsule: return capsule_contact(hull, a, b, shape.radius);
      case ShapeKind::box: return box_contact(hull, pose, shape.half_extents);
      case ShapeKind::convex: return convex_contact(hull, *convex);
    }
    return std::nullopt;
  }
};
} // namespace

std::optional<RuntimeHull> placed_convex(const QueryShape& shape, const Eigen::Isometry3d& pose) {
  std::vector<Eigen::Vector3d> points;
  for (const Eigen::Vector3d& p : shape.points) points.push_back(pose * p);
  std::optional<ConvexPolytope> hull = convex_hull_of_points(points);
  if (!hull) return std::nullopt;
  return make_runtime_hull(std::move(*hull), 0);
}

// Checks a shape and pose and places the shape (which keeps references to
// both); fails as overlap() documents.
static Status place(const QueryShape& shape, const Eigen::Isometry3d& pose, std::optional<PlacedShape>& placed) {
  if (Status s = check_query_shape(shape, pose); !s.ok()) return s;
  PlacedShape p{shape, pose, pose.translation(), pose.translation(), std::nullopt};
  if (shape.kind == ShapeKind::capsule) std::tie(p.a, p.b) = capsule_ends(shape, pose);
  if (shape.kind == ShapeKind::convex) {
    p.convex = placed_convex(shape, pose);
    if (!p.convex) return {StatusCode::invalid_argument, "the convex query shape has no 3D hull"};
  }
  placed.emplace(std::move(p));
  return Status::success();
}

// Calls visit(h) for the hulls the placed shape may touch, until it returns
// true: the hulls whose boxes meet its box, or for a sphere those within its
// radius.
template <typename Visit>
void find_candidates(const detail::HullTree& tree, const PlacedShape& placed, Visit&& visit) {
  if (placed.shape.kind == ShapeKind::sphere)
    tree.find_near_point(placed.a, placed.shape.radius, visit);
  else
    tree.find_in_box(world_box(placed.shape, placed.pose), visit);
}

Status HullWorld::touches(const OverlapRequest& request, TouchResult& result) const {
  return detail::guarded("touch query", [&]() -> Status {
    result = {};
    std::optional<PlacedShape> placed;
    if (Status s = place(request.shape, request.pose, placed); !s.ok()) return s;
    const auto first_touching = [&](int h) {
      if (!placed->touches(hulls_[h])) return false;
      result.touching = true;
      result.hull = h;
      return true;
    };
    find_candidates(*tree_, *placed, first_touching);
    return Status::success();
  });
}

Status HullWorld::overlap(const OverlapRequest& request, OverlapResult& result) const {
  return detail::guarded("overlap query", [&]() -> Status {
    result.hulls.clear();
    std::optional<PlacedShape> placed;
    if (Status s = place(request.shape, request.pose, placed); !s.ok()) return s;
    find_candidates(*tree_, *placed, [&](int h) {
      if (placed->touches(hulls_[h])) result.hulls.push_back(h);
      return false;
    });
    std::sort(result.hulls.begin(), result.hulls.end());
    return Status::success();
  });
}

Status HullWorld::contacts(const ContactRequest& request, ContactResult& result) const {
  return detail::guarded("contact query", [&]() -> Status {
    result.contacts.clear();
    if (request.max_contacts < 1) return {StatusCode::invalid_argument, "max_contacts must be at least 1"};
    std::optional<PlacedShape> placed;
    if (Status s = place(request.shape, request.pose, placed); !s.ok()) return s;
    find_candidates(*tree_, *placed, [&](int h) {
      if (std::optional<Contact> c = placed->contact(hulls_[h])) {
        c->hull = h;
        result.contacts.push_back(*c);
      }
      return false;
    });
    // Deepest first, equal depths by hull index: a total order, so the
    // answer does not depend on the tree's walk.
    std::sort(result.contacts.begin(), result.contacts.end(), [](const Contact& x, const Contact& y) {
      return x.depth > y.depth || (x.depth == y.depth && x.hull < y.hull);
    });
    if (static_cast<int>(result.contacts.size()) > request.max_contacts) result.contacts.resize(request.max_contacts);
    return Status::success();
  });
}

Status check_ray_request(const RayRequest& request, Eigen::Vector3d& unit_direction) {
  // Guarded: the message is allocated.
  return detail::guarded("checking a ray", [&]() -> Status {
    const double length = request.direction.norm();
    if (!(length > 0.0) || !request.direction.allFinite() || !request.origin.allFinite() ||
        !(request.max_distance >= 0.0))
      return {StatusCode::invalid_argument, "a ray needs a finite origin, a non-zero direction and max_distance >= 0"};
    unit_direction = request.direction / length;
    return Status::success();
  });
}

void HullWorld::cast_checked_ray(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double max_distance,
                                 RayResult& result) const {
  result = {};
  double reach = max_distance;
  tree_->walk_ray(origin, dir.cwiseInverse(), reach, [&](int h, double& best) {
    std::optional<RayHit> hit = ray_hit(hulls_[h], origin, dir, best);
    if (hit && (!result.hit || hit->t < result.first.t || (hit->t == result.first.t && h < result.first.hull))) {
      hit->hull = h;
      result.hit = true;
      result.first = *hit;
      best = hit->t;
    }
  });
}

Status HullWorld::ray_cast(const RayRequest& request, RayResult& result) const {
  return detail::guarded("ray query", [&]() -> Status {
    result = {};
    Eigen::Vector3d dir;
    if (Status s = check_ray_request(request, dir); !s.ok()) return s;
    cast_checked_ray(request.origin, dir, request.max_distance, result);
    return Status::success();
  });
}

Status HullWorld::ray_cast_batch(const std::vector<RayRequest>& requests, std::vector<RayResult>& results) const {
  return detail::guarded("ray batch", [&]() -> Status {
    results.clear();
    results.resize(requests.size());
    std::vector<Eigen::Vector3d> directions(requests.size());
    for (size_t i = 0; i < requests.size(); ++i)
      if (Status s = check_ray_request(requests[i], directions[i]); !s.ok()) {
        results.clear();
        return {s.code(), "ray " + std::to_string(i) + " of the batch: " + s.message()};
      }
    for (size_t i = 0; i < requests.size(); ++i)
      cast_checked_ray(requests[i].origin, directions[i], requests[i].max_distance, results[i]);
    return Status::success();
  });
}

std::function<double(int, Eigen::Vector3d&, Eigen::Vector3d&)> HullWorld::separation_from(
    const QueryShape& s, const Eigen::Isometry3d& pose) const {
  // Spheres and capsules: exact closest points to the axis.
  if (s.kind == ShapeKind::sphere || s.kind == ShapeKind::capsule) {
    const auto [a, b] = s.kind == ShapeKind::capsule ? capsule_ends(s, pose)
                                                     : std::make_pair(pose.translation(), pose.translation());
    return [this, a = a, b = b, radius = s.radius](int h, Eigen::Vector3d& on_world, Eigen::Vector3d& on_shape) {
      const ClosestPoints c = closest_to_segment(hulls_[h], a, b);
      on_world = c.on_hull;
      on_shape = c.distance > 0.0 ? Eigen::Vector3d(c.on_other + (c.on_hull - c.on_other) * (radius / c.distance))
                                  : c.on_other;
      return std::max(0.0, c.distance - radius);
    };
  }
  // Boxes and convex shapes: exact closest features (closest_between).
  std::optional<RuntimeHull> placed =
      s.kind == ShapeKind::box ? std::optional<RuntimeHull>(placed_box(pose, s.half_extents)) : placed_convex(s, pose);
  if (!placed) return nullptr;
  auto shape = std::make_shared<const RuntimeHull>(std::move(*placed));
  return [this, shape](int h, Eigen::Vector3d& on_world, Eigen::Vector3d& on_shape) {
    const ClosestPoints c = closest_between(hulls_[h], *shape);
    on_world = c.on_hull;
    on_shape = c.on_other;
    return c.distance;
  };
}

Status HullWorld::distance(const DistanceRequest& request, DistanceResult& result) const {
  return detail::guarded("distance query", [&]() -> Status {
    result = {};
    if (Status s = check_query_shape(request.shape, request.pose); !s.ok()) return s;
    const QueryShape& s = request.shape;
    const Aabb core = world_box(s, request.pose);
    const auto separation = separation_from(s, request.pose);
    if (!separation) return {StatusCode::invalid_argument, "the convex query shape has no 3D hull"};
    // Grow the search box until it holds a hull, then until it holds every
    // hull nearer than the best found.
    const Aabb world = tree_->bounds();
    const double scene = (world.max - world.min).norm();
    result.distance = std::numeric_limits<double>::infinity();
    double reach = 0.0;
    for (int round = 0; round < 64; ++round) {
      std::vector<int> near;
      candidates(grown(core, reach), near);
      for (int h : near) {
        Eigen::Vector3d on_world, on_shape;
        const double d = separation(h, on_world, on_shape);
        if (d < result.distance || (d == result.distance && h < result.hull)) {
          result.distance = d;
          result.hull = h;
          result.on_world = on_world;
          result.on_shape = on_shape;
        }
      }
      if (result.hull >= 0 && result.distance <= reach) break;
      if (reach > 4.0 * scene) break;
      reach = result.hull >= 0 ? result.distance : 2.0 * reach + kDistanceReachGrowth * (1.0 + scene);
    }
    result.touching = result.hull >= 0 && result.distance == 0.0;
    return Status::success();
  });
}

namespace {
// How far any point of the shape lies from its local origin (scene units):
// what a turn of angle a moves it by, at most a times this.
double reach_from_origin(const QueryShape& s) {
  switch (s.kind) {
    case ShapeKind::sphere: return 0.0;  // turning a sphere moves none of it
    case ShapeKind::capsule: return s.half_height;  // its axis; the radius turns with it
    case ShapeKind::box: return s.half_extents.norm();
    case ShapeKind::convex: {
      double farthest = 0.0;
      for (const Eigen::Vector3d& p : s.points) farthest = std::max(farthest, p.norm());
      return farthest;
    }
  }
  return 0.0;
}

// How far the shape extends beyond its axis or core points: the radius of a
// sphere or capsule, 0 for the others.
double rounding_of(const QueryShape& s) {
  return s.kind == ShapeKind::sphere || s.kind == ShapeKind::capsule ? s.radius : 0.0;
}
} // namespace

Status HullWorld::sweep(const SweepRequest& request, SweepResult& result, double touch) const {
  return detail::guarded("sweep", [&]() -> Status {
    result = {};
    if (Status s = check_query_shape(request.shape, request.start); !s.ok()) return s;
    if (Status s = check_query_shape(request.shape, request.end); !s.ok()) return s;
    const QueryShape& s = request.shape;
    if (!(touch > 0.0) || !std::isfinite(touch))
      return {StatusCode::invalid_argument, "touch must be a positive length"};
    if (request.max_steps < 1) return {StatusCode::invalid_argument, "max_steps must be at least 1"};
    const Eigen::Vector3d travel = request.end.translation() - request.start.translation();
    // The turn, along the shorter way; none when the rotations agree to
    // rounding (then the swept box is exact).
    const Eigen::Quaterniond from(request.start.linear()), to(request.end.linear());
    const bool turns = !request.start.linear().isApprox(request.end.linear(), kSweepSameRotation);
    const double angle = turns ? from.angularDistance(to) : 0.0;
    // No point of the shape moves farther than `speed` per unit of the way:
    // advancing by the distance over it never passes through a hull.
    const double speed = travel.norm() + angle * reach_from_origin(s);
    const auto pose_at = [&](double t) {
      Eigen::Isometry3d pose = request.start;
      pose.translation() += t * travel;
      if (turns) pose.linear() = from.slerp(t, to).toRotationMatrix();
      return pose;
    };
    Aabb swept = world_box(s, request.start);
    const Aabb at_end = world_box(s, request.end);
    swept.extend(at_end.min);
    swept.extend(at_end.max);
    if (turns) {
      // Every point stays within reach + rounding of the origin's path.
      const double around = reach_from_origin(s) + rounding_of(s);
      for (const Eigen::Isometry3d* end : {&request.start, &request.end}) {
        swept.extend(end->translation().array() - around);
        swept.extend(end->translation().array() + around);
      }
    }
    std::vector<int> near;
    candidates(swept, near);
    double t = 0.0;
    for (int step = 0; step < request.max_steps; ++step) {
      const Eigen::Isometry3d pose = pose_at(t);
      const auto separation = separation_from(s, pose);
      if (!separation) return {StatusCode::invalid_argument, "the convex query shape has no 3D hull"};
      double nearest = std::numeric_limits<double>::infinity();
      int nearest_hull = -1;
      Eigen::Vector3d on_world, on_shape, away = Eigen::Vector3d::Zero();
      for (int h : near) {
        const double d = separation(h, on_world, on_shape);
        if (d < nearest) {
          nearest = d;
          nearest_hull = h;
          away = on_shape - on_world;
        }
      }
      if (nearest_hull < 0) return Status::success();  // nothing on the way
      // Out of steps (a grazing approach advances ever more slowly): a hit
      // where the shape stands is conservative, as it is still apart there.
      if (nearest <= touch || step + 1 == request.max_steps) {
        result.hit = true;
        result.fraction = t;
        result.hull = nearest_hull;
        // The normal of the exact contact a touch further on (closest points
        // this near are noise in direction).
        const Eigen::Isometry3d pressed = speed > 0.0 ? pose_at(std::min(1.0, t + 2.0 * touch / speed)) : pose;
        std::optional<PlacedShape> placed;
        if (Status status = place(s, pressed, placed); !status.ok()) return status;
        const std::optional<Contact> c = placed->contact(hulls_[nearest_hull]);
        // Without a contact (out of steps, a graze): from the hull towards the
        // shape, else against the travel, else up (a turn in place touching).
        const Eigen::Vector3d fallback = away.norm() > 0.0      ? Eigen::Vector3d(away.normalized())
                                         : travel.norm() > 0.0 ? Eigen::Vector3d(-travel.normalized())
                                                               : Eigen::Vector3d::UnitZ();
        result.normal = c ? c->normal : fallback;
        return Status::success();
      }
      if (speed == 0.0) return Status::success();
      t += nearest / speed;
      if (t > 1.0) return Status::success();
    }
    return Status::success();
  });
}

} // namespace hullcover::bvh
