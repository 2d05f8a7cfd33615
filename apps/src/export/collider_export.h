#pragma once
/// \file collider_export.h
/// An engine export of a covering's hulls (`hullcover export`, `hullcover
/// decompose --format`): flat hulls thickened (flat_hull_thickening.h),
/// corners kept clear for the engine's hull builder (cooking_margin.h),
/// every hull checked against the target engine's limits
/// (engine_limits.h), then written as glTF binary or OBJ with the engine's
/// collider names.

#include "export/collider_glb_writer.h"
#include "export/engine_limits.h"

#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/geometry/status.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace hullcover::app {

/// The file an export writes.
enum class ColliderFormat { glb, obj };

/// What an export is asked for (the command line's options).
struct ColliderExportOptions {
  std::string format;         ///< "glb", "obj", or "" (from the output's extension)
  std::string ucx_name;       ///< Unreal naming: UCX_<ucx_name>_<NN>; "" off
  bool godot_names = false;   ///< Godot naming: hull_<NNN>-convcolonly
  std::string engine = "any"; ///< engine_named
  /// Thickness of flat hulls, scene units; default the engine's smallest
  /// (EngineLimits::min_thickness_metres x units_per_metre), at least
  /// kFlatThicknessInTolerances x tol.
  std::optional<double> flat_thickness;
  double units_per_metre = 1.0; ///< scene units in a metre
  bool with_scene = false;      ///< carry the scene's triangles as a render mesh
};

/// A flat hull is never thinner than this many tolerances, so the audit,
/// which calls "inside" only what lies deeper than tol, sees a solid.
inline constexpr double kFlatThicknessInTolerances = 4.0;

/// What an export wrote.
struct ColliderExportReport {
  ColliderFormat format = ColliderFormat::glb;
  int hulls = 0;
  int flat_thickened = 0; ///< flat hulls given a thickness
  int split = 0;          ///< of those, split across both sides of a double-sided sheet
  double thickness = 0.0; ///< scene units
  /// Hulls whose corners were pushed clear of the others so the engine's
  /// hull builder keeps every one (cooking_margin.h), and that clearance
  /// (scene units): no point moved farther out than it.
  int cooking_repaired = 0;
  double cooking_margin = 0.0;
  std::string engine; ///< the limits checked
};

/// Adds the export options (--format, --ucx, --godot, --engine,
/// --flat-thickness, --units-per-metre, --with-scene) to `command`.
void add_collider_export_options(CLI::App* command, ColliderExportOptions& options);

/// Exports `hulls` to `path`. `tol` is the covering's tolerance (scene
/// units); `scene` is carried when options.with_scene (it must then be
/// given). Fails with `invalid_argument` (format not known from the
/// options or the extension, an unknown engine, a hull over the engine's
/// limits: every breach named, with the decompose option that prevents
/// it) or `unwritable_file`.
[[nodiscard]] Result<ColliderExportReport> export_colliders(const std::vector<bvh::RuntimeHull>& hulls, double tol,
                                                            const Mesh* scene, const ColliderExportOptions& options,
                                                            const std::string& path);

/// One line for the console: what was written and the thickness used.
std::string describe_export(const ColliderExportReport& report, const std::string& path);

} // namespace hullcover::app
