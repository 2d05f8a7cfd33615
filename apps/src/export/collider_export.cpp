#include "export/collider_export.h"
#include "number_checks.h"

#include "export/collider_obj_writer.h"
#include "export/cooking_margin.h"
#include "export/flat_hull_thickening.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace hullcover::app {
namespace {

// Breaches listed in an error before "and N more".
constexpr size_t kBreachesListed = 5;

Status breaches_status(const std::vector<std::string>& breaches, const std::string& what) {
  std::string message = std::to_string(breaches.size()) + " " + what + ":";
  for (size_t i = 0; i < std::min(breaches.size(), kBreachesListed); ++i) message += "\n  " + breaches[i];
  if (breaches.size() > kBreachesListed)
    message += "\n  and " + std::to_string(breaches.size() - kBreachesListed) + " more";
  return Status{StatusCode::invalid_argument, message};
}

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         std::equal(suffix.rbegin(), suffix.rend(), s.rbegin(), [](char a, char b) { return std::tolower(a) == b; });
}

std::optional<ColliderFormat> format_of(const ColliderExportOptions& options, const std::string& path) {
  const std::string& f = options.format;
  if (f == "glb" || (f.empty() && ends_with(path, ".glb"))) return ColliderFormat::glb;
  if (f == "obj" || (f.empty() && ends_with(path, ".obj"))) return ColliderFormat::obj;
  return std::nullopt;
}

std::string padded(size_t number, int digits) {
  std::string text = std::to_string(number);
  if (static_cast<int>(text.size()) < digits) text.insert(0, digits - text.size(), '0');
  return text;
}

std::vector<std::string> collider_names(size_t count, const ColliderExportOptions& options) {
  std::vector<std::string> names;
  for (size_t h = 0; h < count; ++h) {
    if (!options.ucx_name.empty())
      names.push_back("UCX_" + options.ucx_name + "_" + padded(h, 2)); // Unreal numbers them _00, _01, ...
    else if (options.godot_names)
      names.push_back("hull_" + padded(h, 3) + "-convcolonly");
    else
      names.push_back("hull_" + padded(h, 3));
  }
  return names;
}

} // namespace

void add_collider_export_options(CLI::App* command, ColliderExportOptions& options) {
  command
      ->add_option("--format", options.format,
                   "glb (glTF binary, physics extensions) or obj; default from the "
                   "output's extension")
      ->check(CLI::IsMember({"glb", "obj"}));
  auto* ucx = command->add_option("--ucx", options.ucx_name,
                                  "Unreal names: hull i is UCX_NAME_<ii>, the collision of the mesh NAME (with "
                                  "--with-scene the scene is that mesh)");
  command->add_flag("--godot", options.godot_names, "Godot names: hull_<iii>-convcolonly (a convex collider, no mesh)")
      ->excludes(ucx);
  std::string engines;
  for (const std::string& name : engine_names()) engines += (engines.empty() ? "" : ", ") + name;
  command
      ->add_option("--engine", options.engine,
                   "Engine whose convex-collider limits every hull must meet: " + engines +
                       " (any: 256 vertices, 255 polygons, 255 triangles)")
      ->check(CLI::IsMember(engine_names()))
      ->capture_default_str();
  command
      ->add_option("--flat-thickness", options.flat_thickness,
                   "Thickness given to flat hulls, scene units (default: 2 mm, the thinnest the engines cook, "
                   "and at least 4 tol); behind the face, or half each side of a double-sided sheet")
      ->check(positive_number());
  command
      ->add_option("--units-per-metre", options.units_per_metre, "Scene units in a metre (for the default thickness)")
      ->check(positive_number())
      ->capture_default_str();
  command->add_flag("--with-scene", options.with_scene, "Also carry the scene's triangles as a render mesh");
}

Result<ColliderExportReport> export_colliders(const std::vector<bvh::RuntimeHull>& hulls, double tol, const Mesh* scene,
                                              const ColliderExportOptions& options, const std::string& path) {
  const std::optional<ColliderFormat> format = format_of(options, path);
  if (!format)
    return Status{StatusCode::invalid_argument, path + ": give --format glb or obj (or end the name in .glb or .obj)"};
  // The name becomes OBJ object names and Unreal asset names: letters,
  // digits, '_' and '-' only, so no line break or space can split a line.
  if (!std::all_of(options.ucx_name.begin(), options.ucx_name.end(),
                   [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; }))
    return Status{StatusCode::invalid_argument, "--ucx NAME may hold only letters, digits, '_' and '-'"};
  const std::optional<TargetEngine> engine = engine_named(options.engine);
  if (!engine) return Status{StatusCode::invalid_argument, "unknown engine '" + options.engine + "'"};
  if (options.with_scene && !scene) return Status{StatusCode::invalid_argument, "--with-scene needs the scene"};
  const EngineLimits limits = engine_limits(*engine);
  const double thickness = options.flat_thickness.value_or(
      std::max(limits.min_thickness_metres * options.units_per_metre, kFlatThicknessInTolerances * tol));
  if (!(std::isfinite(thickness) && thickness > 0.0))
    return Status{StatusCode::invalid_argument, "flat thickness must be a length > 0"};
  const ThickenedHulls thick = thicken_flat_hulls(hulls, thickness, tol);
  const CookingRepair cooked =
      repair_cooking_margins(thick.hulls, limits.hull_tolerance_metres * options.units_per_metre);
  if (!cooked.failures.empty()) return breaches_status(cooked.failures, "hull(s) the engine cannot cook as they are");
  const std::vector<std::string> breaches = engine_limit_breaches(cooked.hulls, limits);
  if (!breaches.empty()) return breaches_status(breaches, "hull limit(s) broken");
  const std::vector<std::string> names = collider_names(cooked.hulls.size(), options);
  RenderMesh render;
  if (options.with_scene) render = {scene, options.ucx_name.empty() ? "scene" : options.ucx_name};
  const Status written = *format == ColliderFormat::glb ? write_collider_glb(cooked.hulls, names, render, path)
                                                        : write_collider_obj(cooked.hulls, names, render, path);
  if (!written.ok()) return written;
  ColliderExportReport report;
  report.format = *format;
  report.hulls = static_cast<int>(thick.hulls.size());
  report.flat_thickened = thick.flat;
  report.split = thick.split;
  report.thickness = thickness;
  report.cooking_repaired = cooked.repaired;
  report.cooking_margin = cooked.margin;
  report.engine = limits.name;
  return report;
}

std::string describe_export(const ColliderExportReport& report, const std::string& path) {
  char line[512];
  std::snprintf(line, sizeof line,
                "exported %d hulls to %s (%s, within %s limits); %d flat hulls given thickness %.6g (%d split across a "
                "double-sided sheet): free space lost to them lies within %.6g of the mesh",
                report.hulls, path.c_str(), report.format == ColliderFormat::glb ? "glTF binary" : "OBJ",
                report.engine.c_str(), report.flat_thickened, report.thickness, report.split, report.thickness);
  std::string text = line;
  if (report.cooking_repaired > 0) {
    std::snprintf(line, sizeof line,
                  "; %d hulls given corners at least %.6g clear of the others so the engine's hull builder keeps "
                  "them, growing by at most %.6g",
                  report.cooking_repaired, report.cooking_margin, report.cooking_margin);
    text += line;
  }
  return text;
}

} // namespace hullcover::app
