// `hullcover bench SCENE... [--agent-radius LIST] [--max-deviation LIST]
// [--agent-reach LIST] [--agent-slop LIST]`:
// speed against error. Every scene at every setting of the sweep, in one
// process: the covering, its runtime file timed against the triangles, and
// its audit; written as a CSV, a Markdown table and a plot.

#include "commands.h"
#include "number_checks.h"
#include "terminal_progress.h"
#include "scene_loading.h"

#include "bench/bench_plot.h"
#include "bench/bench_report.h"
#include "bench/bench_run.h"
#include "bench/bench_settings.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace hullcover::app {
namespace {

// The query capsule's half height, in radii: a standing character.
constexpr double kCapsuleHalfHeightPerRadius = 1.25;

struct BenchCommandOptions {
  std::vector<std::string> scenes;
  std::vector<std::string> agent_radii{"0", "0.3m"};
  std::vector<std::string> max_deviations{"0", "0.2%"};
  std::vector<std::string> agent_reaches{bench::kExactReach};
  std::vector<std::string> agent_slops;
  std::string query_radius = "0.4m";
  std::string out_dir = "bench";
  bench::BenchRunOptions run;
  ImportLimits limits;
  bool quiet = false;
};

int fail(const std::string& message) {
  std::fprintf(stderr, "hullcover: error: %s\n", message.c_str());
  return kExitBadInput;
}

// The capsule every setting of one scene is timed with: the query radius,
// raised to the sweep's largest agent radius (a covering for agents of
// radius r answers exactly only for shapes at least that wide).
double capsule_radius(const bench::SceneSpec& scene, double diagonal, const bench::LengthSpec& query_radius,
                      const std::vector<bench::Setting>& settings) {
  const double metre = scene.metre(diagonal);
  double radius = query_radius.resolve(metre, diagonal);
  for (const bench::Setting& s : settings) radius = std::max(radius, s.agent_radius.resolve(metre, diagonal));
  return radius;
}

int run_bench(BenchCommandOptions& o) {
  const Result<std::vector<bench::Setting>> settings =
      bench::sweep_settings(o.agent_radii, o.max_deviations, o.agent_reaches, o.agent_slops);
  if (!settings.ok()) return fail(settings.status().message());
  const Result<bench::LengthSpec> query_radius = bench::parse_length(o.query_radius);
  if (!query_radius.ok()) return fail(query_radius.status().message());
  if (!(query_radius.value().value > 0.0)) return fail("--query-radius must be > 0");
  std::vector<bench::SceneSpec> scenes;
  for (const std::string& text : o.scenes) {
    Result<bench::SceneSpec> scene = bench::parse_scene(text);
    if (!scene.ok()) return fail(scene.status().message());
    scenes.push_back(scene.value());
  }
  std::error_code made;
  std::filesystem::create_directories(o.out_dir, made);
  if (made || !std::filesystem::is_directory(o.out_dir)) return fail(o.out_dir + ": cannot create the output folder");
  o.run.out_dir = o.out_dir;

  std::vector<bench::BenchRow> rows;
  const size_t cells = scenes.size() * settings.value().size();
  TerminalProgress bar("bench", o.quiet);
  for (const bench::SceneSpec& scene : scenes) {
    const std::optional<LoadedScene> loaded = load_scene(scene.path, std::nullopt, o.limits);
    if (!loaded) return kExitBadInput;
    const PreparedMesh& prepared = loaded->prepared;
    const Result<std::shared_ptr<const bvh::TriangleWorld>> triangles =
        bvh::TriangleWorld::build(prepared.mesh, prepared.tolerance.length);
    if (!triangles.ok()) return fail(scene.path + ": " + triangles.status().message());
    const double radius = capsule_radius(scene, prepared.tolerance.diagonal, query_radius.value(), settings.value());
    const bench::QueryPoses poses =
        bench::surface_poses(prepared.mesh, radius, kCapsuleHalfHeightPerRadius * radius, o.run.query_poses, 42);
    for (const bench::Setting& setting : settings.value()) {
      bar.relabel("bench " + std::to_string(rows.size() + 1) + "/" + std::to_string(cells) + ": " + scene.path + " " +
                  setting.label());
      bar.update(static_cast<double>(rows.size()) / static_cast<double>(cells));
      Result<bench::BenchRow> row = bench::bench_setting(prepared, scene, setting, *triangles.value(), poses, o.run);
      if (!row.ok()) return fail(scene.path + " (" + setting.label() + "): " + row.status().message());
      const bench::BenchRow& r = row.value();
      if (bar.enabled()) {
        char line[512];
        std::snprintf(line, sizeof line,
                      "%s %s: %ld hulls in %.1f s; contacts %.2fx, yes/no %.2fx, ray %.2fx; audit %s in %.1f s",
                      scene.path.c_str(), setting.label().c_str(), r.hulls, r.decompose_seconds,
                      r.queries.contacts.speedup(), r.queries.touches.speedup(), r.queries.ray.speedup(),
                      r.clean ? "CLEAN" : r.findings.c_str(), r.audit_seconds);
        bar.note(line);
      }
      rows.push_back(std::move(row).value());
    }
  }

  bar.update(1.0);
  bar.finish();
  const std::filesystem::path out(o.out_dir);
  for (const Status& s : {bench::write_bench_csv(rows, (out / "bench.csv").string()),
                          bench::write_bench_markdown(rows, (out / "bench.md").string()),
                          bench::write_bench_plot(rows, (out / "bench.svg").string()),
                          bench::write_bench_plot(rows, (out / "bench.png").string())})
    if (!s.ok()) return fail(s.message());
  std::printf("%s", bench::bench_markdown(rows).c_str());
  std::printf("\nwrote %s/bench.csv, bench.md, bench.svg, bench.png and one .hcw per row\n", o.out_dir.c_str());
  const bool all_clean = std::all_of(rows.begin(), rows.end(), [](const bench::BenchRow& r) { return r.clean; });
  return all_clean ? kExitSuccess : kExitFinding;
}

} // namespace

void register_bench_command(CLI::App& app, int& exit_status) {
  auto o = std::make_shared<BenchCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "bench",
      "Speed against error: decompose every scene at every setting of the sweep (the exact covering at each\n"
      "agent radius with each max deviation; with --agent-reach walk or fly, movement coverings at each agent\n"
      "radius with each slop), write its runtime file, time it against the scene's triangles on the same capsule\n"
      "poses and rays (yes/no, contacts, ray; side by side, as speed-ups), and audit it with the setting's\n"
      "allowance (a movement covering: the movement audit for its agent).\n"
      "Writes DIR/bench.csv (every figure), bench.md (a table), bench.svg and bench.png (the plot) and one .hcw\n"
      "per row, and prints the table. Lengths are scene units, or end in 'm' (metres: the scene's units per\n"
      "metre) or '%' (of the scene's bounding-box diagonal); 0 is off.\n"
      "Exit status 0 every audit clean, 1 some audit found a violation, 2 bad input.");
  cmd->add_option("SCENES", o->scenes,
                  "Scenes: FILE@UNITS_PER_METRE for a level (e.g. map.obj@20 for 20 units per metre), or FILE for\n"
                  "an object, where 1 m stands for 1/50 of its diagonal")
      ->required();
  cmd->add_option("--agent-radius", o->agent_radii, "Agent radii to sweep, comma-separated")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--max-deviation", o->max_deviations, "Max deviations to sweep, comma-separated")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--agent-reach", o->agent_reaches,
                  "Coverings to sweep, comma-separated: exact (each agent radius with each max deviation), walk\n"
                  "and fly (movement coverings: each agent radius above 0 with each --agent-slop; they keep no rays)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--agent-slop", o->agent_slops,
                  "Slops to sweep for walk and fly, comma-separated, each above 0 (default: the decomposer's, r / 15)")
      ->delimiter(',');
  cmd->add_option("--query-radius", o->query_radius,
                  "Radius of the timed capsule (half height 1.25 radii), raised to the sweep's largest agent radius")
      ->capture_default_str();
  cmd->add_option("--query-poses", o->run.query_poses, "Capsule poses and rays timed per scene")
      ->check(count_from(1, 1 << 20))
      ->capture_default_str();
  cmd->add_option("--query-seconds", o->run.query_seconds, "Least time per query kind on each world, seconds")
      ->check(number_in(1e-3, 60.0))
      ->capture_default_str();
  cmd->add_option("--out", o->out_dir, "Folder for the files written (made if missing)")->capture_default_str();
  cmd->add_flag("-q,--quiet", o->quiet, "No progress bar (drawn on stderr only when it is a terminal)");
  add_import_limit_options(*cmd, o->limits);
  cmd->callback([o, &exit_status] { exit_status = run_bench(*o); });
}

} // namespace hullcover::app
