#pragma once
/// \file scene_builder.h
/// Building blocks for synthetic scenes made in code: the demo scene and the
/// test cases. Every function appends to a `Mesh`, giving each triangle the
/// material id passed in. Coordinates are y-up, in metres.

#include "hullcover/geometry/mesh.h"

#include <functional>

namespace hullcover {

/// Appends the quad a-b-c-d as two triangles (a,b,c) and (a,c,d). The front
/// is the side from which a, b, c, d run counter-clockwise.
void add_quad(Mesh& mesh, const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
              const Eigen::Vector3d& d, int material = 0);

/// Appends a closed axis-aligned box of 12 triangles with shared vertices.
/// `outward` true: normals point out (a solid block); false: normals point in
/// (a room seen from inside). Requires min < max on every axis.
void add_box(Mesh& mesh, const Eigen::Vector3d& min, const Eigen::Vector3d& max, bool outward = true, int material = 0);

/// Appends an open height field y = height(x, z) over [x0, x1] x [z0, z1],
/// facing up, with grid lines at the given sorted x and z coordinates (so
/// the tessellation may be non-uniform). Shared vertices; one boundary loop.
void add_height_field(Mesh& mesh, const std::vector<double>& xs, const std::vector<double>& zs,
                      const std::function<double(double, double)>& height, int material = 0);

/// Material ids used by `demo_building`.
enum DemoMaterial : int { demo_terrain = 0, demo_floor = 1, demo_wall = 2, demo_stairs = 3 };

/// The embedded default scene: a small building (footprint 10 x 8 m, walls
/// 3 m high) on a floor slab with a doorway in its front wall, an interior
/// wall that stops short of the front to leave a passage, a flight of
/// stairs against the back wall, a roof slab, and a patch of uneven,
/// non-uniformly tessellated terrain beside it. Walls are closed boxes that
/// touch each other and the floor, as in real levels.
Mesh demo_building();

} // namespace hullcover
