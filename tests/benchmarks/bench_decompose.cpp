// Decomposition benchmark over the shared scenes (not a test): for each
// scene, the paper's conditions and exact mode (compact order), exact mode
// without dissolving, without near merges (nor dissolving), and exact mode in
// random order, side by side, with faces, hulls, hulls per face, the
// ratio to the prototype's paper-mode count (../shared/DESIGN.md; issue 6's
// target for exact mode: <= 1) and the time per 20K faces (the paper: tens
// of seconds to a minute for 21K faces).
//
//   build/release/tests/hullcover_bench_decompose [--benchmark_filter=fdm6]

#include "shared_data.h"

#include "hullcover/covering/covering.h"

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
// (../shared/DESIGN.md, "Where the paper's four conditions are not enough").
const std::map<std::string, double> kPrototypePaperHulls = {
    {"sauerbraten-fdm6.obj", 3112},   {"sauerbraten-pandora.obj", 21098},       {"recast-dungeon.obj", 3231},
    {"threejs-collision-world.glb", 368}, {"recast-nav_test.obj", 714}};

// One way of decomposing, named in the benchmark's name.
struct Variant {
  const char* name;
  MergeOrder order;
  ValidityMode conditions;
  std::optional<double> near_merge_distance;  // unset: the mode's default
  std::optional<bool> dissolve;               // unset: the mode's default
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

} // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  const std::optional<std::string> dir = hullcover::test::shared_scenes_dir_for_benchmark();
  if (!dir) return 0;
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
