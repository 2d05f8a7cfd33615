#include "world_queries.h"

#include <memory>
#include <tuple>

namespace hullcover::bvh {

Status check_ray_request(const RayRequest& request, Eigen::Vector3d& unit_direction) {
  const double length = request.direction.norm();
  if (length > 0.0 && request.direction.allFinite() && request.origin.allFinite() && request.max_distance >= 0.0) {
    unit_direction = request.direction / length;
    return Status::success();
  }
  // Guarded: the message is allocated.
  return detail::guarded("checking a ray", []() -> Status {
    return {StatusCode::invalid_argument, "a ray needs a finite origin, a non-zero direction and max_distance >= 0"};
  });
}

namespace detail {
namespace {
// The capsule's axis end points in the world.
std::pair<Eigen::Vector3d, Eigen::Vector3d> capsule_ends(const QueryShape& s, const Eigen::Isometry3d& pose) {
  const Eigen::Vector3d axis = pose.linear().col(2) * s.half_height;
  return {pose.translation() - axis, pose.translation() + axis};
}

// How far any point of the shape lies from its local origin (scene units):
// what a turn of angle a moves it by, at most a times this.
double reach_from_origin(const QueryShape& s) {
  switch (s.kind) {
    case ShapeKind::sphere: return 0.0;            // turning a sphere moves none of it
    case ShapeKind::capsule: return s.half_height; // its axis; the radius turns with it
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

bool PlacedShape::touches(const RuntimeHull& hull) const {
  switch (shape.kind) {
    case ShapeKind::sphere: return sphere_touches(hull, a, shape.radius);
    case ShapeKind::capsule: return capsule_touches(hull, a, b, shape.radius);
    case ShapeKind::box: return box_touches(hull, pose, shape.half_extents);
    case ShapeKind::convex: return convex_touches(hull, *convex);
  }
  return false;
}

FloatVerdict PlacedShape::float_verdict(PlanesOf planes) const {
  switch (shape.kind) {
    case ShapeKind::sphere: return planes.sphere(a, shape.radius);
    case ShapeKind::capsule: return planes.segment(a, b, shape.radius);
    case ShapeKind::box:
    case ShapeKind::convex: return FloatVerdict::unsure;
  }
  return FloatVerdict::unsure;
}

std::optional<Contact> PlacedShape::contact(const RuntimeHull& hull) const {
  switch (shape.kind) {
    case ShapeKind::sphere: return sphere_contact(hull, a, shape.radius);
    case ShapeKind::capsule: return capsule_contact(hull, a, b, shape.radius);
    case ShapeKind::box: return box_contact(hull, pose, shape.half_extents);
    case ShapeKind::convex: return convex_contact(hull, *convex);
  }
  return std::nullopt;
}

Status place(const QueryShape& shape, const Eigen::Isometry3d& pose, std::optional<PlacedShape>& placed) {
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

Separation separation_from(const QueryShape& s, const Eigen::Isometry3d& pose) {
  // Spheres and capsules: exact closest points to the axis.
  if (s.kind == ShapeKind::sphere || s.kind == ShapeKind::capsule) {
    const auto [a, b] =
        s.kind == ShapeKind::capsule ? capsule_ends(s, pose) : std::make_pair(pose.translation(), pose.translation());
    return [a = a, b = b, radius = s.radius](const RuntimeHull& hull, Eigen::Vector3d& on_world,
                                             Eigen::Vector3d& on_shape) {
      const ClosestPoints c = closest_to_segment(hull, a, b);
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
  return [shape](const RuntimeHull& hull, Eigen::Vector3d& on_world, Eigen::Vector3d& on_shape) {
    const ClosestPoints c = closest_between(hull, *shape);
    on_world = c.on_hull;
    on_shape = c.on_other;
    return c.distance;
  };
}

Status check_hulls(const std::vector<RuntimeHull>& hulls, const std::vector<int>* names) {
  for (size_t i = 0; i < hulls.size(); ++i) {
    const std::string name = "hull " + std::to_string(names ? (*names)[i] : static_cast<int>(i));
    const ConvexPolytope& s = hulls[i].shape;
    bool finite = !s.vertices.empty() && s.facets.size() >= 2 && s.planes.size() >= s.facets.size();
    for (const Eigen::Vector3d& v : s.vertices) finite = finite && v.allFinite();
    for (const Plane& p : s.planes) finite = finite && p.normal.allFinite() && std::isfinite(p.offset);
    if (!finite) return {StatusCode::invalid_argument, name + " has no facets or non-finite data"};
    // The trees file a hull under its box: one that misses a vertex would
    // hide the hull from the queries that reach that vertex.
    const Aabb& box = hulls[i].box;
    bool holds = box.min.allFinite() && box.max.allFinite() && (box.min.array() <= box.max.array()).all();
    for (const Eigen::Vector3d& v : s.vertices)
      holds = holds && (v.array() >= box.min.array()).all() && (v.array() <= box.max.array()).all();
    if (!holds) return {StatusCode::invalid_argument, name + " has a box that does not hold all its vertices"};
    if (!hulls[i].surface_planes.empty() && hulls[i].surface_planes.size() != s.planes.size())
      return {StatusCode::invalid_argument, name + " has surface flags neither absent nor one per plane"};
    // Indices the narrow phase reads without a check.
    const int vertices = static_cast<int>(s.vertices.size());
    bool indexed = true;
    for (const std::vector<int>& facet : s.facets) {
      // A facet of fewer corners would hold every point its plane does.
      indexed = indexed && facet.size() >= 3;
      for (int v : facet) indexed = indexed && v >= 0 && v < vertices;
    }
    for (const auto& [a, b] : hulls[i].edges) indexed = indexed && a >= 0 && a < vertices && b >= 0 && b < vertices;
    if (!indexed)
      return {StatusCode::invalid_argument,
              name + " has a facet of fewer than 3 corners, or a facet or edge naming a vertex it does not have"};
  }
  return Status::success();
}

Eigen::Isometry3d SweepPath::pose_at(double t) const {
  Eigen::Isometry3d pose = start;
  pose.translation() += t * travel;
  if (turns) pose.linear() = from.slerp(t, to).toRotationMatrix();
  return pose;
}

Status plan_sweep(const SweepRequest& request, double touch, SweepPath& path, Aabb& swept) {
  if (Status s = check_query_shape(request.shape, request.start); !s.ok()) return s;
  if (Status s = check_query_shape(request.shape, request.end); !s.ok()) return s;
  const QueryShape& s = request.shape;
  if (!(touch > 0.0) || !std::isfinite(touch)) return {StatusCode::invalid_argument, "touch must be a positive length"};
  if (request.max_steps < 1) return {StatusCode::invalid_argument, "max_steps must be at least 1"};
  path.start = request.start;
  path.travel = request.end.translation() - request.start.translation();
  // The turn, along the shorter way; none when the rotations agree to
  // rounding (then the swept box is exact).
  path.from = Eigen::Quaterniond(request.start.linear());
  path.to = Eigen::Quaterniond(request.end.linear());
  path.turns = !request.start.linear().isApprox(request.end.linear(), kSweepSameRotation);
  const double angle = path.turns ? path.from.angularDistance(path.to) : 0.0;
  // No point of the shape moves farther than `speed` per unit of the way:
  // advancing by the distance over it never passes through a hull.
  path.speed = path.travel.norm() + angle * reach_from_origin(s);
  swept = world_box(s, request.start);
  const Aabb at_end = world_box(s, request.end);
  swept.extend(at_end.min);
  swept.extend(at_end.max);
  if (path.turns) {
    // Every point stays within reach + rounding of the origin's path.
    const double around = reach_from_origin(s) + rounding_of(s);
    for (const Eigen::Isometry3d* end : {&request.start, &request.end}) {
      swept.extend(end->translation().array() - around);
      swept.extend(end->translation().array() + around);
    }
  }
  return Status::success();
}

Status advance_sweep(const SweepRequest& request, const SweepPath& path, const std::vector<Candidate>& near,
                     double touch, SweepResult& result) {
  const QueryShape& s = request.shape;
  double t = 0.0;
  for (int step = 0; step < request.max_steps; ++step) {
    const Eigen::Isometry3d pose = path.pose_at(t);
    const Separation separation = separation_from(s, pose);
    if (!separation) return {StatusCode::invalid_argument, "the convex query shape has no 3D hull"};
    double nearest = std::numeric_limits<double>::infinity();
    const Candidate* nearest_hull = nullptr;
    Eigen::Vector3d on_world, on_shape, away = Eigen::Vector3d::Zero();
    for (const Candidate& c : near) {
      const double d = separation(*c.hull, on_world, on_shape);
      if (d < nearest) {
        nearest = d;
        nearest_hull = &c;
        away = on_shape - on_world;
      }
    }
    if (!nearest_hull) return Status::success(); // nothing on the way
    // Out of steps (a grazing approach advances ever more slowly): a hit
    // where the shape stands is conservative, as it is still apart there.
    if (nearest <= touch || step + 1 == request.max_steps) {
      result.hit = true;
      result.fraction = t;
      result.hull = nearest_hull->index;
      // The normal of the exact contact a touch further on (closest points
      // this near are noise in direction).
      const Eigen::Isometry3d pressed =
          path.speed > 0.0 ? path.pose_at(std::min(1.0, t + 2.0 * touch / path.speed)) : pose;
      std::optional<PlacedShape> placed;
      if (Status status = place(s, pressed, placed); !status.ok()) return status;
      const std::optional<Contact> c = placed->contact(*nearest_hull->hull);
      // Without a contact (out of steps, a graze): from the hull towards the
      // shape, else against the travel, else up (a turn in place touching).
      const Eigen::Vector3d fallback = away.norm() > 0.0          ? Eigen::Vector3d(away.normalized())
                                       : path.travel.norm() > 0.0 ? Eigen::Vector3d(-path.travel.normalized())
                                                                  : Eigen::Vector3d::UnitZ();
      result.normal = c ? c->normal : fallback;
      return Status::success();
    }
    if (path.speed == 0.0) return Status::success();
    t += nearest / path.speed;
    if (t > 1.0) return Status::success();
  }
  return Status::success();
}

} // namespace detail
} // namespace hullcover::bvh
