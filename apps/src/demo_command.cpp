// `hullcover demo`: the whole product on the embedded default scene, for a
// first run with nothing but a build: decompose, audit, draw, then load the
// runtime file and ask it what a game server asks.

#include "audit_printout.h"
#include "commands.h"
#include "mesh_report.h"

#include "render/scene_picture.h"

#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/bvh/hull_world.h"
#include "hullcover/bvh/runtime_file.h"
#include "hullcover/covering/covering.h"
#include "hullcover/covering/covering_export.h"
#include "hullcover/mesh/mesh_export.h"
#include "hullcover/mesh/scene_builder.h"
#include "hullcover/validate/audit.h"
#include "hullcover/validate/hull_set.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

namespace hullcover::app {
namespace {

struct DemoOptions {
  std::string out_dir = "hullcover-demo";
};

// The demo's character and shot, in the building's metres (demo_building:
// floor top at y = 0, interior wall across x = -0.1 .. 0.1 up to z = 1.5).
// The character is a capsule of radius 0.3 with a 1.2 m axis, standing on
// the floor sunk 1 cm into it, as a controller's step leaves it; the ray
// is a shot at chest height towards the interior wall.
constexpr double kCharacterRadius = 0.3;
constexpr double kCharacterHalfAxis = 0.6;
constexpr double kCharacterSink = 0.01;
constexpr double kCharacterFeet[3] = {2.5, 0.0, 0.0};
constexpr double kShotOrigin[3] = {-3.0, 1.4, 0.0};
constexpr double kShotDirection[3] = {1.0, 0.0, 0.0};

Eigen::Vector3d point(const double (&p)[3]) { return {p[0], p[1], p[2]}; }
constexpr double kShotReach = 20.0;

int fail(const Status& status) {
  std::fprintf(stderr, "hullcover: error: demo: %s\n", status.message().c_str());
  return kExitBadInput;
}

void print_point(const char* name, const Eigen::Vector3d& v) {
  std::printf("%s (%.4g, %.4g, %.4g)", name, v.x(), v.y(), v.z());
}

// The runtime file as a server loads it, asked one character contact and one ray.
int query_runtime(const std::string& world_path, std::vector<render::Marker>& markers) {
  Result<std::vector<bvh::RuntimeHull>> hulls = bvh::read_runtime_file(world_path);
  if (!hulls.ok()) return fail(hulls.status());
  Result<std::shared_ptr<const bvh::HullWorld>> built = bvh::HullWorld::build(std::move(hulls).value());
  if (!built.ok()) return fail(built.status());
  const bvh::HullWorld& world = *built.value();

  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  // QueryShape::capsule's axis is local z: stand it up along y.
  pose.linear() =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY()).toRotationMatrix();
  const Eigen::Vector3d feet = point(kCharacterFeet), origin = point(kShotOrigin), along = point(kShotDirection);
  pose.translation() = feet + Eigen::Vector3d(0.0, kCharacterRadius + kCharacterHalfAxis - kCharacterSink, 0.0);
  bvh::ContactResult contacts;
  if (Status s = world.contacts({bvh::QueryShape::capsule(kCharacterRadius, kCharacterHalfAxis), pose, 8}, contacts);
      !s.ok())
    return fail(s);
  print_point("query: character (capsule r 0.3, half-axis 0.6) standing at", feet);
  std::printf(": %zu contact(s)\n", contacts.contacts.size());
  for (const bvh::Contact& c : contacts.contacts) {
    std::printf("  hull %d, depth %.4g,", c.hull, c.depth);
    print_point(" normal", c.normal);
    print_point(", at", c.point);
    std::printf("\n");
    markers.push_back({c.point, 0.1, {0.0, 0.45, 0.9}, "C"});
  }

  bvh::RayResult shot;
  if (Status s = world.ray_cast({origin, along, kShotReach}, shot); !s.ok()) return fail(s);
  print_point("query: ray from", origin);
  print_point(" along", along);
  if (!shot.hit) {
    std::printf(": no hit within %.4g\n", kShotReach);
    return kExitSuccess;
  }
  std::printf(": hull %d at distance %.4g,", shot.first.hull, shot.first.t);
  print_point(" point", shot.first.point);
  print_point(", normal", shot.first.normal);
  std::printf("\n");
  markers.push_back({origin, 0.1, {0.9, 0.5, 0.0}, "R"});
  markers.push_back({shot.first.point, 0.1, {0.9, 0.5, 0.0}, "H"});
  return kExitSuccess;
}

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
  if (Status written = write_mesh_obj(scene, scene_path); !written.ok()) return fail(written);
  Result<PreparedMesh> prepared = prepare_mesh(scene, std::nullopt);
  if (!prepared.ok()) return fail(prepared.status());
  const MeshFigures figures = measure_mesh(prepared.value());
  std::printf("demo scene: a building with a doorway, an interior wall, stairs and a terrain patch\n%s",
              format_mesh_figures(figures).c_str());

  // 1. Decompose, and write the hulls, their figures and the runtime file.
  const Result<Covering> covering = decompose(prepared.value(), DecomposeOptions{});
  if (!covering.ok()) return fail(covering.status());
  const Covering& c = covering.value();
  const std::string hulls_path = options.out_dir + "/demo-hulls.obj";
  const std::string json_path = options.out_dir + "/demo-hulls.json";
  const std::string world_path = options.out_dir + "/demo-world.hcw";
  nlohmann::json extra;
  extra["scene"] = mesh_figures_json(figures);
  for (const Status& s : {write_covering_obj(c, hulls_path), write_covering_json(c, extra, json_path),
                          bvh::write_covering_runtime_file(c, world_path)})
    if (!s.ok()) return fail(s);
  const CoveringStatistics& st = c.statistics;
  std::printf("decomposed: %d faces -> %zu hulls (%.3f hulls/face) in %.3f s\n", st.faces, c.hulls.size(),
              static_cast<double>(c.hulls.size()) / st.faces,
              st.seconds_index + st.seconds_merging + st.seconds_output);
  std::printf("wrote %s, %s, %s and %s\n", scene_path.c_str(), hulls_path.c_str(), json_path.c_str(),
              world_path.c_str());

  // 2. Audit the hull file as written, as `hullcover audit` would.
  Result<validate::HullSet> set = validate::load_hull_set(hulls_path);
  if (!set.ok()) return fail(set.status());
  const Result<validate::AuditReport> audited = validate::run_audit(prepared.value(), set.value(), {});
  if (!audited.ok()) return fail(audited.status());
  std::printf("audit: ");
  print_audit(hulls_path, prepared.value(), audited.value());

  // 3. Ask the runtime file what a game server asks.
  std::vector<render::Marker> markers;
  if (const int status = query_runtime(world_path, markers); status != kExitSuccess) return status;

  // 4. The picture: the hulls, each in its colour, roof and front walls cut
  // away, with the character's contacts (C) and the ray's start (R) and hit (H).
  render::PictureContent content;
  content.scene = &prepared.value().mesh;
  content.hulls = &set.value().hulls;
  content.markers = std::move(markers);
  render::PictureOptions picture;
  picture.cut = true;
  const std::string picture_path = options.out_dir + "/demo-hulls.png";
  if (Status written = render::write_scene_picture_png(content, picture, picture_path); !written.ok())
    return fail(written);
  std::printf("picture: %s (hulls in colour, roof and front walls cut away; C contact, R ray start, H ray hit)\n",
              picture_path.c_str());
  return audited.value().clean() ? kExitSuccess : kExitFinding;
}

} // namespace

void register_demo_command(CLI::App& app, int& exit_status) {
  auto options = std::make_shared<DemoOptions>();
  CLI::App* demo = app.add_subcommand(
      "demo",
      "Run the whole product on the embedded default scene (a small building with a doorway, an interior\n"
      "wall, stairs and a terrain patch, generated in code): decompose it, audit the hulls, query the\n"
      "runtime file with a standing character and a ray, and draw the hulls; writes everything to --out.");
  demo->add_option("--out", options->out_dir, "Directory for the outputs")->capture_default_str();
  demo->callback([options, &exit_status] { exit_status = run_demo(*options); });
}

} // namespace hullcover::app
