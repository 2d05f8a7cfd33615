#pragma once
// A small level for movement coverings (y up, metres), made for agents of
// radius 0.3, height 1.8 and climb 0.4: a floor, a crate holding a sealed
// void, two blocks with a gap narrower than the agent between them, a
// flight of stairs up to a landing, and a balcony on a pillar out of
// reach, with a spawn point on the floor.

#include "hullcover/covering/movement_options.h"
#include "hullcover/geometry/mesh.h"

#include <Eigen/Core>

#include <array>
#include <cmath>

namespace hullcover::test {

/// Adds the box [lo, hi] as 12 triangles facing out, or, `inward`, facing in
/// (the walls of a cavity).
inline void add_level_box(Mesh& mesh, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, bool inward = false) {
  const int base = static_cast<int>(mesh.positions.size());
  for (int i = 0; i < 8; ++i)
    mesh.positions.emplace_back((i & 1) ? hi.x() : lo.x(), (i & 2) ? hi.y() : lo.y(), (i & 4) ? hi.z() : lo.z());
  // Each quad counter-clockwise seen from outside.
  const std::array<std::array<int, 4>, 6> quads = {{{0, 4, 6, 2},   // -x
                                                    {1, 3, 7, 5},   // +x
                                                    {0, 1, 5, 4},   // -y
                                                    {2, 6, 7, 3},   // +y
                                                    {0, 2, 3, 1},   // -z
                                                    {4, 5, 7, 6}}}; // +z
  for (const auto& q : quads) {
    Eigen::Vector3i t0(base + q[0], base + q[1], base + q[2]), t1(base + q[0], base + q[2], base + q[3]);
    if (inward) {
      std::swap(t0[1], t0[2]);
      std::swap(t1[1], t1[2]);
    }
    mesh.triangles.push_back(t0);
    mesh.triangles.push_back(t1);
  }
}

/// `mesh` and a copy of it moved by `apart`, as two maps of a world (every
/// triangle material 0).
inline Mesh with_a_copy(const Mesh& mesh, const Eigen::Vector3d& apart) {
  Mesh world = mesh;
  for (const Eigen::Vector3d& p : mesh.positions) world.positions.push_back(p + apart);
  const int offset = static_cast<int>(mesh.positions.size());
  for (const Eigen::Vector3i& t : mesh.triangles) world.triangles.push_back(t.array() + offset);
  world.material_ids.assign(world.triangles.size(), 0);
  return world;
}

/// The level's parts, for the tests to look at.
struct MovementLevel {
  Mesh mesh;
  Eigen::Vector3d spawn{2.0, 0.5, 2.0};
  Eigen::Vector3d in_void{9.0, 0.75, 2.0};   ///< the middle of the crate's sealed cavity
  Eigen::Vector3d in_gap{5.0, 0.75, 6.5};    ///< the middle of the gap between the blocks
  Eigen::Vector3d on_balcony{9.0, 3.2, 9.0}; ///< on top of the balcony, out of reach
  double stair_rise = 0.15, stair_run = 0.3; ///< each step
  int steps = 5;
  Eigen::Vector3d stairs_lo{2.0, 0.0, 8.0};  ///< the flight's box, before its landing
  int first_stair_face = 0, stair_faces = 0; ///< the flight's triangles
  int first_balcony_face = 0;                ///< the balcony slab's 12 triangles
};

/// The character the level is made for: radius 0.3, slop 0.02, 1.8 tall,
/// stepping 0.4, standing on faces up to 45 degrees from level, y up.
inline AgentShape level_agent(AgentReach reach = AgentReach::walk) {
  AgentShape agent;
  agent.radius = 0.3;
  agent.slop = 0.02;
  agent.height = 1.8;
  agent.climb = 0.4;
  agent.min_up_cosine = std::cos(45.0 * M_PI / 180.0);
  agent.reach = reach;
  return agent;
}

inline MovementLevel movement_level() {
  MovementLevel level;
  Mesh& m = level.mesh;
  using V = Eigen::Vector3d;
  add_level_box(m, V(0, -0.2, 0), V(12, 0, 12));              // the floor slab
  add_level_box(m, V(8, 0, 1), V(10, 1.5, 3));                // the crate
  add_level_box(m, V(8.3, 0.3, 1.3), V(9.7, 1.2, 2.7), true); // its sealed cavity
  add_level_box(m, V(4, 0, 6), V(4.9, 1.5, 7));               // two blocks, 0.2 apart
  add_level_box(m, V(5.1, 0, 6), V(6, 1.5, 7));
  level.first_stair_face = static_cast<int>(m.triangles.size());
  for (int s = 0; s < level.steps; ++s) {
    const V lo = level.stairs_lo + V(0, 0, s * level.stair_run);
    add_level_box(m, lo, lo + V(1.0, (s + 1) * level.stair_rise, level.stair_run));
  }
  level.stair_faces = static_cast<int>(m.triangles.size()) - level.first_stair_face;
  const double top = level.steps * level.stair_rise;
  const V landing = level.stairs_lo + V(0, 0, level.steps * level.stair_run);
  add_level_box(m, landing, landing + V(1.0, top, 1.5)); // the landing, reached by the stairs
  add_level_box(m, V(8.8, 0, 8.8), V(9.2, 3.0, 9.2));    // the balcony's pillar
  level.first_balcony_face = static_cast<int>(m.triangles.size());
  add_level_box(m, V(8, 3.0, 8), V(10, 3.2, 10)); // the balcony, 3 m up
  m.material_ids.assign(m.triangles.size(), 0);
  m.material_names = {"default"};
  return level;
}

} // namespace hullcover::test
