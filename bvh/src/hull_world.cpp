#include "hullcover/bvh/hull_world.h"

#include "fcl_objects.h"
#include "query_guard.h"

#include "hullcover/geometry/point_hull.h"
#include "hullcover/geometry/tolerances.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

namespace hullcover::bvh {

struct HullWorld::Fcl {
  // Broad phase: one object per hull in FCL's dynamic AABB tree. They carry
  // the hull's exact box over a shared placeholder geometry, so building a
  // world does not pay for every fcl::Convex up front.
  std::shared_ptr<fcl::Boxd> placeholder = std::make_shared<fcl::Boxd>(1.0, 1.0, 1.0);
  std::vector<std::unique_ptr<detail::HullEntry>> broad;
  fcl::DynamicAABBTreeCollisionManagerd manager;
  // Narrow phase: each hull's fcl::Convex, built once, on the first query
  // that needs it, and shared by every later one (once per hull, so
  // concurrent queries are safe).
  std::unique_ptr<std::once_flag[]> built;
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> narrow;

  const fcl::CollisionObjectd& convex(const RuntimeHull& hull, int h) {
    std::call_once(built[h],
                   [&] { narrow[h] = std::make_unique<fcl::CollisionObjectd>(detail::fcl_convex(hull.shape)); });
    return *narrow[h];
  }
};

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
    }
    std::shared_ptr<HullWorld> world(new HullWorld());
    world->hulls_ = std::move(hulls);
    world->fcl_ = std::make_unique<Fcl>();
    Fcl& f = *world->fcl_;
    const size_t n = world->hulls_.size();
    f.built = std::make_unique<std::once_flag[]>(n);
    f.narrow.resize(n);
    std::vector<fcl::CollisionObjectd*> registered;
    registered.reserve(n);
    for (size_t i = 0; i < n; ++i) {
      f.broad.push_back(std::make_unique<detail::HullEntry>(f.placeholder, world->hulls_[i].box, static_cast<int>(i)));
      registered.push_back(f.broad.back().get());
    }
    f.manager.registerObjects(registered);
    f.manager.setup();
    return std::shared_ptr<const HullWorld>(std::move(world));
  });
}

void HullWorld::candidates(const Aabb& box, std::vector<int>& out) const {
  using Node = fcl::DynamicAABBTreeCollisionManagerd::DynamicAABBNode;
  const Node* root = fcl_->manager.getTree().getRoot();
  if (root == nullptr) return;
  const fcl::AABBd query(box.min, box.max);
  std::vector<const Node*> stack = {root};
  while (!stack.empty()) {
    const Node* node = stack.back();
    stack.pop_back();
    if (!node->bv.overlap(query)) continue;
    if (node->isLeaf()) {
      out.push_back(static_cast<const detail::HullEntry*>(node->data)->index);
    } else {
      stack.push_back(node->children[0]);
      stack.push_back(node->children[1]);
    }
  }
  std::sort(out.begin(), out.end());
}

Status HullWorld::overlap(const OverlapRequest& request, OverlapResult& result) const {
  return detail::guarded("overlap query", [&]() -> Status {
    result.hulls.clear();
    if (Status s = check_query_shape(request.shape, request.pose); !s.ok()) return s;
    const std::shared_ptr<fcl::CollisionGeometryd> geometry = detail::fcl_geometry(request.shape);
    if (!geometry) return {StatusCode::invalid_argument, "the convex query shape has no 3D hull"};
    const detail::QueryObject query(geometry, request.pose, world_box(request.shape, request.pose));
    std::vector<int> near;
    candidates(world_box(request.shape, request.pose), near);
    const fcl::CollisionRequestd yes_no;
    for (int h : near) {
      fcl::CollisionResultd answer;
      if (fcl::collide(&query, &fcl_->convex(hulls_[h], h), yes_no, answer) > 0) result.hulls.push_back(h);
    }
    return Status::success();
  });
}

namespace {
// The capsule's axis end points in the world.
std::pair<Eigen::Vector3d, Eigen::Vector3d> capsule_ends(const QueryShape& s, const Eigen::Isometry3d& pose) {
  const Eigen::Vector3d axis = pose.linear().col(2) * s.half_height;
  return {pose.translation() - axis, pose.translation() + axis};
}

std::optional<Contact> contact_with(const RuntimeHull& hull, const QueryShape& s, const Eigen::Isometry3d& pose,
                                    const RuntimeHull* convex_in_world) {
  switch (s.kind) {
    case ShapeKind::sphere: return sphere_contact(hull, pose.translation(), s.radius);
    case ShapeKind::capsule: {
      const auto [a, b] = capsule_ends(s, pose);
      return capsule_contact(hull, a, b, s.radius);
    }
    case ShapeKind::box: return box_contact(hull, pose, s.half_extents);
    case ShapeKind::convex: return convex_contact(hull, *convex_in_world);
  }
  return std::nullopt;
}
} // namespace

std::optional<RuntimeHull> placed_convex(const QueryShape& shape, const Eigen::Isometry3d& pose) {
  std::vector<Eigen::Vector3d> points;
  for (const Eigen::Vector3d& p : shape.points) points.push_back(pose * p);
  std::optional<ConvexPolytope> hull = convex_hull_of_points(points);
  if (!hull) return std::nullopt;
  return make_runtime_hull(std::move(*hull), 0);
}

Status HullWorld::contacts(const ContactRequest& request, ContactResult& result) const {
  return detail::guarded("contact query", [&]() -> Status {
    result.contacts.clear();
    if (Status s = check_query_shape(request.shape, request.pose); !s.ok()) return s;
    if (request.max_contacts < 1) return {StatusCode::invalid_argument, "max_contacts must be at least 1"};
    std::optional<RuntimeHull> convex;
    if (request.shape.kind == ShapeKind::convex) {
      convex = placed_convex(request.shape, request.pose);
      if (!convex) return {StatusCode::invalid_argument, "the convex query shape has no 3D hull"};
    }
    std::vector<int> near;
    candidates(world_box(request.shape, request.pose), near);
    const RuntimeHull* placed = convex ? &*convex : nullptr;
    for (int h : near)
      if (std::optional<Contact> c = contact_with(hulls_[h], request.shape, request.pose, placed)) {
        c->hull = h;
        result.contacts.push_back(*c);
      }
    std::stable_sort(result.contacts.begin(), result.contacts.end(),
                     [](const Contact& x, const Contact& y) { return x.depth > y.depth; });
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

Status HullWorld::ray_cast(const RayRequest& request, RayResult& result) const {
  return detail::guarded("ray query", [&]() -> Status {
    result = {};
    Eigen::Vector3d dir;
    if (Status s = check_ray_request(request, dir); !s.ok()) return s;
    const Eigen::Vector3d inverse = dir.cwiseInverse();
    using Node = fcl::DynamicAABBTreeCollisionManagerd::DynamicAABBNode;
    double best = request.max_distance;
    std::vector<const Node*> stack = {fcl_->manager.getTree().getRoot()};
    while (!stack.empty()) {
      const Node* node = stack.back();
      stack.pop_back();
      if (node == nullptr) continue;
      // Slab test of the node's box against the ray, up to the best hit so far.
      double t0 = 0.0, t1 = best;
      for (int k = 0; k < 3 && t0 <= t1; ++k) {
        double near = (node->bv.min_[k] - request.origin[k]) * inverse[k];
        double far = (node->bv.max_[k] - request.origin[k]) * inverse[k];
        if (std::isnan(near) || std::isnan(far)) {  // parallel and on the slab's face
          near = -std::numeric_limits<double>::infinity();
          far = std::numeric_limits<double>::infinity();
        }
        if (near > far) std::swap(near, far);
        t0 = std::max(t0, near);
        t1 = std::min(t1, far);
      }
      if (t0 > t1) continue;
      if (!node->isLeaf()) {
        stack.push_back(node->children[0]);
        stack.push_back(node->children[1]);
        continue;
      }
      const int h = static_cast<const detail::HullEntry*>(node->data)->index;
      std::optional<RayHit> hit = ray_hit(hulls_[h], request.origin, dir, best);
      if (hit && (!result.hit || hit->t < result.first.t || (hit->t == result.first.t && h < result.first.hull))) {
        hit->hull = h;
        result.hit = true;
        result.first = *hit;
        best = hit->t;
      }
    }
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
    const fcl::AABBd& world = fcl_->manager.getTree().getRoot()->bv;
    const double scene = (world.max_ - world.min_).norm();
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

Status HullWorld::sweep(const SweepRequest& request, SweepResult& result, double touch) const {
  return detail::guarded("sweep", [&]() -> Status {
    result = {};
    if (Status s = check_query_shape(request.shape, request.start); !s.ok()) return s;
    if (Status s = check_query_shape(request.shape, request.end); !s.ok()) return s;
    const QueryShape& s = request.shape;
    if (!request.start.linear().isApprox(request.end.linear(), kSweepSameRotation))
      return {StatusCode::invalid_argument, "a sweep moves without turning: start and end need the same rotation"};
    if (!(touch > 0.0) || !std::isfinite(touch))
      return {StatusCode::invalid_argument, "touch must be a positive length"};
    if (request.max_steps < 1) return {StatusCode::invalid_argument, "max_steps must be at least 1"};
    const Eigen::Vector3d travel = request.end.translation() - request.start.translation();
    const double length = travel.norm();
    Aabb swept = world_box(s, request.start);
    const Aabb at_end = world_box(s, request.end);
    swept.extend(at_end.min);
    swept.extend(at_end.max);
    std::vector<int> near;
    candidates(swept, near);
    double t = 0.0;
    for (int step = 0; step < request.max_steps; ++step) {
      Eigen::Isometry3d pose = request.start;
      pose.translation() += t * travel;
      const auto separation = separation_from(s, pose);
      if (!separation) return {StatusCode::invalid_argument, "the convex query shape has no 3D hull"};
      double nearest = std::numeric_limits<double>::infinity();
      int nearest_hull = -1;
      Eigen::Vector3d on_world, on_shape;
      for (int h : near) {
        const double d = separation(h, on_world, on_shape);
        if (d < nearest) {
          nearest = d;
          nearest_hull = h;
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
        Eigen::Isometry3d pressed = pose;
        if (length > 0.0) pressed.translation() += travel * (2.0 * touch / length);
        std::optional<RuntimeHull> convex;
        if (s.kind == ShapeKind::convex) convex = placed_convex(s, pressed);
        const std::optional<Contact> c = contact_with(hulls_[nearest_hull], s, pressed, convex ? &*convex : nullptr);
        result.normal = c ? c->normal : Eigen::Vector3d(-travel.normalized());
        return Status::success();
      }
      if (length == 0.0) return Status::success();
      t += nearest / length;
      if (t > 1.0) return Status::success();
    }
    return Status::success();
  });
}

} // namespace hullcover::bvh
