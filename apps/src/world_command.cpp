// `hullcover world SCENE... -o WORLD.obj --triangles N`: a test world made
// of copies of scenes laid on a grid, far apart, each turned by a multiple
// of 90 degrees about the up axis (turns and moves by whole grid steps keep
// every map the same shape to the last bit but for the moves' rounding).

#include "number_checks.h"
#include "commands.h"
#include "scene_loading.h"

#include "hullcover/mesh/mesh_export.h"

#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace hullcover::app {
namespace {

struct WorldOptions {
  std::vector<std::string> scenes;
  std::string output;
  long triangles = 0;
  double gap = 0.5;
  std::string up = "y";
  ImportLimits limits;
};

// One scene as the world takes it: centred over the origin, its lowest point
// at 0 along the up axis.
struct Piece {
  Mesh mesh;
  Aabb box;
};

// p turned by `quarter` quarter turns about the up axis (exact: a
// permutation with signs).
Eigen::Vector3d turned(const Eigen::Vector3d& p, int quarter, int up) {
  const int a = (up + 1) % 3, b = (up + 2) % 3;
  Eigen::Vector3d q = p;
  for (int i = 0; i < quarter; ++i) {
    const double x = q[a];
    q[a] = -q[b];
    q[b] = x;
  }
  return q;
}

int run_world(const WorldOptions& o) {
  const int up = o.up == "x" ? 0 : o.up == "z" ? 2 : 1;
  std::vector<Piece> pieces;
  double cell = 0.0;
  for (const std::string& spec : o.scenes) {
    // SCENE@UNITS_PER_METRE: scaled to metres, so levels in different units
    // sit together at their true sizes.
    std::string path = spec;
    double units_per_metre = 1.0;
    if (const size_t at = spec.rfind('@'); at != std::string::npos) {
      char* end = nullptr;
      units_per_metre = std::strtod(spec.c_str() + at + 1, &end);
      if (end == spec.c_str() + at + 1 || *end != '\0' || !(units_per_metre > 0.0) ||
          !(units_per_metre <= kLargestOptionValue)) {
        std::fprintf(stderr, "hullcover: error: %s: units per metre after '@' must be a number above 0, at most 1e15\n",
                     spec.c_str());
        return kExitBadInput;
      }
      path = spec.substr(0, at);
    }
    const std::optional<LoadedScene> scene = load_scene(path, std::nullopt, o.limits);
    if (!scene) return kExitBadInput;
    Piece piece;
    piece.mesh = scene->prepared.mesh;
    for (Eigen::Vector3d& p : piece.mesh.positions) p /= units_per_metre;
    piece.box = referenced_bounding_box(piece.mesh);
    cell = std::max(cell, (piece.box.max - piece.box.min).norm());
    pieces.push_back(std::move(piece));
  }
  // A grid step of the largest diagonal plus the gap: no turned copy reaches
  // its neighbour's square.
  const double step = std::ceil(cell * (1.0 + o.gap));
  Mesh world;
  long copies = 0;
  // A square grid: as many columns as the copies needed need rows.
  long round_triangles = 0;
  for (const Piece& piece : pieces) round_triangles += static_cast<long>(piece.mesh.triangles.size());
  const double copies_needed =
      static_cast<double>(pieces.size()) *
      std::max(1.0, std::ceil(static_cast<double>(o.triangles) / static_cast<double>(std::max(1L, round_triangles))));
  const long per_row_guess = std::max(1L, static_cast<long>(std::ceil(std::sqrt(copies_needed))));
  while (static_cast<long>(world.triangles.size()) < std::max<long>(1, o.triangles) || copies == 0) {
    for (const Piece& piece : pieces) {
      const int quarter = static_cast<int>(copies % 4);
      const long row = copies / per_row_guess, column = copies % per_row_guess;
      Eigen::Vector3d centre = 0.5 * (piece.box.min + piece.box.max);
      centre[up] = piece.box.min[up];
      Eigen::Vector3d offset = Eigen::Vector3d::Zero();
      offset[(up + 1) % 3] = step * static_cast<double>(column);
      offset[(up + 2) % 3] = step * static_cast<double>(row);
      const int base = static_cast<int>(world.positions.size());
      for (const Eigen::Vector3d& p : piece.mesh.positions)
        world.positions.push_back(turned(p - centre, quarter, up) + offset);
      for (const Eigen::Vector3i& t : piece.mesh.triangles)
        world.triangles.push_back(t + Eigen::Vector3i::Constant(base));
      world.material_ids.insert(world.material_ids.end(), piece.mesh.triangles.size(), 0);
      ++copies;
      if (static_cast<long>(world.triangles.size()) >= o.triangles && o.triangles > 0) break;
    }
  }
  if (Status s = write_mesh_obj(world, o.output); !s.ok()) {
    std::fprintf(stderr, "hullcover: error: %s\n", s.message().c_str());
    return kExitBadInput;
  }
  std::printf("%s: %ld copies, %zu triangles, grid step %.6g\n", o.output.c_str(), copies, world.triangles.size(),
              step);
  return kExitSuccess;
}

} // namespace

void register_world_command(CLI::App& app, int& exit_status) {
  auto o = std::make_shared<WorldOptions>();
  CLI::App* cmd = app.add_subcommand(
      "world",
      "Build a test world: copies of the scenes, in turn, on a square grid (a step of the largest scene's\n"
      "diagonal plus a gap, so no copy touches another), each turned by the next multiple of 90 degrees\n"
      "about the up axis, until the world holds --triangles. Writes one OBJ.");
  cmd->add_option("SCENES", o->scenes, "Scene files, taken in turn; SCENE@N scales one in N units per metre to metres")
      ->required();
  cmd->add_option("-o,--output", o->output, "The world OBJ")->required();
  cmd->add_option("--triangles", o->triangles, "Stop once the world holds at least this many (default: one copy each)")
      ->check(count_from(0, kMostWorldTriangles));
  cmd->add_option("--gap", o->gap, "Space between copies, as a fraction of the largest diagonal")
      ->check(non_negative_number())
      ->capture_default_str();
  cmd->add_option("--up", o->up, "Up axis (turns are about it; copies lie on its floor plane)")
      ->check(CLI::IsMember({"x", "y", "z"}))
      ->capture_default_str();
  add_import_limit_options(*cmd, o->limits);
  cmd->callback([o, &exit_status] { exit_status = run_world(*o); });
}

} // namespace hullcover::app
