// Decomposition benchmark over the shared scenes (not a test): for each
// scene, compact and random merge order side by side, with faces, hulls,
// hulls per face and the time per 20K faces (the target: under 1 s
// on one core; the paper: tens of seconds to a minute for 21K faces).
//
//   build/release/tests/hullcover_bench_decompose [--benchmark_filter=fdm6]

#include "shared_data.h"

#include "hullcover/lib/covering.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <memory>

namespace {

using namespace hullcover;

// The paper's building: 3,137 hulls for 14,608 faces.
constexpr double kPaperHullsPerFace = 3137.0 / 14608.0;

void decompose_scene(benchmark::State& state, std::shared_ptr<PreparedMesh> prepared, MergeOrder order) {
  DecomposeOptions options;
  options.order = order;
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
    for (MergeOrder order : {MergeOrder::compact, MergeOrder::random}) {
      const std::string name = std::string("decompose/") + scene + (order == MergeOrder::compact ? "/compact" : "/random");
      benchmark::RegisterBenchmark(name.c_str(), decompose_scene, shared, order)
          ->Unit(benchmark::kMillisecond)
          ->MeasureProcessCPUTime()
          ->UseRealTime();
    }
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
