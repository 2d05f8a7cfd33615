// Runtime query benchmark (not a test): HullWorld against the triangle
// baseline (TriangleWorld, FCL on the original triangles), side by side in
// one run over the same poses near the surfaces of each shared scene, at two
// sizes: a character (capsule radius 0.4 m, half height 0.5 m, from the
// scene's units per metre) and a large probe (radius 0.02 x the scene's
// diagonal, the size of the Jolt comparison's probes, docs/results/runtime.md), and, on the levels, a
// walker: the character's capsule upright, standing on walkable faces where
// it can be (rows query/SCENE/walker/...). Each row reports
// microseconds per query for both worlds and the speed-up
// (triangles / hulls). Rows: yes/no (touches), contacts, every touching
// hull (overlap), rays (single and a batch of all poses, up to 4 radii
// long), distance, and sliding: character spheres and capsules resting on
// one plane of the surface, with the count of contact normals more than 1
// degree off the face's (ghost collisions) on each side.
//
//   build/release/tests/hullcover_bench_queries [--benchmark_filter=pandora]
//
// Only the scenes some benchmark of the filter names are decomposed. A
// filter naming "movement" also times each level's movement covering for
// walking characters of the benchmark's capsule (radius 0.4 m, 1.8 m tall;
// hullcover/covering/movement_covering.h), as rows
// query/SCENE/movement/... beside the exact covering's, against the same
// triangles: the ratio of the two speed-ups is the movement covering's
// speed against the exact one.

#include "shared_data.h"
#include "temp_dir.h"

#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/bvh/hull_world.h"
#include "hullcover/bvh/runtime_file.h"
#include "hullcover/bvh/triangle_world.h"
#include "hullcover/covering/covering.h"
#include "hullcover/covering/movement_covering.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <regex>
#include <thread>

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
const SceneScale kScenes[] = {{"recast-dungeon.obj", 1.0},       {"recast-nav_test.obj", 1.0},
                              {"recast-undulating.obj", 1.0},    {"sauerbraten-fdm6.obj", 20.0},
                              {"sauerbraten-pandora.obj", 20.0}, {"stanford-bunny-res2.ply", 0.0},
                              {"thor-art56-gearplate.stl", 0.0}, {"threejs-collision-world.glb", 1.0}};
constexpr int kPoses = 512;
constexpr int kBatchCopies = 8; // a thread-batch benchmark asks every pose this many times

// Poses and rays for one probe size.
struct Probe {
  double radius = 0.4, half_height = 0.5; // capsule (and sphere radius), scene units
  double ray_length = 1.6;                // 4 radii
  std::vector<Eigen::Isometry3d> poses;   // near surfaces: -0.5 to 1.5 radii in front of a face
  std::vector<RayRequest> rays;           // from each pose, towards its face
};

// A shape resting 5% of its radius deep on a face, where every triangle it
// touches lies in that face's plane: what a character sliding over a floor,
// ramp or wall meets.
struct Resting {
  Eigen::Isometry3d pose;
  Eigen::Vector3d normal; // the face's
};

struct Scene {
  std::shared_ptr<const HullWorld> hulls;
  std::shared_ptr<const TriangleWorld> triangles;
  Probe character, large;
  Probe walker;                                           // levels only: upright characters standing where they can be
  std::vector<Resting> resting_spheres, resting_capsules; // character size
};

// A point drawn uniformly on a random face with a surface, and that face's
// unit normal.
struct FacePoint {
  int face = -1;
  Eigen::Vector3d point, normal;
};
FacePoint random_face_point(const Mesh& mesh, std::mt19937& rng) {
  std::uniform_int_distribution<int> face(0, static_cast<int>(mesh.triangles.size()) - 1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (;;) {
    const int f = face(rng);
    const Eigen::Vector3d n = triangle_area_vector(mesh, f);
    if (!(n.norm() > 0.0)) continue;
    double a = u(rng), b = u(rng);
    if (a + b > 1.0) a = 1.0 - a, b = 1.0 - b;
    const Eigen::Vector3i& t = mesh.triangles[f];
    const std::vector<Eigen::Vector3d>& x = mesh.positions;
    return {f, x[t[0]] + a * (x[t[1]] - x[t[0]]) + b * (x[t[2]] - x[t[0]]), n.normalized()};
  }
}

Probe make_probe(const PreparedMesh& prepared, double radius, double half_height, unsigned seed) {
  Probe probe;
  probe.radius = radius;
  probe.half_height = half_height;
  probe.ray_length = 4.0 * radius;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0), offset(-0.5, 1.5);
  while (static_cast<int>(probe.poses.size()) < kPoses) {
    const FacePoint on = random_face_point(prepared.mesh, rng);
    const Eigen::Vector3d& n = on.normal;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = on.point + n * (offset(rng) * radius);
    pose.linear() =
        Eigen::Quaterniond(Eigen::Vector4d(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5).normalized())
            .toRotationMatrix();
    probe.poses.push_back(pose);
    const Eigen::Vector3d towards = -n + 0.3 * Eigen::Vector3d(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5);
    probe.rays.push_back({pose.translation(), towards, probe.ray_length});
  }
  return probe;
}

// Upright characters (capsule axis along +y, the levels' up) standing on
// walkable faces (normal within the movement covering's default slope,
// 45 degrees, of up), their feet up to one
// radius across of a random point of one and from a tenth of a radius into
// it to half a radius above it, kept where a capsule of half the radius on
// the same axis touches no triangle: the poses a character controller asks
// about, on floors, stairs and against walls, never inside the scene.
Probe make_walker_probe(const PreparedMesh& prepared, const TriangleWorld& triangles, double radius, double half_height,
                        unsigned seed) {
  Probe probe;
  probe.radius = radius;
  probe.half_height = half_height;
  probe.ray_length = 4.0 * radius;
  const double min_up_cosine = std::cos(kDefaultMaxSlopeDegrees * M_PI / 180.0);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> across(-radius, radius), lift(-0.1 * radius, 0.5 * radius);
  for (int tries = 0; static_cast<int>(probe.poses.size()) < kPoses && tries < 1000 * kPoses; ++tries) {
    const FacePoint on = random_face_point(prepared.mesh, rng);
    if (on.normal.y() < min_up_cosine) continue;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = Eigen::AngleAxisd(-M_PI / 2.0, Eigen::Vector3d::UnitX()).toRotationMatrix(); // local z up
    pose.translation() = on.point + Eigen::Vector3d(across(rng), radius + half_height + lift(rng), across(rng));
    TouchResult inside;
    if (!triangles.touches({QueryShape::capsule(0.5 * radius, half_height), pose}, inside).ok() || inside.touching)
      continue;
    probe.poses.push_back(pose);
    probe.rays.push_back({pose.translation(), -Eigen::Vector3d::UnitY(), probe.ray_length});
  }
  return probe;
}

constexpr int kRestingPoses = 1000;
const double kGhostCosine = std::cos(M_PI / 180.0); // a normal more than 1 degree off the face's is a ghost

// Resting poses on random faces (a capsule lies along the face's first
// edge), kept where every triangle contact is with a face in the same plane.
std::vector<Resting> resting_poses(const PreparedMesh& prepared, const TriangleWorld& triangles,
                                   const QueryShape& shape, unsigned seed) {
  const Mesh& mesh = prepared.mesh;
  const double tol = prepared.tolerance.length;
  std::mt19937 rng(seed);
  std::vector<Resting> poses;
  for (int tries = 0; static_cast<int>(poses.size()) < kRestingPoses && tries < 100 * kRestingPoses; ++tries) {
    const FacePoint on = random_face_point(mesh, rng);
    const Eigen::Vector3d &n = on.normal, &p = on.point;
    const Eigen::Vector3i& t = mesh.triangles[on.face];
    const std::vector<Eigen::Vector3d>& x = mesh.positions;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = p + n * (0.95 * shape.radius);
    const Eigen::Vector3d along = (x[t[1]] - x[t[0]]).normalized();
    pose.linear().col(2) = along;
    pose.linear().col(0) = n.cross(along).normalized();
    pose.linear().col(1) = along.cross(pose.linear().col(0));
    ContactResult touching;
    if (!triangles.contacts({shape, pose, 64}, touching).ok() || touching.contacts.empty()) continue;
    bool one_plane = true;
    for (const Contact& c : touching.contacts) {
      const Eigen::Vector3i& g = mesh.triangles[c.hull];
      one_plane = one_plane && triangle_area_vector(mesh, c.hull).normalized().dot(n) > kGhostCosine;
      for (int k = 0; k < 3; ++k) one_plane = one_plane && std::abs(n.dot(x[g[k]] - p)) <= tol;
    }
    if (one_plane) poses.push_back({pose, n});
  }
  return poses;
}

Scene make_scene(const PreparedMesh& prepared, const Covering& covering, double units_per_metre) {
  Scene s;
  s.hulls = build_hull_world(covering).value();
  s.triangles = TriangleWorld::build(prepared.mesh, prepared.tolerance.length).value();
  const double diagonal = prepared.tolerance.diagonal;
  const double metre = units_per_metre > 0.0 ? units_per_metre : diagonal / 50.0;
  s.character = make_probe(prepared, 0.4 * metre, 0.5 * metre, 42);
  s.large = make_probe(prepared, 0.02 * diagonal, 0.025 * diagonal, 43);
  if (units_per_metre > 0.0) s.walker = make_walker_probe(prepared, *s.triangles, 0.4 * metre, 0.5 * metre, 46);
  s.resting_spheres = resting_poses(prepared, *s.triangles, QueryShape::sphere(s.character.radius), 44);
  s.resting_capsules =
      resting_poses(prepared, *s.triangles, QueryShape::capsule(s.character.radius, s.character.half_height), 45);
  return s;
}

// Runs `first()` then `second()` each iteration, timing both; the manual
// time is the second's when `time_second`, else the first's. Sets the
// counters `<first_name>_us` and `<second_name>_us` (µs per query, `count`
// queries a call) and `speedup`: the other's time over the timed one's.
void in_turn(benchmark::State& state, int count, const std::function<void()>& first, const char* first_name,
             const std::function<void()>& second, const char* second_name, bool time_second) {
  double first_seconds = 0.0, second_seconds = 0.0;
  for (auto _ : state) {
    Clock::time_point start = Clock::now();
    first();
    const double a = std::chrono::duration<double>(Clock::now() - start).count();
    start = Clock::now();
    second();
    const double b = std::chrono::duration<double>(Clock::now() - start).count();
    state.SetIterationTime(time_second ? b : a);
    first_seconds += a;
    second_seconds += b;
  }
  const double queries = static_cast<double>(state.iterations()) * std::max(count, 1);
  state.counters[std::string(first_name) + "_us"] = 1e6 * first_seconds / queries;
  state.counters[std::string(second_name) + "_us"] = 1e6 * second_seconds / queries;
  state.counters["speedup"] = time_second ? first_seconds / second_seconds : second_seconds / first_seconds;
}

// Runs `hull_query(i)` and `triangle_query(i)` over every pose, timing both.
void side_by_side(benchmark::State& state, int count, const std::function<void(int)>& hull_query,
                  const std::function<void(int)>& triangle_query) {
  in_turn(
      state, count,
      [&] {
    for (int i = 0; i < count; ++i) hull_query(i);
      },
      "hull",
      [&] {
    for (int i = 0; i < count; ++i) triangle_query(i);
  },
      "triangle", false);
}

// How long the two-thread pool below watches between batches: longer than
// the one-thread batch run between two of its own (but for the largest
// contact batches, which last far longer than a wake-up), so the rows time
// a server's batches asked back to back, threads awake. The cost of waking
// a sleeping thread is its own row (threads/wake_up).
constexpr std::chrono::microseconds kWatchAcrossTheOneThreadBatch{100'000};

// One batch on one thread, then on two (QueryThreads, started once), in
// turn each iteration; the manual time is the two threads'. Counters: µs
// per query for each and the speed-up (1.0: none; 2.0: perfect).
void one_thread_then_two(benchmark::State& state, int count, const std::function<void(QueryThreads*)>& batch) {
  const std::shared_ptr<QueryThreads> one = QueryThreads::start(1).value(),
                                      two = QueryThreads::start(2, kWatchAcrossTheOneThreadBatch).value();
  in_turn(
      state, count, [&] { batch(one.get()); }, "one_thread", [&] { batch(two.get()); }, "two_threads", true);
}

// The machine's own two-thread speed-up, as a control for the batch rows:
// the same pool running arithmetic alone (no memory, no queries). On a
// shared machine it is below 2.0 too; a batch row near it is at the
// machine's limit.
void register_thread_control() {
  benchmark::RegisterBenchmark(
      "threads/arithmetic_control",
      [](benchmark::State& state) {
    constexpr int kItems = 4096;
    std::vector<double> out(kItems);
    one_thread_then_two(state, kItems, [&](QueryThreads* threads) {
      struct Job {
        std::vector<double>* out;
      } job{&out};
      threads->run(
          kItems, 16,
          [](size_t begin, size_t end, void* context) {
        std::vector<double>& o = *static_cast<Job*>(context)->out;
        for (size_t i = begin; i < end; ++i) {
          double x = static_cast<double>(i);
          for (int k = 0; k < 200; ++k) x = std::sqrt(x + 1.0001);
          o[i] = x;
        }
          },
          &job);
      benchmark::DoNotOptimize(out.data());
    });
      })
      ->UseManualTime()
      ->Unit(benchmark::kMicrosecond);
}

// What a batch costs beyond its queries: an empty batch of two items on
// two threads, after a pause of a millisecond, on a pool whose thread slept
// at once (asleep_us: the wake-up a server pays on its first batch of a
// tick) and on one that watched (awake_us). Manual time: asleep.
void register_thread_wake_up() {
  benchmark::RegisterBenchmark(
      "threads/wake_up",
      [](benchmark::State& state) {
    const std::shared_ptr<QueryThreads> asleep = QueryThreads::start(2, std::chrono::microseconds(0)).value(),
                                        awake = QueryThreads::start(2, kWatchAcrossTheOneThreadBatch).value();
    const auto empty_batch = [](QueryThreads& threads) {
      const Clock::time_point start = Clock::now();
      threads.run(
          2, 1, [](size_t, size_t, void*) {}, nullptr);
      return std::chrono::duration<double>(Clock::now() - start).count();
    };
    double asleep_seconds = 0.0, awake_seconds = 0.0;
    for (auto _ : state) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      const double a = empty_batch(*asleep);
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      awake_seconds += empty_batch(*awake);
      asleep_seconds += a;
      state.SetIterationTime(a);
    }
    const double n = static_cast<double>(std::max<benchmark::IterationCount>(state.iterations(), 1));
    state.counters["asleep_us"] = 1e6 * asleep_seconds / n;
    state.counters["awake_us"] = 1e6 * awake_seconds / n;
      })
      ->UseManualTime()
      ->Unit(benchmark::kMicrosecond);
}

void register_probe(const std::string& name, const std::shared_ptr<const Scene>& s, const Probe& p) {
  const auto reg = [&](const std::string& what, std::function<void(benchmark::State&)> fn) {
    benchmark::RegisterBenchmark(("query/" + name + "/" + what).c_str(), fn)
        ->UseManualTime()
        ->Unit(benchmark::kMicrosecond);
  };
  // `p` lives in `s`, which every benchmark below keeps alive.
  const Probe* probe = &p;
  const auto shapes = {std::make_pair(std::string("capsule"), QueryShape::capsule(p.radius, p.half_height)),
                       std::make_pair(std::string("sphere"), QueryShape::sphere(p.radius))};
  for (const auto& [kind, shape] : shapes) {
    reg("touches_" + kind, [s, probe, shape = shape](benchmark::State& state) {
      TouchResult r;
      side_by_side(
          state, kPoses,
          [&](int i) {
        benchmark::DoNotOptimize(s->hulls->touches({shape, probe->poses[i]}, r));
          },
          [&](int i) {
        benchmark::DoNotOptimize(s->triangles->touches({shape, probe->poses[i]}, r));
      });
    });
    reg("contacts_" + kind, [s, probe, shape = shape](benchmark::State& state) {
      ContactResult r;
      side_by_side(
          state, kPoses,
          [&](int i) {
        benchmark::DoNotOptimize(s->hulls->contacts({shape, probe->poses[i], 8}, r));
          },
          [&](int i) {
        benchmark::DoNotOptimize(s->triangles->contacts({shape, probe->poses[i], 8}, r));
      });
    });
    reg("overlap_" + kind, [s, probe, shape = shape](benchmark::State& state) {
      OverlapResult r;
      side_by_side(
          state, kPoses,
          [&](int i) {
        benchmark::DoNotOptimize(s->hulls->overlap({shape, probe->poses[i]}, r));
          },
          [&](int i) {
        benchmark::DoNotOptimize(s->triangles->overlap({shape, probe->poses[i]}, r));
      });
    });
  }
  reg("ray", [s, probe](benchmark::State& state) {
    RayResult r;
    side_by_side(
        state, kPoses, [&](int i) { benchmark::DoNotOptimize(s->hulls->ray_cast(probe->rays[i], r)); },
        [&](int i) { benchmark::DoNotOptimize(s->triangles->ray_cast(probe->rays[i], r)); });
  });
  // The any-hit ray (a line of sight) against the nearest hit, both on the
  // hulls: speedup = the nearest hit's time over the any-hit's.
  reg("ray_blocked", [s, probe](benchmark::State& state) {
    RayResult r;
    in_turn(
        state, kPoses,
        [&] {
      for (int i = 0; i < kPoses; ++i) benchmark::DoNotOptimize(s->hulls->ray_blocked(probe->rays[i], r));
        },
        "blocked",
        [&] {
      for (int i = 0; i < kPoses; ++i) benchmark::DoNotOptimize(s->hulls->ray_cast(probe->rays[i], r));
    },
        "nearest", false);
  });
  // The batch: one call for all poses' rays against as many single casts on
  // the triangles (they have no batch); reported per ray.
  reg("ray_batch", [s, probe](benchmark::State& state) {
    std::vector<RayResult> batch;
    RayResult r;
    side_by_side(
        state, kPoses,
        [&](int i) {
      if (i == 0) benchmark::DoNotOptimize(s->hulls->ray_cast_batch(probe->rays, batch));
        },
        [&](int i) { benchmark::DoNotOptimize(s->triangles->ray_cast(probe->rays[i], r)); });
  });
  // Batches of every pose, repeated to a few thousand queries: one thread
  // against two.
  reg("contacts_batch_threads", [s, probe](benchmark::State& state) {
    std::vector<ContactRequest> requests;
    for (int copy = 0; copy < kBatchCopies; ++copy)
      for (const Eigen::Isometry3d& pose : probe->poses)
        requests.push_back(
            {copy % 2 ? QueryShape::sphere(probe->radius) : QueryShape::capsule(probe->radius, probe->half_height),
             pose, 64});
    std::vector<ContactResult> results;
    one_thread_then_two(state, static_cast<int>(requests.size()), [&](QueryThreads* threads) {
      benchmark::DoNotOptimize(s->hulls->contacts_batch(requests, results, threads));
    });
  });
  reg("ray_batch_threads", [s, probe](benchmark::State& state) {
    std::vector<RayRequest> requests;
    for (int copy = 0; copy < kBatchCopies; ++copy)
      requests.insert(requests.end(), probe->rays.begin(), probe->rays.end());
    std::vector<RayResult> results;
    one_thread_then_two(state, static_cast<int>(requests.size()), [&](QueryThreads* threads) {
      benchmark::DoNotOptimize(s->hulls->ray_cast_batch(requests, results, threads));
    });
  });
  reg("distance_sphere", [s, probe](benchmark::State& state) {
    DistanceResult r;
    const QueryShape shape = QueryShape::sphere(probe->radius);
    side_by_side(
        state, kPoses,
        [&](int i) {
      benchmark::DoNotOptimize(s->hulls->distance({shape, probe->poses[i]}, r));
        },
        [&](int i) {
      benchmark::DoNotOptimize(s->triangles->distance({shape, probe->poses[i]}, r));
    });
  });
}

// Contacts of shapes resting on one plane of the surface: the time of both
// worlds, and how many contact normals are more than 1 degree off the face's
// (ghosts: a hull side's or a triangle edge's normal where the surface is
// flat).
void register_sliding(const std::string& name, const std::shared_ptr<const Scene>& s) {
  const auto reg = [&](const std::string& what, const QueryShape& shape, const std::vector<Resting>* poses) {
    benchmark::RegisterBenchmark(
        ("query/" + name + "/character/" + what).c_str(),
        [s, shape, poses](benchmark::State& state) {
      long hull_contacts = 0, hull_ghosts = 0, triangle_contacts = 0, triangle_ghosts = 0;
      ContactResult r;
      for (const Resting& rest : *poses) {
        if (s->hulls->contacts({shape, rest.pose, 64}, r).ok())
          for (const Contact& c : r.contacts)
            hull_contacts += 1, hull_ghosts += c.normal.dot(rest.normal) <= kGhostCosine;
        if (s->triangles->contacts({shape, rest.pose, 64}, r).ok())
          for (const Contact& c : r.contacts)
            triangle_contacts += 1, triangle_ghosts += c.normal.dot(rest.normal) <= kGhostCosine;
      }
      const int count = static_cast<int>(poses->size());
      side_by_side(
          state, count,
          [&](int i) {
        benchmark::DoNotOptimize(s->hulls->contacts({shape, (*poses)[i].pose, 64}, r));
          },
          [&](int i) {
        benchmark::DoNotOptimize(s->triangles->contacts({shape, (*poses)[i].pose, 64}, r));
      });
      state.counters["poses"] = count;
      state.counters["hull_contacts"] = static_cast<double>(hull_contacts);
      state.counters["hull_ghosts"] = static_cast<double>(hull_ghosts);
      state.counters["triangle_contacts"] = static_cast<double>(triangle_contacts);
      state.counters["triangle_ghosts"] = static_cast<double>(triangle_ghosts);
        })
        ->UseManualTime()
        ->Unit(benchmark::kMicrosecond);
  };
  reg("sliding_sphere", QueryShape::sphere(s->character.radius), &s->resting_spheres);
  reg("sliding_capsule", QueryShape::capsule(s->character.radius, s->character.half_height), &s->resting_capsules);
}

void register_scene(const std::string& name, const std::shared_ptr<const Scene>& s) {
  register_probe(name + "/character", s, s->character);
  register_probe(name + "/large", s, s->large);
  if (!s->walker.poses.empty()) register_probe(name + "/walker", s, s->walker);
  register_sliding(name, s);
}

// The rows register_probe adds, for filter_selects_scene.
const char* const kRows[] = {"touches_capsule",
                             "contacts_capsule",
                             "overlap_capsule",
                             "touches_sphere",
                             "contacts_sphere",
                             "overlap_sphere",
                             "ray",
                             "ray_batch",
                             "contacts_batch_threads",
                             "ray_batch_threads",
                             "ray_blocked",
                             "distance_sphere",
                             "sliding_sphere",
                             "sliding_capsule"};

// Whether `filter` (--benchmark_filter's value: a regular expression, empty
// for all) selects some benchmark of `scene`, so that only those scenes are
// decomposed. A negative filter ("-...") selects every scene.
bool filter_selects_scene(const std::string& filter, const std::string& scene) {
  if (filter.empty() || filter == "all" || filter[0] == '-') return true;
  try {
    const std::regex pattern(filter);
    if (std::regex_search("load/" + scene, pattern)) return true;
    for (const char* covering : {"", "/movement"})
      for (const char* size : {"character", "large", "walker"})
        for (const char* row : kRows)
          if (std::regex_search("query/" + scene + covering + "/" + size + "/" + row + "/manual_time", pattern))
            return true;
    return false;
  } catch (const std::regex_error&) {
    return true; // Google Benchmark reports the bad filter itself
  }
}

} // namespace

int main(int argc, char** argv) {
  std::string filter; // read before Initialize, which takes its flags out of argv
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]).rfind("--benchmark_filter=", 0) == 0) filter = std::string(argv[i]).substr(19);
  benchmark::Initialize(&argc, argv);
  const std::optional<std::string> dir = hullcover::test::shared_scenes_dir_for_benchmark();
  if (!dir) return 0;
  const hullcover::test::TempDir files;
  for (const SceneScale& scene : kScenes) {
    if (!filter_selects_scene(filter, scene.file)) continue;
    Result<PreparedMesh> loaded = hullcover::test::prepare_shared_scene(*dir, scene.file);
    if (!loaded.ok()) return std::fprintf(stderr, "%s\n", loaded.status().message().c_str()), 2;
    auto prepared = std::make_shared<PreparedMesh>(std::move(loaded).value());
    auto covering = std::make_shared<Covering>(decompose(*prepared, {}).value());
    register_scene(scene.file, std::make_shared<Scene>(make_scene(*prepared, *covering, scene.units_per_metre)));
    if (filter.find("movement") != std::string::npos && scene.units_per_metre > 0.0) {
      MovementOptions walking;
      walking.radius = 0.4 * scene.units_per_metre;
      walking.height = 1.8 * scene.units_per_metre;
      Result<MovementCovering> movement = decompose_for_movement(*prepared, walking);
      if (!movement.ok()) return std::fprintf(stderr, "%s\n", movement.status().message().c_str()), 2;
      auto moving = std::make_shared<Covering>(std::move(movement).value().covering);
      register_scene(std::string(scene.file) + "/movement",
                     std::make_shared<Scene>(make_scene(*prepared, *moving, scene.units_per_metre)));
    }
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
  register_thread_control();
  register_thread_wake_up();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
