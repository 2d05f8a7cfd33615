#include "hullcover/mesh/mesh_islands.h"

#include "hullcover/geometry/aabb_tree.h"

#include "disjoint_sets.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <numeric>
#include <unordered_map>

namespace hullcover {
namespace {

using detail::DisjointSets;

struct PositionHash {
  size_t operator()(const std::array<double, 3>& p) const {
    size_t h = 0;
    for (double c : p) {
      std::uint64_t bits = 0;
      std::memcpy(&bits, &c, sizeof bits);
      h = h * 0x9E3779B97F4A7C15ull ^ (bits + (h << 6) + (h >> 2));
    }
    return h;
  }
};

// Per triangle, the lowest triangle of its connected piece.
std::vector<int> connected_pieces(const Mesh& mesh) {
  const int n = static_cast<int>(mesh.triangles.size());
  // Vertices with bit-identical positions are one vertex here (-0 and +0
  // compare equal but hash apart: a piece split there stays joined by the
  // box overlap below).
  std::unordered_map<std::array<double, 3>, int, PositionHash> first_at;
  first_at.reserve(mesh.positions.size());
  std::vector<int> canonical(mesh.positions.size(), -1);
  std::vector<int> vertex_face(mesh.positions.size(), -1);
  DisjointSets faces(n);
  for (int f = 0; f < n; ++f)
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles[f][k];
      if (canonical[v] < 0) {
        const Eigen::Vector3d& p = mesh.positions[v];
        canonical[v] = first_at.emplace(std::array<double, 3>{p.x(), p.y(), p.z()}, v).first->second;
      }
      const int c = canonical[v];
      if (vertex_face[c] < 0)
        vertex_face[c] = f;
      else
        faces.join(vertex_face[c], f);
    }
  std::vector<int> piece(n);
  for (int f = 0; f < n; ++f) piece[f] = faces.find(f);
  return piece;
}

} // namespace

double MeshIslands::largest_diagonal() const {
  double largest = 0.0;
  for (const Aabb& box : boxes) largest = std::max(largest, box.diagonal());
  return largest;
}

double MeshIslands::smallest_diagonal() const {
  double smallest = 0.0;
  for (const Aabb& box : boxes)
    if (box.diagonal() > 0.0 && (smallest == 0.0 || box.diagonal() < smallest)) smallest = box.diagonal();
  return smallest;
}

MeshIslands find_mesh_islands(const Mesh& mesh) {
  const int n = static_cast<int>(mesh.triangles.size());
  const std::vector<int> piece = connected_pieces(mesh);
  // Pieces, numbered by their lowest triangle, and their boxes.
  std::vector<int> piece_index(n, -1);
  std::vector<Aabb> piece_boxes;
  for (int f = 0; f < n; ++f) {
    const int root = piece[f];
    if (piece_index[root] < 0) {
      piece_index[root] = static_cast<int>(piece_boxes.size());
      piece_boxes.emplace_back();
    }
    Aabb& box = piece_boxes[piece_index[root]];
    for (int k = 0; k < 3; ++k) box.extend(mesh.positions[mesh.triangles[f][k]]);
  }
  std::vector<Aabb> grown_boxes;
  grown_boxes.reserve(piece_boxes.size());
  for (const Aabb& box : piece_boxes) grown_boxes.push_back(grown(box, kIslandJoinRelative * box.diagonal()));
  const AabbTree tree(grown_boxes);
  DisjointSets pieces(static_cast<int>(piece_boxes.size()));
  std::vector<int> near;
  for (int p = 0; p < static_cast<int>(grown_boxes.size()); ++p) {
    near.clear();
    tree.overlapping(grown_boxes[p], near);
    for (int q : near) pieces.join(p, q);
  }
  MeshIslands islands;
  islands.island_of_face.assign(n, -1);
  std::vector<int> island_of_root(piece_boxes.size(), -1);
  for (int f = 0; f < n; ++f) {
    const int root = pieces.find(piece_index[piece[f]]);
    if (island_of_root[root] < 0) {
      island_of_root[root] = static_cast<int>(islands.boxes.size());
      islands.boxes.emplace_back();
      islands.face_counts.push_back(0);
    }
    const int island = island_of_root[root];
    islands.island_of_face[f] = island;
    ++islands.face_counts[island];
    for (int k = 0; k < 3; ++k) islands.boxes[island].extend(mesh.positions[mesh.triangles[f][k]]);
  }
  return islands;
}

} // namespace hullcover
