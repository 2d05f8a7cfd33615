// `hullcover info FILE`: what the importer, welding and connectivity see.

#include "help_numbers.h"
#include "hullcover/geometry/tolerances.h"
#include "commands.h"
#include "number_checks.h"
#include "mesh_report.h"

#include "scene_loading.h"

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

namespace hullcover::app {
namespace {

struct InfoOptions {
  std::string path;
  std::optional<double> tolerance;
  ImportLimits limits;
  bool json = false;
};

int run_info(const InfoOptions& options) {
  const std::optional<LoadedScene> scene = load_scene(options.path, options.tolerance, options.limits);
  if (!scene) return kExitBadInput;
  const MeshFigures figures = measure_mesh(scene->prepared);
  const ImportReport& report = scene->report;
  if (options.json) {
    nlohmann::json out = mesh_figures_json(figures);
    out["file"] = options.path;
    out["skipped_non_triangle_primitives"] = report.skipped_non_triangle_primitives;
    std::cout << out.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n"; // a path need not be UTF-8
  } else {
    std::printf("%s\n%s", options.path.c_str(), format_mesh_figures(figures).c_str());
    if (report.skipped_non_triangle_primitives > 0)
      std::printf("  %-24s %d\n", "skipped points/lines", report.skipped_non_triangle_primitives);
  }
  return kExitSuccess;
}

} // namespace

void register_info_command(CLI::App& app, int& exit_status) {
  auto options = std::make_shared<InfoOptions>();
  CLI::App* info =
      app.add_subcommand("info",
                         "Print what hullcover sees in a scene file: triangles, vertices before and after welding,\n"
                         "components, boundary / non-manifold edges, orientation conflicts, zero-area faces,\n"
                         "bounding box and the tolerance used.");
  info->add_option("FILE", options->path, "Scene file: OBJ, PLY, STL, glTF/GLB, FBX (anything Assimp reads)")
      ->required();
  info->add_option("--tol", options->tolerance,
                   "Tolerance in scene units for welding and zero-area tests\n(default " +
                       number_text(kDefaultRelativeTolerance) +
                       " x each place's diagonal; never below the data's rounding floor)")
      ->check(positive_number());
  add_import_limit_options(*info, options->limits);
  info->add_flag("--json", options->json, "Print the figures as JSON on standard output");
  info->callback([options, &exit_status] { exit_status = run_info(*options); });
}

} // namespace hullcover::app
