#include "hullcover/bvh/query_shape.h"

#include "query_guard.h"

#include "hullcover/geometry/point_hull.h"

#include <cmath>

// The library's own layout of Eigen's fixed-size types (query_shape.h).
extern "C" const int HULLCOVER_EIGEN_LAYOUT_SYMBOL = EIGEN_MAX_STATIC_ALIGN_BYTES;

namespace hullcover::bvh {

Aabb world_box(const QueryShape& shape, const Eigen::Isometry3d& pose) {
  Aabb box;
  const Eigen::Matrix3d& r = pose.linear();
  const Eigen::Vector3d& t = pose.translation();
  switch (shape.kind) {
    case ShapeKind::sphere:
      box.extend(t - Eigen::Vector3d::Constant(shape.radius));
      box.extend(t + Eigen::Vector3d::Constant(shape.radius));
      break;
    case ShapeKind::capsule: {
      const Eigen::Vector3d axis = r.col(2) * shape.half_height;
      for (const Eigen::Vector3d& end : {Eigen::Vector3d(t + axis), Eigen::Vector3d(t - axis)}) {
        box.extend(end - Eigen::Vector3d::Constant(shape.radius));
        box.extend(end + Eigen::Vector3d::Constant(shape.radius));
      }
      break;
    }
    case ShapeKind::box: {
      const Eigen::Vector3d reach = r.cwiseAbs() * shape.half_extents;
      box.extend(t - reach);
      box.extend(t + reach);
      break;
    }
    case ShapeKind::convex:
      for (const Eigen::Vector3d& p : shape.points) box.extend(pose * p);
      break;
  }
  return box;
}

namespace {
// What makes the shape or pose unusable, or nullptr.
const char* shape_problem(const QueryShape& shape, const Eigen::Isometry3d& pose) {
  const auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  if (!pose.matrix().allFinite()) return "the pose is not finite";
  switch (shape.kind) {
    case ShapeKind::sphere:
      if (!positive(shape.radius)) return "sphere radius must be positive";
      break;
    case ShapeKind::capsule:
      if (!positive(shape.radius) || !(std::isfinite(shape.half_height) && shape.half_height >= 0.0))
        return "capsule radius must be positive and half height >= 0";
      break;
    case ShapeKind::box:
      if (!(shape.half_extents.array() > 0.0).all() || !shape.half_extents.allFinite())
        return "box half extents must be positive";
      break;
    case ShapeKind::convex:
      if (shape.points.size() < 4) return "a convex query shape needs at least 4 points";
      for (const Eigen::Vector3d& p : shape.points)
        if (!p.allFinite()) return "convex query shape has a non-finite point";
      break;
  }
  return nullptr;
}
} // namespace

Status check_query_shape(const QueryShape& shape, const Eigen::Isometry3d& pose) {
  // Guarded: the message is allocated.
  return detail::guarded("checking a query shape", [&] {
    const char* why = shape_problem(shape, pose);
    return why != nullptr ? Status{StatusCode::invalid_argument, why} : Status::success();
  });
}

std::optional<RuntimeHull> placed_convex(const QueryShape& shape, const Eigen::Isometry3d& pose) {
  std::vector<Eigen::Vector3d> points;
  for (const Eigen::Vector3d& p : shape.points) points.push_back(pose * p);
  std::optional<ConvexPolytope> hull = convex_hull_of_points(points);
  if (!hull) return std::nullopt;
  return make_runtime_hull(std::move(*hull), 0);
}

} // namespace hullcover::bvh
