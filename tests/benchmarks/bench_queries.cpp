// Runtime query benchmark (not a test): HullWorld against the triangle
// baseline (TriangleWorld, FCL on the original triangles), side by side in
// one run over the same poses: character-sized shapes placed near the
// surfaces of each shared scene. Each benchmark reports microseconds per
// query for both worlds and the speed-up (triangles / hulls); the issue's
// goal is a speed-up of at least 3 for capsule contacts.
//
//   build/release/tests/hullcover_bench_queries [--benchmark_filter=pandora]

#include "shared_data.h"
#include "temp_dir.h"

#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/bvh/hull_world.h"
#include "hullcover/bvh/runtime_file.h"
#include "hullcover/bvh/triangle_world.h"
#include "hullcover/covering/covering.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <random>

namespace {

using namespace hullcover;
using namespace hullcover::bvh;
using Clock = std::chrono::steady_clock;

// Scene units per metre, from ../shared/data/scenes/SOURCES.md; 0 = an
// object, not a level: the character is sized from its diagonal instead.
struct SceneScale {
  const char* file;
  double units_per_metre;
};
const SceneScale kScenes[] = {{"recast-dungeon.obj", 1.0},        {"recast-nav_test.obj", 1.0},
                              {"recast-undulating.obj", 1.0},     {"sauerbraten-fdm6.obj", 20.0},
                              {"sauerbraten-pandora.obj", 20.0},  {"stanford-bunny-res2.ply", 0.0},
                              {"thor-art56-gearplate.stl", 0.0},  {"threejs-collision-world.glb", 1.0}};
constexpr int kPoses = 512;

struct Scene {
  std::shared_ptr<const HullWorld> hulls;
  std::shared_ptr<const TriangleWorld> triangles;
  std::vector<Eigen::Isometry3d> poses;  // near surfaces
  std::vector<Eigen::Vector3d> ray_directions;
  double radius = 0.4, half_height = 0.5;  // character capsule, scene units
};

Scene make_scene(const PreparedMesh& prepared, const Covering& covering, double units_per_metre) {
  Scene s;
  s.hulls = build_hull_world(covering).value();
  s.triangles = TriangleWorld::build(prepared.mesh, prepared.tolerance.length).value();
  const double diagonal = prepared.tolerance.diagonal;
  const double metre = units_per_metre > 0.0 ? units_per_metre : diagonal / 50.0;
  s.radius = 0.4 * metre;
  s.half_height = 0.5 * metre;
  std::mt19937 rng(42);
  std::uniform_int_distribution<int> face(0, static_cast<int>(prepared.mesh.triangles.size()) - 1);
  std::uniform_real_distribution<double> u(0.0, 1.0), offset(-0.5, 1.5);
  while (static_cast<int>(s.poses.size()) < kPoses) {
    const int f = face(rng);
    const Eigen::Vector3d n = triangle_area_vector(prepared.mesh, f);
    if (n.norm() == 0.0) continue;
    double a = u(rng), b = u(rng);
    if (a + b > 1.0) a = 1.0 - a, b = 1.0 - b;
    const Eigen::Vector3i& t = prepared.mesh.triangles[f];
    const Eigen::Vector3d p = prepared.mesh.positions[t[0]] + a * (prepared.mesh.positions[t[1]] - prepared.mesh.positions[t[0]]) +
                              b * (prepared.mesh.positions[t[2]] - prepared.mesh.positions[t[0]]);
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = p + n.normalized() * (offset(rng) * s.radius);
    pose.linear() = Eigen::Quaterniond(Eigen::Vector4d(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5).normalized())
                        .toRotationMatrix();
    s.poses.push_back(pose);
    s.ray_directions.push_back(-n.normalized() + 0.3 * Eigen::Vector3d(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5));
  }
  return s;
}

// Runs `hull_query(i)` and `triangle_query(i)` over every pose, timing both.
void side_by_side(benchmark::State& state, const std::function<void(int)>& hull_query,
                  const std::function<void(int)>& triangle_query) {
  double hull_seconds = 0.0, triangle_seconds = 0.0;
  for (auto _ : state) {
    Clock::time_point start = Clock::now();
    for (int i = 0; i < kPoses; ++i) hull_query(i);
    const double h = std::chrono::duration<double>(Clock::now() - start).count();
    start = Clock::now();
    for (int i = 0; i < kPoses; ++i) triangle_query(i);
    const double t = std::chrono::duration<double>(Clock::now() - start).count();
    state.SetIterationTime(h);
    hull_seconds += h;
    triangle_seconds += t;
  }
  const double queries = static_cast<double>(state.iterations()) * kPoses;
  state.counters["hull_us"] = 1e6 * hull_seconds / queries;
  state.counters["triangle_us"] = 1e6 * triangle_seconds / queries;
  state.counters["speedup"] = triangle_seconds / hull_seconds;
}

void register_scene(const std::string& name, std::shared_ptr<Scene> s) {
  const auto reg = [&](const std::string& what, std::function<void(benchmark::State&)> fn) {
    benchmark::RegisterBenchmark(("query/" + name + "/" + what).c_str(), fn)->UseManualTime()->Unit(benchmark::kMicrosecond);
  };
  const auto contacts = [s](QueryShape shape) {
    return [s, shape](benchmark::State& state) {
      ContactResult r;
      side_by_side(
          state, [&](int i) { benchmark::DoNotOptimize(s->hulls->contacts({shape, s->poses[i], 8}, r)); },
          [&](int i) { benchmark::DoNotOptimize(s->triangles->contacts({shape, s->poses[i], 8}, r)); });
    };
  };
  reg("contacts_capsule", contacts(QueryShape::capsule(s->radius, s->half_height)));
  reg("contacts_sphere", contacts(QueryShape::sphere(s->radius)));
  reg("overlap_capsule", [s](benchmark::State& state) {
    OverlapResult r;
    const QueryShape shape = QueryShape::capsule(s->radius, s->half_height);
    side_by_side(
        state, [&](int i) { benchmark::DoNotOptimize(s->hulls->overlap({shape, s->poses[i]}, r)); },
        [&](int i) { benchmark::DoNotOptimize(s->triangles->overlap({shape, s->poses[i]}, r)); });
  });
  reg("distance_sphere", [s](benchmark::State& state) {
    DistanceResult r;
    const QueryShape shape = QueryShape::sphere(s->radius);
    side_by_side(
        state, [&](int i) { benchmark::DoNotOptimize(s->hulls->distance({shape, s->poses[i]}, r)); },
        [&](int i) { benchmark::DoNotOptimize(s->triangles->distance({shape, s->poses[i]}, r)); });
  });
  reg("ray", [s](benchmark::State& state) {
    RayResult r;
    side_by_side(
        state,
        [&](int i) {
          benchmark::DoNotOptimize(s->hulls->ray_cast({s->poses[i].translation(), s->ray_directions[i], 1e9}, r));
        },
        [&](int i) {
          benchmark::DoNotOptimize(s->triangles->ray_cast({s->poses[i].translation(), s->ray_directions[i], 1e9}, r));
        });
  });
}

} // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  const std::optional<std::string> dir = hullcover::test::shared_scenes_dir_for_benchmark();
  if (!dir) return 0;
  const hullcover::test::TempDir files;
  for (const SceneScale& scene : kScenes) {
    Result<PreparedMesh> loaded = hullcover::test::prepare_shared_scene(*dir, scene.file);
    if (!loaded.ok()) return std::fprintf(stderr, "%s\n", loaded.status().message().c_str()), 2;
    auto prepared = std::make_shared<PreparedMesh>(std::move(loaded).value());
    auto covering = std::make_shared<Covering>(decompose(*prepared, {}).value());
    register_scene(scene.file, std::make_shared<Scene>(make_scene(*prepared, *covering, scene.units_per_metre)));
    // Loading the runtime file: read, check and build the tree.
    const std::vector<RuntimeHull> runtime = runtime_hulls(*covering);
    const std::string path = files.path(std::string(scene.file) + ".hcw");
    if (!write_runtime_file(runtime, path).ok()) return 2;
    benchmark::RegisterBenchmark((std::string("load/") + scene.file).c_str(), [path](benchmark::State& state) {
      for (auto _ : state) {
        Result<std::vector<RuntimeHull>> hulls = read_runtime_file(path);
        auto world = HullWorld::build(std::move(hulls).value());
        benchmark::DoNotOptimize(world);
      }
    })->Unit(benchmark::kMillisecond);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
