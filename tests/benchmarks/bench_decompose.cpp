// Decomposition benchmark over the shared scenes (not a test): for each
// scene, the paper's conditions and exact mode (compact order), exact mode
// without dissolving, without near merges (nor dissolving), and exact mode in
// random order, side by side, with faces, hulls, hulls per face, the
// ratio to the prototype's paper-mode count (docs/results/covering.md, "Paper vs exact"; the
// target for exact mode: <= 1) and the time per 20K faces (the paper: tens
// of seconds to a minute for 21K faces). Then, without the shared scenes,
// scattered islands: n separate triangles a unit apart, each its own island
// (a level of scattered debris or kit pieces), at n = 10K, 30K and 100K;
// the time per triangle must not grow with n.
//
//   build/release/tests/hullcover_bench_decompose [--benchmark_filter=fdm6]

#include "shared_data.h"

#include "hullcover/covering/covering.h"
#include "hullcover/mesh/prepared_mesh.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <memory>
#include <optional>

namespace {

using namespace hullcover;

// The paper's building: 3,137 hulls for 14,608 faces.
constexpr double kPaperHullsPerFace = 3137.0 / 14608.0;

// Hull counts of the prototype with the paper's conditions alone
// (docs/results/covering.md, "Paper vs exact").
const std::map<std::string, double> kPrototypePaperHulls = {{"sauerbraten-fdm6.obj", 3112},
                                                            {"sauerbraten-pandora.obj", 21098},
                                                            {"recast-dungeon.obj", 3231},
                                                            {"threejs-collision-world.glb", 368},
                                                            {"recast-nav_test.obj", 714}};

// One way of decomposing, named in the benchmark's name.
struct Variant {
  const char* name;
  MergeOrder order;
  ValidityMode conditions;
  std::optional<double> near_merge_distance; // unset: the mode's default
  std::optional<bool> dissolve;              // unset: the mode's default
};

constexpr double kNoNearMerges = 0.0;
constexpr bool kNoDissolving = false;

void decompose_scene(benchmark::State& state, std::shared_ptr<PreparedMesh> prepared, std::string scene,
                     Variant variant) {
  DecomposeOptions options;
  options.order = variant.order;
  options.conditions = variant.conditions;
  options.near_merge_distance = variant.near_merge_distance;
  options.dissolve = variant.dissolve;
  size_t hulls = 0;
  for (auto _ : state) {
    Result<Covering> covering = decompose(*prepared, options);
    if (!covering.ok()) {
      state.SkipWithError(covering.status().message().c_str());
      return;
    }
    hulls = covering.value().hulls.size();
    benchmark::DoNotOptimize(hulls);
  }
  const double faces = static_cast<double>(prepared->mesh.triangles.size());
  state.counters["faces"] = faces;
  state.counters["hulls"] = static_cast<double>(hulls);
  state.counters["hulls_per_face"] = hulls / faces;
  state.counters["vs_paper_ratio"] = hulls / faces / kPaperHullsPerFace;
  if (const auto prototype = kPrototypePaperHulls.find(scene); prototype != kPrototypePaperHulls.end())
    state.counters["vs_prototype_paper"] = static_cast<double>(hulls) / prototype->second;
  // Seconds per 20K faces, from the mean iteration time.
  state.counters["s_per_20k_faces"] =
      benchmark::Counter(faces / 20000.0, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// n triangles, triangle i in the plane x = i (the row an OBJ of n objects
// `v i 0 0 / v i 1 0 / v i 0 1` makes).
Mesh scattered_triangles(int n) {
  Mesh mesh;
  for (int i = 0; i < n; ++i) {
    const double x = i;
    mesh.positions.insert(mesh.positions.end(), {{x, 0, 0}, {x, 1, 0}, {x, 0, 1}});
    mesh.triangles.emplace_back(3 * i, 3 * i + 1, 3 * i + 2);
    mesh.material_ids.push_back(0);
  }
  return mesh;
}

void decompose_scattered_islands(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  Result<PreparedMesh> prepared = prepare_mesh(scattered_triangles(n), std::nullopt);
  if (!prepared.ok()) {
    state.SkipWithError(prepared.status().message().c_str());
    return;
  }
  for (auto _ : state) {
    Result<Covering> covering = decompose(prepared.value(), DecomposeOptions{});
    if (!covering.ok()) {
      state.SkipWithError(covering.status().message().c_str());
      return;
    }
    benchmark::DoNotOptimize(covering.value().hulls.size());
  }
  state.counters["us_per_triangle"] =
      benchmark::Counter(n / 1e6, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

} // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  benchmark::RegisterBenchmark("decompose/scattered_islands", decompose_scattered_islands)
      ->Arg(10000)
      ->Arg(30000)
      ->Arg(100000)
      ->Unit(benchmark::kMillisecond)
      ->MeasureProcessCPUTime()
      ->UseRealTime();
  const std::optional<std::string> dir = hullcover::test::shared_scenes_dir_for_benchmark();
  if (!dir) {
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
  }
  for (const char* scene : hullcover::test::kSharedScenes) {
    Result<PreparedMesh> prepared = hullcover::test::prepare_shared_scene(*dir, scene);
    if (!prepared.ok()) {
      std::fprintf(stderr, "%s: %s\n", scene, prepared.status().message().c_str());
      return 2;
    }
    auto shared = std::make_shared<PreparedMesh>(std::move(prepared).value());
    const Variant variants[] = {
        {"compact/paper", MergeOrder::compact, ValidityMode::paper, std::nullopt, std::nullopt},
        {"compact/exact", MergeOrder::compact, ValidityMode::exact, std::nullopt, std::nullopt},
        {"compact/exact_no_dissolving", MergeOrder::compact, ValidityMode::exact, std::nullopt, kNoDissolving},
        {"compact/exact_no_near_merges", MergeOrder::compact, ValidityMode::exact, kNoNearMerges, kNoDissolving},
        {"random/exact", MergeOrder::random, ValidityMode::exact, std::nullopt, std::nullopt}};
    for (const Variant& variant : variants) {
      const std::string name = std::string("decompose/") + scene + "/" + variant.name;
      benchmark::RegisterBenchmark(name.c_str(), decompose_scene, shared, std::string(scene), variant)
          ->Unit(benchmark::kMillisecond)
          ->MeasureProcessCPUTime()
          ->UseRealTime();
    }
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
