// Audit benchmark (not a test): the whole audit at default settings -
// accessible-space probe, independent re-check, behaviour equivalence - of
// hullcover's covering and of the V-HACD peer hulls, per shared scene. The
// aim: one scene in under a minute on a two-core machine.
//
//   build/release/tests/hullcover_bench_audit [--benchmark_filter=fdm6]

#include "shared_data.h"

#include "hullcover/covering/covering.h"
#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/validate/accessible_space.h"
#include "hullcover/validate/behaviour_equivalence.h"
#include "hullcover/validate/hull_set.h"
#include "hullcover/validate/validity_recheck.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <memory>

namespace {

using namespace hullcover;

void audit(benchmark::State& state, std::shared_ptr<PreparedMesh> prepared, std::shared_ptr<validate::HullSet> set) {
  const auto triangles = bvh::TriangleWorld::build(prepared->mesh, prepared->tolerance.length).value();
  const auto hulls = bvh::HullWorld::build(set->hulls).value();
  validate::ProbeReport probe;
  validate::BehaviourReport behaviour;
  for (auto _ : state) {
    probe = validate::probe_accessible_space(*prepared, *triangles, *hulls, {}).value();
    const validate::CheckReport recheck =
        validate::recheck_hulls(*prepared, validate::hulls_under_check(set->hulls),
                                kDefaultBarHalfLengthRelative * prepared->tolerance.diagonal);
    behaviour = validate::compare_behaviour(*prepared, *triangles, *hulls, {}).value();
    benchmark::DoNotOptimize(recheck);
  }
  state.counters["front_lost_pct"] = 100.0 * probe.front.lost / std::max(1L, probe.front.rays);
  state.counters["opening_lost_pct"] = 100.0 * probe.opening.lost / std::max(1L, probe.opening.rays);
  state.counters["lost_length"] = probe.front.lost_length + probe.opening.lost_length;
  state.counters["missed"] = static_cast<double>(behaviour.missed);
  state.counters["false"] = static_cast<double>(behaviour.false_contacts);
}

} // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  const std::optional<std::string> dir = hullcover::test::shared_scenes_dir_for_benchmark();
  if (!dir) return 0;
  for (const char* scene : hullcover::test::kSharedScenes) {
    Result<PreparedMesh> prepared = hullcover::test::prepare_shared_scene(*dir, scene);
    if (!prepared.ok()) return std::fprintf(stderr, "%s: %s\n", scene, prepared.status().message().c_str()), 2;
    auto mesh = std::make_shared<PreparedMesh>(std::move(prepared).value());
    auto ours = std::make_shared<validate::HullSet>();
    ours->hulls = bvh::runtime_hulls(decompose(*mesh, {}).value());
    const std::string stem = std::string(scene).substr(0, std::string(scene).rfind('.'));
    Result<validate::HullSet> peer = validate::load_hull_set(*dir + "/../peer-hulls/" + stem + ".vhacd.obj");
    for (const auto& [who, set] :
         {std::make_pair(std::string("hullcover"), ours),
          std::make_pair(std::string("vhacd"),
                         peer.ok() ? std::make_shared<validate::HullSet>(std::move(peer).value()) : nullptr)}) {
      if (!set) continue;
      benchmark::RegisterBenchmark(("audit/" + std::string(scene) + "/" + who).c_str(), audit, mesh, set)
          ->Unit(benchmark::kSecond)
          ->Iterations(1);
    }
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
