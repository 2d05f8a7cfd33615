#include "export/engine_limits.h"

#include "hullcover/covering/decompose_options.h"

#include <array>
#include <utility>

namespace hullcover::app {
namespace {

// Twice Jolt's default hull tolerance (1 mm), the largest flatness
// threshold of the engines below, so a thickened flat hull cooks in all.
constexpr double kEngineMinThicknessMetres = 0.002;
// Jolt's default hull tolerance, the largest of the engines' (cooking_margin.h).
constexpr double kEngineHullToleranceMetres = 0.001;

constexpr int kJoltMaxVertices = 256;
constexpr int kPhysxMaxVertices = 256;
constexpr int kPhysxMaxPolygons = 255;
constexpr int kPhysxGpuMaxVertices = 64;
constexpr int kUnityMaxTriangles = 255;

constexpr std::array<std::pair<const char*, TargetEngine>, 7> kEngines = {{
    {"any", TargetEngine::any},
    {"jolt", TargetEngine::jolt},
    {"physx", TargetEngine::physx},
    {"physx-gpu", TargetEngine::physx_gpu},
    {"unity", TargetEngine::unity},
    {"godot", TargetEngine::godot},
    {"unreal", TargetEngine::unreal},
}};

} // namespace

EngineLimits engine_limits(TargetEngine engine) {
  switch (engine) {
    case TargetEngine::any:
      return {"any engine",       kPhysxMaxVertices,         kPhysxMaxPolygons,
              kUnityMaxTriangles, kEngineMinThicknessMetres, kEngineHullToleranceMetres};
    // Godot 4.4 and later simulate with Jolt by default.
    case TargetEngine::jolt:
      return {"Jolt", kJoltMaxVertices, 0, 0, kEngineMinThicknessMetres, kEngineHullToleranceMetres};
    case TargetEngine::godot:
      return {"Godot (Jolt)", kJoltMaxVertices, 0, 0, kEngineMinThicknessMetres, kEngineHullToleranceMetres};
    case TargetEngine::physx:
      return {"PhysX", kPhysxMaxVertices, kPhysxMaxPolygons, 0, kEngineMinThicknessMetres, kEngineHullToleranceMetres};
    // Unreal's importer cooks UCX meshes as PhysX did before Chaos kept them.
    case TargetEngine::unreal:
      return {"Unreal", kPhysxMaxVertices, kPhysxMaxPolygons, 0, kEngineMinThicknessMetres, kEngineHullToleranceMetres};
    case TargetEngine::physx_gpu:
      return {"PhysX GPU", kPhysxGpuMaxVertices,      kPhysxMaxPolygons,
              0,           kEngineMinThicknessMetres, kEngineHullToleranceMetres};
    case TargetEngine::unity:
      return {"Unity",
              kPhysxMaxVertices,
              kPhysxMaxPolygons,
              kUnityMaxTriangles,
              kEngineMinThicknessMetres,
              kEngineHullToleranceMetres};
  }
  return engine_limits(TargetEngine::any);
}

std::optional<TargetEngine> engine_named(const std::string& name) {
  for (const auto& [engine_name, engine] : kEngines)
    if (name == engine_name) return engine;
  return std::nullopt;
}

std::vector<std::string> engine_names() {
  std::vector<std::string> names;
  for (const auto& entry : kEngines) names.emplace_back(entry.first);
  return names;
}

std::vector<std::string> engine_limit_breaches(const std::vector<ConvexPolytope>& hulls, const EngineLimits& limits) {
  std::vector<std::string> breaches;
  const auto over = [&](size_t hull, int count, int limit, const char* what, const std::string& remedy) {
    if (limit > 0 && count > limit)
      breaches.push_back("hull " + std::to_string(hull) + " has " + std::to_string(count) + " " + what + ", over " +
                         limits.name + "'s " + std::to_string(limit) + " (decompose with " + remedy + ")");
  };
  for (size_t h = 0; h < hulls.size(); ++h) {
    const ConvexPolytope& hull = hulls[h];
    over(h, static_cast<int>(hull.vertices.size()), limits.max_vertices, "vertices",
         "--max-hull-vertices " + std::to_string(limits.max_vertices));
    // A fanned hull has at least as many triangles as polygons, so the
    // triangle option keeps both.
    over(h, static_cast<int>(hull.facets.size()), limits.max_polygons, "polygons",
         "--max-hull-triangles " + std::to_string(limits.max_polygons));
    over(h, triangles_of_facets(hull.facets), limits.max_triangles, "triangles",
         "--max-hull-triangles " + std::to_string(limits.max_triangles));
  }
  return breaches;
}

} // namespace hullcover::app
