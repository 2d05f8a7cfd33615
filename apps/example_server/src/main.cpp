// hullcover_example_server: a game server's collision loop on an installed
// hullcover (find_package(hullcover), hullcover::bvh only). Loads a runtime
// file, stands capsule characters on free ground, moves them from several
// threads at once through one shared, read-only HullWorld, and reports the
// queries per second and any character that ended inside a hull. With a
// second world for rays (--rays-world: the exact covering, when the first is
// a movement covering, which keeps no rays), the characters' shots are cast
// there: each question asked of the world made for it.

#include "character_controller.h"

#include "hullcover/bvh/hull_world.h"
#include "hullcover/bvh/runtime_file.h"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace example_server {
namespace {

using hullcover::Status;
namespace bvh = hullcover::bvh;

constexpr int kExitSuccess = 0;
constexpr int kExitEndedInside = 1;
constexpr int kExitBadInput = 2;
constexpr int kExitRunFailed = 3;

/// Command-line limits: beyond them a run is a typo, not a test.
constexpr std::int64_t kMaxCharacters = 1000000;
constexpr std::int64_t kMaxThreads = 1024;
constexpr std::int64_t kMaxSweepsPerThread = INT64_C(1000000000000);
/// With --rays-world: shots each character fires from where it ended.
constexpr int kShotsPerCharacter = 16;

/// Without --units-per-metre a metre is this fraction of the world box's
/// diagonal, as `hullcover bench` assumes: a 50 m level.
constexpr double kDiagonalsPerMetre = 1.0 / 50.0;
/// Default character, in metres: a person-sized capsule (1.8 m tall).
constexpr double kDefaultRadiusMetres = 0.4;
constexpr double kDefaultHalfHeightMetres = 0.5;
/// Default skin, metres: far above the runtime's tolerances, far below
/// anything a player sees.
constexpr double kDefaultSkinMetres = 0.02;
constexpr double kWalkSpeedMetresPerSecond = 3.0;
constexpr double kGravityMetresPerSecondSquared = 9.81;
constexpr double kTerminalFallMetresPerSecond = 20.0;
/// Characters that fall this fraction of the world's diagonal below its box
/// have left the level (through an opening in its shell) and respawn.
constexpr double kRespawnDepthPerDiagonal = 0.1;

struct ServerOptions {
  std::string world_path;
  std::string rays_world_path; // empty: no shots
  int characters = 64;
  int threads = 4;
  std::int64_t sweeps_per_thread = 10000;
  std::uint64_t seed = 1;
  int up_axis = 1; // 0 x, 1 y, 2 z
  std::optional<double> units_per_metre, radius, half_height, skin;
};

/// What one thread did with the characters it owns.
struct ThreadRun {
  std::vector<Character> characters;
  QueryCounts counts;
  Status failure;
  /// Per character of `characters`: the hulls its shrunk capsule overlaps at the end.
  std::vector<std::vector<int>> inside;
  std::int64_t shots = 0, shot_hits = 0;         ///< rays cast on the rays world, and those that hit
  std::int64_t sight_lines = 0, sight_clear = 0; ///< lines of sight to the next character, and those clear
};

void print_usage(const char* program) {
  std::printf(
      "usage: %s WORLD.hcw [options]\n"
      "\n"
      "Moves capsule characters through a hullcover runtime file (.hcw, from\n"
      "`hullcover decompose SCENE -o HULLS.obj --world WORLD.hcw`) from several threads\n"
      "sharing one HullWorld, as a game server's kinematic character controller would:\n"
      "each step sweeps the capsule along a random walk plus gravity, stops a skin short\n"
      "of the first hull hit and slides along it; a contacts query checks for penetration.\n"
      "\n"
      "options:\n"
      "  --characters N       capsules, spread over the threads (default 64)\n"
      "  --threads T          threads moving characters (default 4; at most N)\n"
      "  --sweeps S           sweep queries per thread before it stops (default 10000)\n"
      "  --seed K             start positions and random walks (default 1)\n"
      "  --up x|y|z           the world's up axis (default y)\n"
      "  --units-per-metre U  scene units in a metre (default: the world box's diagonal / 50)\n"
      "  --radius R           capsule radius, scene units (default 0.4 m)\n"
      "  --half-height H      half the capsule's axis segment, scene units (default 0.5 m)\n"
      "  --skin E             gap kept from hulls, scene units (default 0.02 m; radius > 2 E)\n"
      "  --rays-world F.hcw   cast each character's shots (16, level, in random directions) and\n"
      "                       its line of sight to the next character of its thread\n"
      "                       on this world: the exact covering, when WORLD.hcw is a\n"
      "                       movement covering (`decompose --agent-reach`), which keeps no rays\n"
      "  -h, --help           this text\n"
      "\n"
      "Prints queries per second (sweeps, contacts and the final overlap checks) and\n"
      "every character that ends inside a hull (its capsule shrunk by the skin overlaps\n"
      "one). Exit status: 0 none inside, 1 some inside, 2 bad usage or unreadable file,\n"
      "3 the run failed (a query failed, or a thread could not start).\n",
      program);
}

bool parse_integer(const std::string& text, std::int64_t low, std::int64_t high, std::int64_t& out) {
  if (text.empty()) return false;
  char* end = nullptr;
  const long long value = std::strtoll(text.c_str(), &end, 10);
  if (end != text.c_str() + text.size() || value < low || value > high) return false;
  out = value;
  return true;
}

bool parse_non_negative_number(const std::string& text, double& out) {
  if (text.empty()) return false;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(value) || value < 0.0) return false;
  out = value;
  return true;
}

/// Fills `options` from the command line; false (after saying why) on bad
/// usage. Sets `help` for --help.
bool parse_command_line(int argc, char** argv, ServerOptions& options, bool& help) {
  const auto complain = [&](const std::string& message) {
    std::fprintf(stderr, "%s: error: %s (see --help)\n", argv[0], message.c_str());
    return false;
  };
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      help = true;
      return true;
    }
    if (arg.rfind("--", 0) != 0) {
      if (!options.world_path.empty()) return complain("more than one world file: '" + arg + "'");
      options.world_path = arg;
      continue;
    }
    if (i + 1 >= argc) return complain(arg + " needs a value");
    const std::string value = argv[++i];
    if (arg == "--rays-world") {
      options.rays_world_path = value;
      continue;
    }
    std::int64_t integer = 0;
    double length = 0.0;
    if (arg == "--characters") {
      if (!parse_integer(value, 1, kMaxCharacters, integer))
        return complain("--characters is 1.." + std::to_string(kMaxCharacters) + ", not '" + value + "'");
      options.characters = static_cast<int>(integer);
    } else if (arg == "--threads") {
      if (!parse_integer(value, 1, kMaxThreads, integer))
        return complain("--threads is 1.." + std::to_string(kMaxThreads) + ", not '" + value + "'");
      options.threads = static_cast<int>(integer);
    } else if (arg == "--sweeps") {
      if (!parse_integer(value, 1, kMaxSweepsPerThread, integer))
        return complain("--sweeps is a count >= 1, not '" + value + "'");
      options.sweeps_per_thread = integer;
    } else if (arg == "--seed") {
      if (!parse_integer(value, 0, INT64_MAX, integer))
        return complain("--seed is an integer >= 0, not '" + value + "'");
      options.seed = static_cast<std::uint64_t>(integer);
    } else if (arg == "--up") {
      if (value != "x" && value != "y" && value != "z") return complain("--up is x, y or z, not '" + value + "'");
      options.up_axis = value[0] - 'x';
    } else if (arg == "--units-per-metre" || arg == "--radius" || arg == "--half-height" || arg == "--skin") {
      const bool zero_allowed = arg == "--half-height";
      if (!parse_non_negative_number(value, length) || (!zero_allowed && length <= 0.0))
        return complain(arg + " is a finite number " + (zero_allowed ? ">= 0" : "> 0") + ", not '" + value + "'");
      if (arg == "--units-per-metre") options.units_per_metre = length;
      if (arg == "--radius") options.radius = length;
      if (arg == "--half-height") options.half_height = length;
      if (arg == "--skin") options.skin = length;
    } else {
      return complain("unknown option '" + arg + "'");
    }
  }
  if (options.world_path.empty()) return complain("no world file given");
  return true;
}

/// Casts kShotsPerCharacter level rays from each of `run`'s characters, in
/// directions drawn from its own stream, on `rays`.
void fire_shots(const bvh::HullWorld& rays, int up_axis, ThreadRun& run) {
  for (Character& character : run.characters)
    for (int shot = 0; shot < kShotsPerCharacter; ++shot) {
      bvh::RayRequest request;
      request.origin = character.position;
      std::normal_distribution<double> normal;
      for (int a = 0; a < 3; ++a) request.direction[a] = a == up_axis ? 0.0 : normal(character.random);
      if (!(request.direction.norm() > 0.0)) continue;
      bvh::RayResult result;
      if (Status s = rays.ray_cast(request, result); !s.ok()) {
        run.failure = s;
        return;
      }
      ++run.shots;
      run.shot_hits += result.hit ? 1 : 0;
    }
}

/// Checks each of `run`'s characters' line of sight to the next one on
/// `rays`: any hull between them blocks it, wherever it lies, so the walk
/// may stop at the first hull it finds hit (ray_blocked).
void check_lines_of_sight(const bvh::HullWorld& rays, ThreadRun& run) {
  for (size_t i = 0; i + 1 < run.characters.size(); ++i) {
    const Eigen::Vector3d from = run.characters[i].position;
    const Eigen::Vector3d along = run.characters[i + 1].position - from;
    const double length = along.norm();
    if (!(length > 0.0)) continue;
    bvh::RayResult result;
    if (Status s = rays.ray_blocked({from, along, length}, result); !s.ok()) {
      run.failure = s;
      return;
    }
    ++run.sight_lines;
    run.sight_clear += result.hit ? 0 : 1;
  }
}

/// Moves `run`'s characters until the thread has swept `sweeps` times, then
/// checks where each ended and, with a rays world, fires their shots and
/// checks their lines of sight.
/// Touches nothing but `run` and the const worlds.
void move_characters(const CharacterController& controller, std::int64_t sweeps, const bvh::HullWorld* rays,
                     int up_axis, ThreadRun& run) {
  if (run.characters.empty()) return;
  while (run.counts.sweeps < sweeps) {
    const std::int64_t sweeps_before = run.counts.sweeps;
    for (Character& character : run.characters) {
      if (Status s = controller.step(character, run.counts); !s.ok()) {
        run.failure = s;
        return;
      }
      if (run.counts.sweeps >= sweeps) break;
    }
    // Characters too slow to sweep at all would never use up the budget.
    if (run.counts.sweeps == sweeps_before) break;
  }
  run.inside.resize(run.characters.size());
  for (size_t i = 0; i < run.characters.size(); ++i)
    if (Status s = controller.hulls_inside(run.characters[i], run.inside[i], run.counts); !s.ok()) {
      run.failure = s;
      return;
    }
  if (rays) {
    fire_shots(*rays, up_axis, run);
    if (run.failure.ok()) check_lines_of_sight(*rays, run);
  }
}

/// The world in `path`, or nothing after a message.
std::shared_ptr<const bvh::HullWorld> load_world(const std::string& path) {
  hullcover::Result<std::vector<bvh::RuntimeHull>> hulls = bvh::read_runtime_file(path);
  if (!hulls.ok()) {
    std::fprintf(stderr, "example_server: error: %s\n", hulls.status().message().c_str());
    return nullptr;
  }
  hullcover::Result<std::shared_ptr<const bvh::HullWorld>> built = bvh::HullWorld::build(std::move(hulls).value());
  if (!built.ok()) {
    std::fprintf(stderr, "example_server: error: %s: %s\n", path.c_str(), built.status().message().c_str());
    return nullptr;
  }
  return built.value();
}

int serve(const ServerOptions& options) {
  const std::shared_ptr<const bvh::HullWorld> world = load_world(options.world_path);
  if (!world) return kExitBadInput;
  std::shared_ptr<const bvh::HullWorld> rays;
  if (!options.rays_world_path.empty() && !(rays = load_world(options.rays_world_path))) return kExitBadInput;
  const hullcover::Aabb box = world_bounds(*world);
  const double diagonal = box.diagonal();
  const double metre = options.units_per_metre.value_or(kDiagonalsPerMetre * diagonal);

  ControllerSettings settings;
  settings.up = Eigen::Vector3d::Unit(options.up_axis);
  settings.radius = options.radius.value_or(kDefaultRadiusMetres * metre);
  settings.half_height = options.half_height.value_or(kDefaultHalfHeightMetres * metre);
  settings.skin = options.skin.value_or(kDefaultSkinMetres * metre);
  settings.walk_speed = kWalkSpeedMetresPerSecond * metre;
  settings.gravity = kGravityMetresPerSecondSquared * metre;
  settings.terminal_fall_speed = kTerminalFallMetresPerSecond * metre;
  settings.respawn_below = box.min[options.up_axis] - kRespawnDepthPerDiagonal * diagonal;
  if (!(settings.radius > 2.0 * settings.skin)) {
    std::fprintf(stderr, "example_server: error: the radius (%g) must exceed twice the skin (%g)\n", settings.radius,
                 settings.skin);
    return kExitBadInput;
  }
  const CharacterController controller(*world, settings);

  std::printf("world: %s, %zu hulls, box (%.6g, %.6g, %.6g) - (%.6g, %.6g, %.6g), diagonal %.6g\n",
              options.world_path.c_str(), world->hulls().size(), box.min.x(), box.min.y(), box.min.z(), box.max.x(),
              box.max.y(), box.max.z(), diagonal);
  std::printf("characters: %d capsules, radius %.6g, half height %.6g, skin %.6g (scene units; a metre = %.6g)\n",
              options.characters, settings.radius, settings.half_height, settings.skin, metre);

  std::vector<Eigen::Vector3d> starts;
  if (Status s = find_start_positions(*world, controller, options.characters, options.seed, starts); !s.ok()) {
    std::fprintf(stderr, "example_server: error: %s: %s\n", options.world_path.c_str(), s.message().c_str());
    return kExitBadInput;
  }

  int thread_count = options.threads;
  if (thread_count > options.characters) {
    std::fprintf(stderr, "example_server: note: %d threads for %d characters: using %d threads\n", thread_count,
                 options.characters, options.characters);
    thread_count = options.characters;
  }
  std::vector<ThreadRun> runs(thread_count);
  for (int id = 0; id < options.characters; ++id) {
    Character character;
    character.id = id;
    character.start = character.position = starts[id];
    std::seed_seq stream{static_cast<std::uint32_t>(options.seed), static_cast<std::uint32_t>(options.seed >> 32),
                         static_cast<std::uint32_t>(id)};
    character.random.seed(stream);
    runs[id % thread_count].characters.push_back(std::move(character));
  }

  std::printf("run: %d threads x %lld sweeps\n", thread_count, static_cast<long long>(options.sweeps_per_thread));
  std::fflush(stdout);
  const auto begin = std::chrono::steady_clock::now();
  {
    std::vector<std::thread> threads;
    threads.reserve(runs.size());
    for (ThreadRun& run : runs)
      threads.emplace_back(move_characters, std::cref(controller), options.sweeps_per_thread, rays.get(),
                           options.up_axis, std::ref(run));
    for (std::thread& thread : threads) thread.join();
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();

  QueryCounts total;
  for (const ThreadRun& run : runs) {
    total.add(run.counts);
    if (!run.failure.ok()) {
      std::fprintf(stderr, "example_server: error: a query failed: %s\n", run.failure.message().c_str());
      return kExitRunFailed;
    }
  }
  std::printf("queries: %lld sweeps, %lld contacts, %lld overlaps in %.3f s: %.0f queries/s (%.0f sweeps/s)\n",
              static_cast<long long>(total.sweeps), static_cast<long long>(total.contacts),
              static_cast<long long>(total.overlaps), seconds, total.queries() / seconds, total.sweeps / seconds);
  std::printf("steps: %lld, sweeps that hit and slid: %lld, penetrations recovered: %lld, respawns: %lld\n",
              static_cast<long long>(total.steps), static_cast<long long>(total.sweep_hits),
              static_cast<long long>(total.recoveries), static_cast<long long>(total.respawns));

  double path_length = 0.0;
  for (const ThreadRun& run : runs)
    for (const Character& c : run.characters) path_length += c.path_length;
  const double simulated_seconds = static_cast<double>(total.steps) * settings.time_step;
  std::printf("moved: %.6g scene units per character on average, %.3g m/s (walking at %.3g m/s)\n",
              path_length / options.characters, path_length / metre / simulated_seconds, kWalkSpeedMetresPerSecond);

  int ended_inside = 0;
  for (const ThreadRun& run : runs)
    for (size_t i = 0; i < run.inside.size(); ++i) {
      if (run.inside[i].empty()) continue;
      ++ended_inside;
      const Character& c = run.characters[i];
      std::string hull_list;
      for (int hull : run.inside[i]) hull_list += " " + std::to_string(hull);
      std::printf("inside: character %d at (%.6g, %.6g, %.6g), hulls%s\n", c.id, c.position.x(), c.position.y(),
                  c.position.z(), hull_list.c_str());
    }
  if (rays) {
    std::int64_t shots = 0, hits = 0, lines = 0, clear = 0;
    for (const ThreadRun& run : runs) {
      shots += run.shots;
      hits += run.shot_hits;
      lines += run.sight_lines;
      clear += run.sight_clear;
    }
    std::printf("shots: %lld rays on %s (%zu hulls), %lld hit\n", static_cast<long long>(shots),
                options.rays_world_path.c_str(), rays->hulls().size(), static_cast<long long>(hits));
    std::printf("sight lines: %lld between characters, %lld clear\n", static_cast<long long>(lines),
                static_cast<long long>(clear));
  }
  std::printf("characters ended inside a hull: %d of %d\n", ended_inside, options.characters);
  return ended_inside > 0 ? kExitEndedInside : kExitSuccess;
}

} // namespace
} // namespace example_server

int main(int argc, char** argv) {
  // Nothing may escape: a thread that cannot start or memory that runs out
  // ends the run with a message and a status, not std::terminate.
  try {
    example_server::ServerOptions options;
    bool help = false;
    if (!example_server::parse_command_line(argc, argv, options, help)) return example_server::kExitBadInput;
    if (help) {
      example_server::print_usage(argv[0]);
      return example_server::kExitSuccess;
    }
    return example_server::serve(options);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%s: error: %s\n", argv[0], error.what());
  } catch (...) {
    std::fprintf(stderr, "%s: error: unexpected failure\n", argv[0]);
  }
  return example_server::kExitRunFailed;
}
