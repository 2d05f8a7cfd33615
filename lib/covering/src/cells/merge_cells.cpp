#include "hullcover/covering/merge_cells.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>

namespace hullcover {
namespace {

using CellKey = std::array<long long, 3>;

Eigen::Vector3d centroid(const MeshView& mesh, int f) {
  const Eigen::Vector3i& t = mesh.triangles[f];
  return (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3.0;
}

// The grid cell of a point: cubes of side `size` with a corner at `centre`.
CellKey cell_key(const Eigen::Vector3d& p, const Eigen::Vector3d& centre, double size) {
  CellKey key;
  for (int axis = 0; axis < 3; ++axis) key[axis] = static_cast<long long>(std::floor((p[axis] - centre[axis]) / size));
  return key;
}

// Faces per occupied cell of side `size` of the grid through `centre`, in
// key order.
std::map<CellKey, std::vector<int>> cells_of_grid(const MeshView& mesh, const std::vector<int>& faces,
                                                  const Eigen::Vector3d& centre, double size) {
  std::map<CellKey, std::vector<int>> cells;
  for (int f : faces) cells[cell_key(centroid(mesh, f), centre, size)].push_back(f);
  return cells;
}

// The same for one island's grid, centred on its box.
std::map<CellKey, std::vector<int>> cells_of_island(const MeshView& mesh, const std::vector<int>& faces,
                                                    const Aabb& box, double size) {
  return cells_of_grid(mesh, faces, 0.5 * (box.min + box.max), size);
}

// Finer grids than this many cells along an island's longest side are not
// tried: a cluster of faces that dense stays one cell (a bound on the work
// for any input).
constexpr long long kMostCellsAlongAnIsland = 1024;

// The automatic side for an island: its longest extent over k, for the
// smallest power of two k whose occupied cells average at most
// kFacesPerAutomaticCell.
double automatic_cell_size(const MeshView& mesh, const std::vector<int>& faces, const Aabb& box) {
  if (static_cast<int>(faces.size()) <= kFacesPerAutomaticCell) return 0.0;
  const double longest = (box.max - box.min).maxCoeff();
  if (!(longest > 0.0)) return 0.0;
  double size = longest;
  for (long long k = 2; k <= kMostCellsAlongAnIsland; k *= 2) {
    size = longest / static_cast<double>(k);
    const size_t occupied = cells_of_island(mesh, faces, box, size).size();
    if (faces.size() <= occupied * static_cast<size_t>(kFacesPerAutomaticCell)) return size;
  }
  return size;
}

// Appends one cell with every per-cell field, so the fields stay aligned
// by cell index whichever way a layout is made.
void add_cell(std::vector<int> faces, int island, int halvings, CellLayout& layout) {
  layout.faces_of_cell.push_back(std::move(faces));
  layout.island_of_cell.push_back(island);
  layout.cell_halvings.push_back(halvings);
}

// Appends island `island`'s cells of `faces` on the grid of side `size`
// through `centre`, in key order. With `finest` > 0, a cell holding more
// than kMostFacesPerAutomaticCell faces is replaced by its cells on the
// grid of half the side (the same centre: halving a side splits each cube
// into eight, to the bit, since halving a quotient is exact), down to sides
// of `finest`.
void append_cells(const MeshView& mesh, const std::vector<int>& faces, const Eigen::Vector3d& centre, double size,
                  double finest, int island, int halvings, CellLayout& layout) {
  for (auto& [key, cell] : cells_of_grid(mesh, faces, centre, size)) {
    if (finest > 0.0 && static_cast<int>(cell.size()) > kMostFacesPerAutomaticCell && 0.5 * size >= finest) {
      append_cells(mesh, cell, centre, 0.5 * size, finest, island, halvings + 1, layout);
      continue;
    }
    add_cell(std::move(cell), island, halvings, layout);
  }
}

// Fills cell_of_face and slot_in_cell from faces_of_cell.
void index_faces(CellLayout& layout) {
  for (int c = 0; c < static_cast<int>(layout.faces_of_cell.size()); ++c)
    for (int slot = 0; slot < static_cast<int>(layout.faces_of_cell[c].size()); ++slot) {
      const int f = layout.faces_of_cell[c][slot];
      layout.cell_of_face[f] = c;
      layout.slot_in_cell[f] = slot;
    }
}

} // namespace

CellLayout lay_out_islands(const PreparedSceneView& prepared, const IslandsView& islands) {
  const int face_count = static_cast<int>(prepared.mesh.triangles.size());
  CellLayout layout;
  layout.cell_of_face.assign(face_count, 0);
  layout.slot_in_cell.assign(face_count, 0);
  std::vector<std::vector<int>> faces_of_island(islands.boxes.size());
  for (int f = 0; f < face_count; ++f) faces_of_island[islands.island_of_face[f]].push_back(f);
  for (size_t i = 0; i < faces_of_island.size(); ++i)
    add_cell(std::move(faces_of_island[i]), static_cast<int>(i), 0, layout);
  layout.island_cell_size.assign(islands.boxes.size(), 0.0);
  index_faces(layout);
  return layout;
}

CellLayout lay_out_cells(const PreparedSceneView& prepared, const IslandsView& islands,
                         std::optional<double> cell_size) {
  const MeshView& mesh = prepared.mesh;
  const int face_count = static_cast<int>(mesh.triangles.size());
  CellLayout layout;
  layout.cell_of_face.assign(face_count, 0);
  layout.slot_in_cell.assign(face_count, 0);
  if (cell_size && *cell_size == 0.0) {
    std::vector<int> every_face(face_count);
    std::iota(every_face.begin(), every_face.end(), 0);
    add_cell(std::move(every_face), islands.boxes.size() == 1 ? 0 : -1, 0, layout);
    layout.island_cell_size.assign(islands.boxes.size(), 0.0);
    index_faces(layout);
    return layout;
  }
  std::vector<std::vector<int>> faces_of_island(islands.boxes.size());
  for (int f = 0; f < face_count; ++f) faces_of_island[islands.island_of_face[f]].push_back(f);
  for (size_t i = 0; i < faces_of_island.size(); ++i) {
    const std::vector<int>& faces = faces_of_island[i];
    const Aabb& box = islands.boxes[i];
    const double size = cell_size ? *cell_size : automatic_cell_size(mesh, faces, box);
    layout.island_cell_size.push_back(size);
    if (!(size > 0.0)) {
      add_cell(faces, static_cast<int>(i), 0, layout);
      continue;
    }
    // A user's side is kept as given; the automatic grid halves its crowded
    // cubes, down to the finest grid automatic_cell_size tries.
    const double finest =
        cell_size ? 0.0 : (box.max - box.min).maxCoeff() / static_cast<double>(kMostCellsAlongAnIsland);
    append_cells(mesh, faces, 0.5 * (box.min + box.max), size, finest, static_cast<int>(i), 0, layout);
  }
  index_faces(layout);
  return layout;
}

} // namespace hullcover
