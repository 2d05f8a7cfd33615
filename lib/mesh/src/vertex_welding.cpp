#include "hullcover/mesh/vertex_welding.h"

#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace hullcover {
namespace {

// Grid cell coordinates and the group (island) the cell's grid belongs to.
using Cell = std::array<std::int64_t, 4>;

struct CellHash {
  size_t operator()(const Cell& c) const {
    // Large odd multipliers spread neighbouring cells over the table.
    const auto h = static_cast<std::uint64_t>(c[0]) * 0x9E3779B97F4A7C15ull ^
                   static_cast<std::uint64_t>(c[1]) * 0xC2B2AE3D27D4EB4Full ^
                   static_cast<std::uint64_t>(c[2]) * 0x165667B19E3779F9ull ^
                   static_cast<std::uint64_t>(c[3]) * 0xD6E8FEB86659FD93ull;
    return static_cast<size_t>(h ^ (h >> 29));
  }
};

Cell cell_of(const Eigen::Vector3d& p, double cell_size, int group) {
  return {static_cast<std::int64_t>(std::floor(p.x() / cell_size)),
          static_cast<std::int64_t>(std::floor(p.y() / cell_size)),
          static_cast<std::int64_t>(std::floor(p.z() / cell_size)), group};
}

} // namespace

WeldResult weld_vertices(const Mesh& mesh, double radius) {
  return weld_vertices(mesh, std::vector<int>(mesh.positions.size(), 0), {radius});
}

WeldResult weld_vertices(const Mesh& mesh, const std::vector<int>& group_of_vertex,
                         const std::vector<double>& radius_of_group) {
  assert(group_of_vertex.size() == mesh.positions.size());
  const int input_count = static_cast<int>(mesh.positions.size());

  std::vector<char> referenced(input_count, 0);
  for (const Eigen::Vector3i& tri : mesh.triangles)
    for (int k = 0; k < 3; ++k) referenced[tri[k]] = 1;

  WeldResult result;
  result.new_index_of_input_vertex.assign(input_count, -1);
  Mesh& out = result.mesh;
  out.material_ids = mesh.material_ids;
  out.material_names = mesh.material_names;
  out.coordinate_error = mesh.coordinate_error;
  out.coordinate_relative_error = mesh.coordinate_relative_error;

  std::unordered_map<Cell, std::vector<int>, CellHash> kept_in_cell;
  kept_in_cell.reserve(mesh.positions.size());

  for (int v = 0; v < input_count; ++v) {
    if (!referenced[v]) {
      ++result.unreferenced_dropped;
      continue;
    }
    const Eigen::Vector3d& p = mesh.positions[v];
    const int group = group_of_vertex[v];
    const double radius = radius_of_group[group];
    assert(radius > 0.0);
    const double radius_squared = radius * radius;
    const Cell home = cell_of(p, radius, group);
    int best = -1;
    double best_distance_squared = 0.0;
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto found = kept_in_cell.find({home[0] + dx, home[1] + dy, home[2] + dz, group});
          if (found == kept_in_cell.end()) continue;
          for (int candidate : found->second) {
            const double d2 = (out.positions[candidate] - p).squaredNorm();
            const bool within = d2 <= radius_squared;
            const bool better =
                best < 0 || d2 < best_distance_squared || (d2 == best_distance_squared && candidate < best);
            if (within && better) {
              best = candidate;
              best_distance_squared = d2;
            }
          }
        }
    if (best < 0) {
      best = static_cast<int>(out.positions.size());
      out.positions.push_back(p);
      kept_in_cell[home].push_back(best);
    }
    result.new_index_of_input_vertex[v] = best;
  }

  out.triangles.reserve(mesh.triangles.size());
  for (const Eigen::Vector3i& tri : mesh.triangles)
    out.triangles.emplace_back(result.new_index_of_input_vertex[tri[0]], result.new_index_of_input_vertex[tri[1]],
                               result.new_index_of_input_vertex[tri[2]]);
  return result;
}

} // namespace hullcover
