#pragma once
/// \file engine_limits.h
/// What each game engine's convex collider accepts, and the check an
/// export makes of every hull before it writes one (decompose chooses the
/// limits up front with --max-hull-vertices and --max-hull-triangles).

#include "hullcover/geometry/convex_polytope.h"

#include <optional>
#include <string>
#include <vector>

namespace hullcover::app {

/// The engine an export is for.
enum class TargetEngine { any, jolt, physx, physx_gpu, unity, godot, unreal };

/// Limits of one engine's convex collider. A count of 0 is no limit.
struct EngineLimits {
  const char* name = "";
  int max_vertices = 0;  ///< vertices of one hull
  int max_polygons = 0;  ///< facets (polygons) of one hull
  int max_triangles = 0; ///< triangles once its facets are fanned
  /// Thinnest hull the engine's hull builder takes, metres: flatter point
  /// sets fail to cook or are dropped (Jolt's hull tolerance is 1 mm,
  /// PhysX's plane tolerance 0.7 mm; twice the largest of them).
  double min_thickness_metres = 0.0;
  /// Distance within which the engine's hull builder drops a point as
  /// already inside, metres: Jolt's default hull tolerance is 1 mm, PhysX's
  /// plane tolerance 0.7 mm (grown with the hull's size), so 1 mm for all.
  /// The export keeps no hull corner its builder could drop and then find
  /// outside (cooking_margin.h).
  double hull_tolerance_metres = 0.0;
};

/// The limits of `engine`. `any` is the strictest of the CPU engines:
/// Jolt's and PhysX's 256 vertices, PhysX's 255 polygons, Unity's 255
/// triangles.
EngineLimits engine_limits(TargetEngine engine);

/// The engine named `name` (any, jolt, physx, physx-gpu, unity, godot,
/// unreal), or nothing.
std::optional<TargetEngine> engine_named(const std::string& name);

/// The names engine_named takes, for --help.
std::vector<std::string> engine_names();

/// One sentence per hull of `hulls` over a limit of `limits` (naming the
/// hull, the count, the limit and the decompose option that keeps it);
/// empty when every hull fits.
std::vector<std::string> engine_limit_breaches(const std::vector<ConvexPolytope>& hulls, const EngineLimits& limits);

} // namespace hullcover::app
