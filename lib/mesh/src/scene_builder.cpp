#include "hullcover/mesh/scene_builder.h"

#include <cassert>
#include <cmath>

namespace hullcover {

namespace {
int add_vertex(Mesh& mesh, const Eigen::Vector3d& p) {
  mesh.positions.push_back(p);
  return static_cast<int>(mesh.positions.size()) - 1;
}

void add_triangle(Mesh& mesh, int a, int b, int c, int material) {
  mesh.triangles.emplace_back(a, b, c);
  mesh.material_ids.push_back(material);
}
} // namespace

void add_quad(Mesh& mesh, const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
              const Eigen::Vector3d& d, int material) {
  const int ia = add_vertex(mesh, a), ib = add_vertex(mesh, b), ic = add_vertex(mesh, c), id = add_vertex(mesh, d);
  add_triangle(mesh, ia, ib, ic, material);
  add_triangle(mesh, ia, ic, id, material);
}

void add_box(Mesh& mesh, const Eigen::Vector3d& min, const Eigen::Vector3d& max, bool outward, int material) {
  assert((min.array() < max.array()).all());
  const int base = static_cast<int>(mesh.positions.size());
  // Corner i has x from bit 0, y from bit 1, z from bit 2.
  for (int i = 0; i < 8; ++i)
    add_vertex(mesh, {(i & 1) ? max.x() : min.x(), (i & 2) ? max.y() : min.y(), (i & 4) ? max.z() : min.z()});
  // Each side counter-clockwise seen from outside.
  static const int kSides[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& s : kSides) {
    if (outward) {
      add_triangle(mesh, base + s[0], base + s[1], base + s[2], material);
      add_triangle(mesh, base + s[0], base + s[2], base + s[3], material);
    } else {
      add_triangle(mesh, base + s[0], base + s[2], base + s[1], material);
      add_triangle(mesh, base + s[0], base + s[3], base + s[2], material);
    }
  }
}

void add_height_field(Mesh& mesh, const std::vector<double>& xs, const std::vector<double>& zs,
                      const std::function<double(double, double)>& height, int material) {
  assert(xs.size() >= 2 && zs.size() >= 2);
  const int base = static_cast<int>(mesh.positions.size());
  const int nz = static_cast<int>(zs.size());
  for (double x : xs)
    for (double z : zs) add_vertex(mesh, {x, height(x, z), z});
  const auto at = [&](size_t i, size_t j) { return base + static_cast<int>(i) * nz + static_cast<int>(j); };
  for (size_t i = 0; i + 1 < xs.size(); ++i)
    for (size_t j = 0; j + 1 < zs.size(); ++j) {
      // Counter-clockwise seen from above (+y).
      add_triangle(mesh, at(i, j), at(i, j + 1), at(i + 1, j + 1), material);
      add_triangle(mesh, at(i, j), at(i + 1, j + 1), at(i + 1, j), material);
    }
}

Mesh demo_building() {
  Mesh m;
  m.material_names = {"terrain", "floor", "wall", "stairs"};
  using V = Eigen::Vector3d;
  const double wall = 0.2, height = 3.0;

  add_box(m, V(-5, -0.2, -4), V(5, 0, 4), true, demo_floor);
  add_box(m, V(-5, height, -4), V(5, height + 0.2, 4), true, demo_wall); // roof slab
  add_box(m, V(-5, 0, -4), V(5, height, -4 + wall), true, demo_wall);    // back
  add_box(m, V(-5, 0, -4 + wall), V(-5 + wall, height, 4 - wall), true, demo_wall);
  add_box(m, V(5 - wall, 0, -4 + wall), V(5, height, 4 - wall), true, demo_wall);
  // Front wall with a 1.2 x 2.1 m doorway.
  add_box(m, V(-5, 0, 4 - wall), V(-0.6, height, 4), true, demo_wall);
  add_box(m, V(0.6, 0, 4 - wall), V(5, height, 4), true, demo_wall);
  add_box(m, V(-0.6, 2.1, 4 - wall), V(0.6, height, 4), true, demo_wall);
  // Interior wall, stopping 2.3 m short of the front wall.
  add_box(m, V(-0.1, 0, -4 + wall), V(0.1, height, 1.5), true, demo_wall);
  // Six steps of 0.25 m climbing along +x against the back wall.
  for (int i = 0; i < 6; ++i)
    add_box(m, V(1.0 + 0.5 * i, 0, -4 + wall), V(1.5 + 0.5 * i, 0.25 * (i + 1), -2.8), true, demo_stairs);

  // Terrain beside the building, finer near it.
  std::vector<double> xs, zs;
  for (double x = -16; x < -8; x += 1.0) xs.push_back(x);
  for (double x = -8; x <= -5.99; x += 0.25) xs.push_back(x);
  for (double z = -6; z <= 6.01; z += 0.75) zs.push_back(z);
  add_height_field(
      m, xs, zs, [](double x, double z) { return 0.3 * std::sin(0.8 * x) * std::cos(0.6 * z) - 0.3; }, demo_terrain);
  return m;
}

} // namespace hullcover
