#include "hullcover/bvh/triangle_world.h"

#include "fcl_objects.h"
#include "query_guard.h"

#include "hullcover/geometry/planar_hull.h"
#include "hullcover/geometry/tolerances.h"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/distance.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>

namespace hullcover::bvh {

// Nodes a ray's traversal stack holds before it grows: a balanced tree of a
// million triangles is 20 deep, and the stack holds at most one sibling a level.
constexpr size_t kRayStackReserve = 64;

struct TriangleWorld::Fcl {
  std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> model;
  std::unique_ptr<fcl::CollisionObjectd> object;
};

TriangleWorld::~TriangleWorld() = default;

namespace {

// A ray against one triangle (a flat hull: front plane first, side planes
// after its two facets), counting a hit within `tol` of its edges, so a ray
// through the edge two triangles share meets at least one of them, and
// inside the triangle's box grown by kFaceBoxMarginInTolerances tol: past a
// sharp corner the edges pushed out by tol reach tol / sin(half the angle)
// beyond it (a rail's 11-degree tip on Red Eclipse's depot: 0.2 units at tol
// 0.02), where the ray misses the triangle by far more than tol. The
// decomposer's rays meet faces by the same rule (mesh_ray.h).
std::optional<RayHit> ray_hits_triangle(const RuntimeHull& triangle, const Eigen::Vector3d& origin,
                                        const Eigen::Vector3d& dir, double reach, double tol) {
  const std::vector<Plane>& planes = triangle.shape.planes;
  const Plane& front = planes.front();
  const double rate = front.normal.dot(dir);
  if (rate == 0.0) return std::nullopt;
  const double t = -front.signed_distance(origin) / rate;
  if (t < 0.0 || t > reach) return std::nullopt;
  const Eigen::Vector3d p = origin + t * dir;
  const double box_margin = kFaceBoxMarginInTolerances * tol;
  if ((p.array() > triangle.box.max.array() + box_margin).any() ||
      (p.array() < triangle.box.min.array() - box_margin).any())
    return std::nullopt;
  for (size_t i = triangle.shape.facets.size(); i < planes.size(); ++i)
    if (planes[i].signed_distance(p) > tol) return std::nullopt;
  return RayHit{-1, t, p, rate < 0.0 ? front.normal : Eigen::Vector3d(-front.normal)};
}

QueryShape inflated(QueryShape s, double by) {
  s.radius += by;
  s.half_extents.array() += by;
  return s;
}
} // namespace

Result<std::shared_ptr<const TriangleWorld>> TriangleWorld::build(const Mesh& mesh, double tol,
                                                                  const std::vector<char>& no_surface) {
  using Built = Result<std::shared_ptr<const TriangleWorld>>;
  return detail::guarded("building the triangle world", [&]() -> Built {
    if (Status s = validate_mesh(mesh); !s.ok()) return Status{StatusCode::invalid_argument, s.message()};
    if (!no_surface.empty() && no_surface.size() != mesh.triangles.size())
      return Status{StatusCode::invalid_argument, "one no-surface flag per triangle expected"};
    std::shared_ptr<TriangleWorld> world(new TriangleWorld());
    world->margin_ = kTriangleMarginInTolerances * tol;
    world->tol_ = tol;
    std::vector<fcl::Triangle> tris;
    for (int f = 0; f < static_cast<int>(mesh.triangles.size()); ++f) {
      const Eigen::Vector3i& t = mesh.triangles[f];
      const Eigen::Vector3d &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
      const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
      if ((b - a).cross(c - a).norm() <= tol * longest || (!no_surface.empty() && no_surface[f])) continue;
      world->triangles_.push_back(flat_triangle_hull(a, b, c));
      world->face_of_.push_back(f);
      tris.emplace_back(t[0], t[1], t[2]);
    }
    if (tris.empty()) return Status{StatusCode::invalid_argument, "the mesh has no triangle with a surface"};
    world->fcl_ = std::make_unique<Fcl>();
    auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
    model->beginModel(static_cast<int>(tris.size()), static_cast<int>(mesh.positions.size()));
    model->addSubModel(mesh.positions, tris);
    model->endModel();
    world->fcl_->model = model;
    world->fcl_->object = std::make_unique<fcl::CollisionObjectd>(model);
    return std::shared_ptr<const TriangleWorld>(std::move(world));
  });
}

void TriangleWorld::candidates(const QueryShape& shape, const Eigen::Isometry3d& pose, double inflate,
                               std::vector<int>& out) const {
  const QueryShape s = inflated(shape, inflate);
  const std::shared_ptr<fcl::CollisionGeometryd> geometry = detail::fcl_geometry(s);
  if (!geometry) return;
  const detail::QueryObject query(geometry, pose, world_box(s, pose));
  fcl::CollisionRequestd request(std::numeric_limits<int>::max() / 2, false);
  fcl::CollisionResultd result;
  fcl::collide(&query, fcl_->object.get(), request, result);
  std::vector<fcl::Contactd> found;
  result.getContacts(found);
  for (const fcl::Contactd& c : found) out.push_back(c.o1 == fcl_->model.get() ? c.b1 : c.b2);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

Status TriangleWorld::overlap(const OverlapRequest& request, OverlapResult& result) const {
  return detail::guarded("overlap query", [&]() -> Status {
    result.hulls.clear();
    if (Status s = check_query_shape(request.shape, request.pose); !s.ok()) return s;
    candidates(request.shape, request.pose, 0.0, result.hulls);
    return Status::success();
  });
}

Status TriangleWorld::touches(const OverlapRequest& request, TouchResult& result) const {
  return detail::guarded("touch query", [&]() -> Status {
    result = {};
    if (Status s = check_query_shape(request.shape, request.pose); !s.ok()) return s;
    const std::shared_ptr<fcl::CollisionGeometryd> geometry = detail::fcl_geometry(request.shape);
    if (!geometry) return {StatusCode::invalid_argument, "the convex query shape has no 3D hull"};
    const detail::QueryObject query(geometry, request.pose, world_box(request.shape, request.pose));
    const fcl::CollisionRequestd first_only(1, false);
    fcl::CollisionResultd found;
    if (fcl::collide(&query, fcl_->object.get(), first_only, found) > 0) {
      const fcl::Contactd& c = found.getContact(0);
      const int primitive = c.o1 == fcl_->model.get() ? c.b1 : c.b2;
      result.touching = true;
      result.hull = primitive >= 0 && primitive < static_cast<int>(face_of_.size()) ? face_of_[primitive] : -1;
    }
    return Status::success();
  });
}

Status TriangleWorld::contacts(const ContactRequest& request, ContactResult& result) const {
  return detail::guarded("contact query", [&]() -> Status {
    result.contacts.clear();
    if (Status s = check_query_shape(request.shape, request.pose); !s.ok()) return s;
    std::optional<RuntimeHull> convex;
    if (request.shape.kind == ShapeKind::convex) {
      convex = placed_convex(request.shape, request.pose);
      if (!convex) return {StatusCode::invalid_argument, "the convex query shape has no 3D hull"};
    }
    std::vector<int> near;
    candidates(request.shape, request.pose, margin_, near);
    for (int i : near) {
      const RuntimeHull& tri = triangles_[i];
      std::optional<Contact> c;
      const QueryShape& s = request.shape;
      if (s.kind == ShapeKind::sphere) {
        c = sphere_contact(tri, request.pose.translation(), s.radius);
      } else if (s.kind == ShapeKind::capsule) {
        const Eigen::Vector3d axis = request.pose.linear().col(2) * s.half_height;
        c = capsule_contact(tri, request.pose.translation() - axis, request.pose.translation() + axis, s.radius);
      } else if (s.kind == ShapeKind::box) {
        c = box_contact(tri, request.pose, s.half_extents);
      } else {
        c = convex_contact(tri, *convex);
      }
      if (c) {
        c->hull = face_of_[i];
        result.contacts.push_back(*c);
      }
    }
    std::stable_sort(result.contacts.begin(), result.contacts.end(),
                     [](const Contact& x, const Contact& y) { return x.depth > y.depth; });
    if (static_cast<int>(result.contacts.size()) > request.max_contacts) result.contacts.resize(request.max_contacts);
    return Status::success();
  });
}

void TriangleWorld::traverse_ray(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double& reach,
                                 const std::function<void(const RayHit&)>& on_hit) const {
  const fcl::BVHModel<fcl::OBBRSSd>& model = *fcl_->model;
  // Where the ray enters node `id`'s box, within the current reach, or
  // nothing. A slab test in the box's oriented frame; boxes are grown by the
  // margin: a tight box (flat for a triangle) would lose rays through its
  // edges to rounding.
  const auto entry_into = [&](int id) -> std::optional<double> {
    const fcl::OBBd& box = model.getBV(id).bv.obb;
    const Eigen::Vector3d o = box.axis.transpose() * (origin - box.To);
    const Eigen::Vector3d d = box.axis.transpose() * dir;
    double t0 = 0.0, t1 = reach;
    for (int k = 0; k < 3 && t0 <= t1; ++k) {
      const double extent = box.extent[k] + margin_;
      if (d[k] == 0.0) {
        if (std::abs(o[k]) > extent) return std::nullopt;
        continue;
      }
      double a = (-extent - o[k]) / d[k], b = (extent - o[k]) / d[k];
      if (a > b) std::swap(a, b);
      t0 = std::max(t0, a);
      t1 = std::min(t1, b);
    }
    if (t0 > t1) return std::nullopt;
    return t0;
  };
  // Nearer child first, and a node entered beyond the reach (which a hit
  // shortens) is skipped: a ray down a row of N separate triangles meets
  // the first and visits O(log N) nodes, not all N.
  struct Pending {
    int node;
    double entry;
  };
  std::vector<Pending> stack;
  stack.reserve(kRayStackReserve);
  if (const std::optional<double> root = entry_into(0)) stack.push_back({0, *root});
  while (!stack.empty()) {
    const Pending top = stack.back();
    stack.pop_back();
    if (top.entry > reach) continue;
    const fcl::BVNode<fcl::OBBRSSd>& node = model.getBV(top.node);
    if (!node.isLeaf()) {
      const std::optional<double> left = entry_into(node.leftChild()), right = entry_into(node.rightChild());
      const bool left_first = left && (!right || *left <= *right);
      if (left_first) {
        if (right) stack.push_back({node.rightChild(), *right});
        stack.push_back({node.leftChild(), *left});
      } else {
        if (left) stack.push_back({node.leftChild(), *left});
        if (right) stack.push_back({node.rightChild(), *right});
      }
      continue;
    }
    // The model holds only triangles with a surface, in triangles_ order.
    const int i = node.primitiveId();
    if (std::optional<RayHit> hit = ray_hits_triangle(triangles_[i], origin, dir, reach, tol_)) {
      hit->hull = face_of_[i];
      on_hit(*hit);
    }
  }
}

Status TriangleWorld::ray_cast(const RayRequest& request, RayResult& result) const {
  return detail::guarded("ray query", [&]() -> Status {
    result = {};
    Eigen::Vector3d dir;
    if (Status s = check_ray_request(request, dir); !s.ok()) return s;
    double best = request.max_distance;
    traverse_ray(request.origin, dir, best, [&](const RayHit& hit) {
      if (!result.hit || hit.t < result.first.t || (hit.t == result.first.t && hit.hull < result.first.hull)) {
        result.hit = true;
        result.first = hit;
        best = hit.t;
      }
    });
    return Status::success();
  });
}

Status TriangleWorld::ray_hits(const RayRequest& request, std::vector<RayHit>& hits) const {
  return detail::guarded("ray hits query", [&]() -> Status {
    hits.clear();
    Eigen::Vector3d dir;
    if (Status s = check_ray_request(request, dir); !s.ok()) return s;
    double reach = request.max_distance;
    traverse_ray(request.origin, dir, reach, [&](const RayHit& hit) { hits.push_back(hit); });
    std::sort(hits.begin(), hits.end(),
              [](const RayHit& a, const RayHit& b) { return a.t < b.t || (a.t == b.t && a.hull < b.hull); });
    return Status::success();
  });
}

Status TriangleWorld::distance(const DistanceRequest& request, DistanceResult& result) const {
  return detail::guarded("distance query", [&]() -> Status {
    result = {};
    if (Status s = check_query_shape(request.shape, request.pose); !s.ok()) return s;
    if (request.shape.kind != ShapeKind::sphere && request.shape.kind != ShapeKind::capsule)
      return {StatusCode::invalid_argument, "distance is implemented for spheres and capsules"};
    const std::shared_ptr<fcl::CollisionGeometryd> geometry = detail::fcl_geometry(request.shape);
    const detail::QueryObject query(geometry, request.pose, world_box(request.shape, request.pose));
    fcl::DistanceRequestd d_request(true);
    fcl::DistanceResultd d_result;
    const double d = fcl::distance(&query, fcl_->object.get(), d_request, d_result);
    const bool model_first = d_result.o1 == fcl_->model.get();
    const int primitive = model_first ? d_result.b1 : d_result.b2;
    result.distance = std::max(0.0, d);
    result.touching = d <= 0.0;
    result.hull = primitive >= 0 && primitive < static_cast<int>(face_of_.size()) ? face_of_[primitive] : -1;
    result.on_world = d_result.nearest_points[model_first ? 0 : 1];
    result.on_shape = d_result.nearest_points[model_first ? 1 : 0];
    return Status::success();
  });
}

} // namespace hullcover::bvh
