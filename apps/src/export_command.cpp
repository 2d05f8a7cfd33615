// `hullcover export HULLS -o OUT`: a covering's hulls as engines import them.

#include "help_numbers.h"
#include "number_checks.h"
#include "commands.h"
#include "export/collider_export.h"
#include "scene_loading.h"

#include "hullcover/geometry/tolerances.h"
#include "hullcover/validate/hull_set.h"

#include <cstdio>
#include <memory>
#include <string>

namespace hullcover::app {
namespace {

struct ExportCommandOptions {
  std::string hulls_path;
  std::string out_path;
  std::string scene_path;
  std::optional<double> tolerance;
  ImportLimits limits;
  ColliderExportOptions exported;
};

int run_export(const ExportCommandOptions& o) {
  const Result<validate::HullSet> set = validate::load_hull_set(o.hulls_path);
  if (!set.ok()) {
    std::fprintf(stderr, "hullcover: error: %s\n", set.status().message().c_str());
    return kExitBadInput;
  }
  std::optional<LoadedScene> scene;
  if (!o.scene_path.empty()) {
    scene = load_scene(o.scene_path, o.tolerance, o.limits);
    if (!scene) return kExitBadInput;
  } else if (o.exported.with_scene) {
    std::fprintf(stderr, "hullcover: error: --with-scene needs --scene SCENE\n");
    return kExitBadInput;
  }
  // Without the scene, the tolerance is the scene's default taken from the
  // hulls' own box (they cover the scene, so it is the same box).
  double tol = 0.0;
  if (scene) {
    tol = scene->prepared.tolerance.length;
  } else if (o.tolerance) {
    tol = *o.tolerance;
  } else {
    Aabb box;
    for (const bvh::RuntimeHull& hull : set.value().hulls) {
      if (hull.box.empty()) continue;
      box.extend(hull.box.min);
      box.extend(hull.box.max);
    }
    tol = kDefaultRelativeTolerance * box.diagonal();
  }
  const Result<ColliderExportReport> report =
      export_colliders(set.value().hulls, tol, scene ? &scene->prepared.mesh : nullptr, o.exported, o.out_path);
  if (!report.ok()) {
    std::fprintf(stderr, "hullcover: error: %s\n", report.status().message().c_str());
    return kExitBadInput;
  }
  std::printf("%s\n", describe_export(report.value(), o.out_path).c_str());
  return kExitSuccess;
}

} // namespace

void register_export_command(CLI::App& app, int& exit_status) {
  auto o = std::make_shared<ExportCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "export",
      "Write a covering's hulls (a hull OBJ or .hcw) as engines import them: glTF binary with every hull a static "
      "convex collider (KHR_physics_rigid_bodies and OMI_physics_shape), or OBJ with Unreal (--ucx) or Godot "
      "(--godot) collider names. Flat hulls get a thickness engines accept (behind the face, or half each side of a "
      "double-sided sheet); every hull is checked against the engine's limits.");
  cmd->add_option(
         "hulls", o->hulls_path,
         "Hull file: a hull OBJ (as decompose writes), a .hcw runtime file, or an export (.glb, UCX or Godot OBJ)")
      ->required();
  cmd->add_option("-o,--out", o->out_path, "Output file (.glb or .obj)")->required();
  cmd->add_option("--scene", o->scene_path,
                  "The scene the hulls cover: its tolerance, and its triangles for "
                  "--with-scene");
  cmd->add_option("--tol", o->tolerance,
                  "Tolerance, scene units (default: the scene's, or " + number_text(kDefaultRelativeTolerance) +
                      " of the hulls' bounding-box diagonal)")
      ->check(positive_number());
  add_collider_export_options(cmd, o->exported);
  add_import_limit_options(*cmd, o->limits);
  cmd->footer("Exit status: 0 written, 2 unreadable input, bad usage or a hull over the engine's limits.");
  cmd->callback([o, &exit_status] { exit_status = run_export(*o); });
}

} // namespace hullcover::app
