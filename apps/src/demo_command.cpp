// `hullcover demo`: the main job on the embedded default scene, for a first
// run with nothing but a build.

#include "commands.h"
#include "mesh_report.h"

#include "hullcover/covering/covering_export.h"
#include "hullcover/mesh/mesh_export.h"
#include "hullcover/mesh/scene_builder.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

namespace hullcover::app {
namespace {

struct DemoOptions {
  std::string out_dir = "hullcover-demo";
};

int run_demo(const DemoOptions& options) {
  std::error_code error;
  std::filesystem::create_directories(options.out_dir, error);
  if (error) {
    std::fprintf(stderr, "hullcover: error: %s: cannot create directory: %s\n", options.out_dir.c_str(),
                 error.message().c_str());
    return kExitBadInput;
  }
  const Mesh scene = demo_building();
  const std::string scene_path = options.out_dir + "/demo-scene.obj";
  if (Status written = write_mesh_obj(scene, scene_path); !written.ok()) {
    std::fprintf(stderr, "hullcover: error: %s\n", written.message().c_str());
    return kExitBadInput;
  }
  Result<PreparedMesh> prepared = prepare_mesh(scene, std::nullopt);
  if (!prepared.ok()) {
    std::fprintf(stderr, "hullcover: error: demo scene: %s\n", prepared.status().message().c_str());
    return kExitBadInput;
  }
  const MeshFigures figures = measure_mesh(prepared.value());
  std::printf("demo scene: a building with a doorway, an interior wall, stairs and a terrain patch\n%s",
              format_mesh_figures(figures).c_str());

  const Result<Covering> covering = decompose(prepared.value(), DecomposeOptions{});
  if (!covering.ok()) {
    std::fprintf(stderr, "hullcover: error: demo scene: %s\n", covering.status().message().c_str());
    return kExitBadInput;
  }
  const Covering& c = covering.value();
  const std::string hulls_path = options.out_dir + "/demo-hulls.obj";
  const std::string json_path = options.out_dir + "/demo-hulls.json";
  nlohmann::json extra;
  extra["scene"] = mesh_figures_json(figures);
  for (const Status& s : {write_covering_obj(c, hulls_path), write_covering_json(c, extra, json_path)})
    if (!s.ok()) {
      std::fprintf(stderr, "hullcover: error: %s\n", s.message().c_str());
      return kExitBadInput;
    }
  const CoveringStatistics& st = c.statistics;
  std::printf("decomposed: %d faces -> %zu hulls (%.3f hulls/face) in %.3f s\n", st.faces, c.hulls.size(),
              static_cast<double>(c.hulls.size()) / st.faces, st.seconds_index + st.seconds_merging + st.seconds_output);
  std::printf("wrote %s, %s and %s\n", scene_path.c_str(), hulls_path.c_str(), json_path.c_str());
  return kExitSuccess;
}

} // namespace

void register_demo_command(CLI::App& app, int& exit_status) {
  auto options = std::make_shared<DemoOptions>();
  CLI::App* demo = app.add_subcommand(
      "demo", "Run the main job on the embedded default scene (a small building with a doorway,\n"
              "an interior wall, stairs and a terrain patch, generated in code) and write its outputs.");
  demo->add_option("--out", options->out_dir, "Directory for the outputs")->capture_default_str();
  demo->callback([options, &exit_status] { exit_status = run_demo(*options); });
}

} // namespace hullcover::app
