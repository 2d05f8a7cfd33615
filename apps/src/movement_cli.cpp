#include "movement_cli.h"

#include "help_numbers.h"
#include "number_checks.h"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace hullcover::app {
namespace {

Eigen::Vector3d up_vector(const std::string& up) {
  const double sign = up[0] == '-' ? -1.0 : 1.0;
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  v[up.back() - 'x'] = sign;
  return v;
}

// The seeds of `path`: one "x y z" a line; blank lines and lines starting
// with '#' are passed over.
std::optional<std::vector<Eigen::Vector3d>> read_seeds(const std::string& path) {
  std::ifstream in(path);
  if (!in) {
    std::fprintf(stderr, "hullcover: error: cannot open the seeds file %s\n", path.c_str());
    return std::nullopt;
  }
  std::vector<Eigen::Vector3d> seeds;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream fields(line);
    Eigen::Vector3d p;
    std::string rest;
    if (!(fields >> p.x() >> p.y() >> p.z()) || (fields >> rest) || !p.allFinite()) {
      std::fprintf(stderr, "hullcover: error: %s line %d: expected three numbers 'x y z'\n", path.c_str(), number);
      return std::nullopt;
    }
    if (static_cast<int>(seeds.size()) >= kMostSeeds) {
      std::fprintf(stderr, "hullcover: error: %s holds more than %d seeds\n", path.c_str(), kMostSeeds);
      return std::nullopt;
    }
    seeds.push_back(p);
  }
  if (seeds.empty()) {
    std::fprintf(stderr, "hullcover: error: %s holds no seed (one 'x y z' a line)\n", path.c_str());
    return std::nullopt;
  }
  return seeds;
}

} // namespace

void add_movement_options(CLI::App& cmd, MovementCliOptions& o) {
  cmd.add_option("--agent-reach", o.reach,
                 "A movement covering for agents of --agent-radius: hulls model only the space such agents can "
                 "occupy, walking (standing on walkable faces, stepping up --agent-climb, dropping off ledges) or "
                 "flying (anywhere at clearance >= r connected to a seed), and an agent anywhere it can be sinks "
                 "at most --agent-slop deeper than into the triangles. RAYS ARE NOT KEPT: keep the exact covering "
                 "for hitscan")
      ->check(CLI::IsMember({"walk", "fly"}));
  cmd.add_option("--agent-slop", o.slop,
                 "With --agent-reach: how much deeper an agent may sink into the hulls than into the triangles, "
                 "scene units (default radius / 15: 0.02 m for a 0.3 m agent)")
      ->check(non_negative_number());
  cmd.add_option("--agent-height", o.height,
                 "With --agent-reach walk: the upright capsule's full height, scene units (default " +
                     number_text(kDefaultHeightInRadii) + " x radius)")
      ->check(positive_number());
  cmd.add_option("--agent-climb", o.climb,
                 "With --agent-reach walk: the highest step an agent climbs, scene units (default " +
                     number_text(kDefaultClimbInRadii) + " x radius)")
      ->check(non_negative_number());
  cmd.add_option("--max-slope", o.max_slope, "With --agent-reach walk: the steepest walkable face, degrees")
      ->check(number_in(0.0, 89.999))
      ->capture_default_str();
  cmd.add_option("--up", o.up, "With --agent-reach: which axis points up")
      ->check(CLI::IsMember({"+x", "-x", "+y", "-y", "+z", "-z", "x", "y", "z"}))
      ->capture_default_str();
  cmd.add_option("--reachable-from", o.seeds_path,
                 "With --agent-reach: agents start at these points (spawn points; one 'x y z' a line, '#' "
                 "comments); default every walkable region");
}

std::string option_without_reach(const MovementCliOptions& o) {
  if (!o.reach.empty()) return {};
  if (o.slop) return "--agent-slop";
  if (o.height) return "--agent-height";
  if (o.climb) return "--agent-climb";
  if (o.max_slope != kDefaultMaxSlopeDegrees) return "--max-slope";
  if (o.up != "+y") return "--up";
  if (!o.seeds_path.empty()) return "--reachable-from";
  return {};
}

std::optional<MovementOptions> movement_options_from(const MovementCliOptions& o, double radius) {
  MovementOptions m;
  m.radius = radius;
  m.reach = o.reach == "fly" ? AgentReach::fly : AgentReach::walk;
  if (o.slop) m.slop = *o.slop;
  if (o.height) m.height = *o.height;
  if (o.climb) m.climb = *o.climb;
  m.max_slope_degrees = o.max_slope;
  m.up = up_vector(o.up);
  if (!o.seeds_path.empty()) {
    std::optional<std::vector<Eigen::Vector3d>> seeds = read_seeds(o.seeds_path);
    if (!seeds) return std::nullopt;
    m.seeds = std::move(*seeds);
  }
  return m;
}

} // namespace hullcover::app
