#pragma once
/// \file query_shape.h
/// The shapes characters are, at a rigid pose, and their exact world boxes.
///
/// Conventions: lengths in scene units; a pose maps the shape's local frame
/// to the world; a capsule's axis is its local z, from -half_height to
/// +half_height between the centres of its end spheres; a box is centred on
/// its local origin.

#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/geometry/aabb.h"
#include "hullcover/geometry/status.h"

#include <Eigen/Geometry>

#include <vector>

// Eigen's fixed-size vectorizable types (the Isometry3d of every request)
// are laid out by the compiler's instruction-set flags: an AVX build aligns
// them to 32 bytes where an SSE2 build aligns them to 16, so a program
// built with other such flags than the library would hand it every
// request at the wrong offsets and get wrong answers, silently. Each file
// that includes this header refers to a symbol named after its own
// alignment, which only a library built with the same alignment defines
// (query_shape.cpp): a mismatch fails to link, naming the symbol
// (hullcover_eigen_static_alignment_32, say), instead. docs/install.md
// says what to do then.
#define HULLCOVER_EIGEN_LAYOUT_NAME_OF(bytes) hullcover_eigen_static_alignment_##bytes
#define HULLCOVER_EIGEN_LAYOUT_NAME(bytes) HULLCOVER_EIGEN_LAYOUT_NAME_OF(bytes)
#define HULLCOVER_EIGEN_LAYOUT_SYMBOL HULLCOVER_EIGEN_LAYOUT_NAME(EIGEN_MAX_STATIC_ALIGN_BYTES)
extern "C" const int HULLCOVER_EIGEN_LAYOUT_SYMBOL;
#if defined(__GNUC__) || defined(__clang__)
namespace hullcover::bvh::detail {
// A constant, kept by `used` so that every including file refers to the
// symbol even when nothing reads it.
[[maybe_unused]] __attribute__((used)) static const int* const eigen_layout_of_this_file =
    &HULLCOVER_EIGEN_LAYOUT_SYMBOL;
} // namespace hullcover::bvh::detail
#endif

namespace hullcover::bvh {

/// What a QueryShape is.
enum class ShapeKind { sphere, capsule, box, convex };

/// A query shape in its local frame. Only the fields of its `kind` are read;
/// check_query_shape gives the limits every query enforces.
struct QueryShape {
  ShapeKind kind = ShapeKind::sphere; ///< default sphere
  /// Sphere and capsule: radius in scene units, finite and > 0. Default 0.5.
  double radius = 0.5;
  /// Capsule: half the length of its axis segment (local z, between the
  /// centres of its end spheres) in scene units, finite and >= 0 (0 is a
  /// sphere). Default 0.5. The capsule is 2 * (half_height + radius) long.
  double half_height = 0.5;
  /// Box: half its size along local x, y, z in scene units, each finite and
  /// > 0. Default 0.5 (a unit cube).
  Eigen::Vector3d half_extents = Eigen::Vector3d::Constant(0.5);
  /// Convex: points in the local frame (scene units), at least 4, finite;
  /// the shape is their hull. Points with no 3D hull (all coplanar) make
  /// HullWorld's queries fail with `invalid_argument`. Every query hulls
  /// them again and its narrow phase costs edges x hull edges: keep the
  /// hull small. Default empty.
  std::vector<Eigen::Vector3d> points;

  /// A sphere of radius `r`, centred on the pose's origin.
  static QueryShape sphere(double r) {
    QueryShape s;
    s.kind = ShapeKind::sphere;
    s.radius = r;
    return s;
  }
  /// A capsule of radius `r` around the local z axis from -half_height to
  /// +half_height.
  static QueryShape capsule(double r, double half_height) {
    QueryShape s;
    s.kind = ShapeKind::capsule;
    s.radius = r;
    s.half_height = half_height;
    return s;
  }
  /// A box of these half extents along the local axes.
  static QueryShape box(const Eigen::Vector3d& half_extents) {
    QueryShape s;
    s.kind = ShapeKind::box;
    s.half_extents = half_extents;
    return s;
  }
};

/// The tight world-space box of `shape` at `pose` (not the cube around its
/// bounding sphere that FCL computes for rotated objects).
Aabb world_box(const QueryShape& shape, const Eigen::Isometry3d& pose);

/// Fails with `invalid_argument` (and a message naming the problem) for a
/// shape FCL or the narrow phase cannot use: non-positive or non-finite
/// sizes, a convex with fewer than 4 points or a non-finite one, a
/// non-finite pose. Every query runs it first.
[[nodiscard]] Status check_query_shape(const QueryShape& shape, const Eigen::Isometry3d& pose);

/// A convex query shape's hull placed at `pose`; nothing when its points
/// have no 3D hull.
std::optional<RuntimeHull> placed_convex(const QueryShape& shape, const Eigen::Isometry3d& pose);

} // namespace hullcover::bvh
