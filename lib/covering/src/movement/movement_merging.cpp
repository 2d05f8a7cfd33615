#include "movement/movement_merging.h"

#include "hullcover/geometry/aabb_tree.h"
#include "hullcover/geometry/planar_hull.h"
#include "hullcover/geometry/triangle_distance.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <functional>

namespace hullcover::detail {
namespace {

Aabb merged_box(const Aabb& a, const Aabb& b) {
  Aabb box = a;
  box.extend(b.min);
  box.extend(b.max);
  return box;
}

std::vector<int> sorted_union(const std::vector<int>& a, const std::vector<int>& b) {
  std::vector<int> u;
  u.reserve(a.size() + b.size());
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(u));
  return u;
}

// Whether `p` lies in `hull` or within `tol` of it: behind every plane, or
// within tol of a facet (a plane test with slack would pass a point far
// past a thin hull's sharp rim).
bool holds(const ConvexPolytope& hull, const Eigen::Vector3d& p, double tol) {
  return deepest_signed_distance(hull.planes, p) <= 0.0 || distance_to_facet_fans(hull, p) <= tol;
}

// Sorted by group, each group once with its lengths added up.
std::vector<std::pair<int, double>> combined(std::vector<std::pair<int, double>> list) {
  std::sort(list.begin(), list.end());
  std::vector<std::pair<int, double>> out;
  for (const auto& [g, length] : list) {
    if (!out.empty() && out.back().first == g)
      out.back().second += length;
    else
      out.emplace_back(g, length);
  }
  return out;
}

void triangle_of(const Mesh& mesh, int face, Eigen::Vector3d (&t)[3]) {
  for (int k = 0; k < 3; ++k) t[k] = mesh.positions[mesh.triangles[face][k]];
}

} // namespace

bool MovementMerger::start_group(int f, Group& group) const {
  const Mesh& mesh = context_.mesh;
  const Eigen::Vector3i& t = mesh.triangles[f];
  const Eigen::Vector3d &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
  const Eigen::Vector3d n = (b - a).cross(c - a);
  if (!(n.norm() > 0.0)) return false;
  FlatPolygon polygon = flat_triangle(a, b, c);
  polygon.corner_vertices = {t[0], t[1], t[2]};
  group.faces = {f};
  group.corners = {t[0], t[1], t[2]};
  std::sort(group.corners.begin(), group.corners.end());
  group.hull = flat_polytope(polygon, true);
  group.flat = true;
  group.box = bounding_box_of(polygon.corners);
  group.area = 0.5 * n.norm();
  group.boundary = (b - a).norm() + (c - b).norm() + (a - c).norm();
  group.area_vector = 0.5 * n;
  return true;
}

MovementMerger::MovementMerger(const MovementContext& context, const MeshConnectivity& connectivity,
                               const std::vector<int>& faces, double near_distance, int max_hull_vertices,
                               MovementStatistics& statistics, std::function<void(double)> progress)
    : context_(context), max_hull_vertices_(max_hull_vertices), statistics_(statistics),
      progress_(std::move(progress)) {
  const Mesh& mesh = context.mesh;
  std::vector<int> group_of_face(mesh.triangles.size(), -1);
  for (int f : faces) {
    Group g;
    if (!start_group(f, g)) continue;
    group_of_face[f] = static_cast<int>(groups_.size());
    groups_.push_back(std::move(g));
  }
  // Neighbours: faces sharing an edge (any edge, open or not), with its
  // length, and faces within the near distance of each other.
  std::vector<std::vector<std::pair<int, double>>> neighbours(groups_.size());
  for (const MeshEdge& edge : connectivity.edges) {
    const double length = (mesh.positions[edge.v1] - mesh.positions[edge.v0]).norm();
    for (int i = 0; i < edge.use_count; ++i)
      for (int j = i + 1; j < edge.use_count; ++j) {
        const int ga = group_of_face[connectivity.edge_uses[edge.first_use + i].face];
        const int gb = group_of_face[connectivity.edge_uses[edge.first_use + j].face];
        if (ga < 0 || gb < 0 || ga == gb) continue;
        neighbours[ga].emplace_back(gb, length);
        neighbours[gb].emplace_back(ga, length);
      }
  }
  if (near_distance > 0.0) {
    std::vector<Aabb> boxes;
    for (const Group& g : groups_) boxes.push_back(grown(g.box, 0.5 * near_distance));
    const AabbTree tree(boxes);
    std::vector<int> found;
    Eigen::Vector3d s[3], t[3];
    for (int ga = 0; ga < static_cast<int>(groups_.size()); ++ga) {
      found.clear();
      tree.overlapping(boxes[ga], found);
      triangle_of(mesh, groups_[ga].faces[0], s);
      for (int gb : found) {
        if (gb <= ga) continue;
        triangle_of(mesh, groups_[gb].faces[0], t);
        if (!triangles_within(s, t, near_distance)) continue;
        neighbours[ga].emplace_back(gb, 0.0);
        neighbours[gb].emplace_back(ga, 0.0);
      }
    }
  }
  for (size_t g = 0; g < groups_.size(); ++g) groups_[g].neighbours = combined(std::move(neighbours[g]));
}

void MovementMerger::push_pair(int a, int b, double shared) {
  if (a > b) std::swap(a, b);
  const Group& ga = groups_[a];
  const Group& gb = groups_[b];
  const double cost = std::max(0.0, ga.boundary + gb.boundary - 2.0 * shared) / std::sqrt(ga.area + gb.area);
  queue_.push_back({cost, a, b, ga.version, gb.version});
  std::push_heap(queue_.begin(), queue_.end(), std::greater<Pair>());
  // Every merge queues its group's pairs anew, and a large group has many:
  // the entries of groups that changed since are dropped once they could
  // crowd the memory (pandora flying kept 60 million).
  if (queue_.size() >= queue_compacted_at_ + kQueueGrowthBeforeCompaction) {
    queue_.erase(std::remove_if(
                     queue_.begin(), queue_.end(),
                     [&](const Pair& p) {
      const Group& x = groups_[p.a];
      const Group& y = groups_[p.b];
      return !x.alive || !y.alive || x.version != p.version_a || y.version != p.version_b;
                     }),
                 queue_.end());
    std::make_heap(queue_.begin(), queue_.end(), std::greater<Pair>());
    queue_compacted_at_ = queue_.size();
  }
}

bool MovementMerger::try_merge(int a, int b, Group& merged) {
  const Mesh& mesh = context_.mesh;
  const Group& ga = groups_[a];
  const Group& gb = groups_[b];
  merged.corners = sorted_union(ga.corners, gb.corners);
  merged.faces = sorted_union(ga.faces, gb.faces);
  merged.area = ga.area + gb.area;
  merged.area_vector = ga.area_vector + gb.area_vector;
  std::vector<Eigen::Vector3d> points;
  points.reserve(merged.corners.size());
  for (int v : merged.corners) points.push_back(mesh.positions[v]);
  const double tol = context_.tol;
  Result<ConvexPolytope> solid = builder_.build(points, merged.corners);
  if (solid.ok()) {
    merged.hull = std::move(solid).value();
    merged.flat = false;
  } else {
    // Flat (or too thin for Qhull): one polygon, every point within tol of
    // its plane, or no hull.
    Eigen::Vector3d normal = merged.area_vector;
    if (!(normal.norm() > 0.0)) normal = ga.hull.planes[0].normal;
    normal.normalize();
    const auto [low, high] = extent_along(mesh.positions, merged.corners, normal);
    if (!(high - low <= 2.0 * tol)) return false;
    FlatPolygon polygon = make_flat_polygon(mesh.positions, merged.corners, normal, tol);
    if (polygon.corners.size() < 3) return false;
    merged.hull = flat_polytope(polygon, true);
    merged.flat = true;
  }
  if (static_cast<int>(merged.hull.vertices.size()) > max_hull_vertices_) return false;
  merged.corners.clear();
  for (int id : merged.hull.vertex_ids)
    if (id >= 0) merged.corners.push_back(id);
  std::sort(merged.corners.begin(), merged.corners.end());
  merged.corners.erase(std::unique(merged.corners.begin(), merged.corners.end()), merged.corners.end());
  merged.box = merged_box(ga.box, gb.box);
  ++statistics_.candidates;
  const MovementVerdict verdict =
      check_movement_hull(context_, merged.hull, merged.flat, {&ga.hull, &gb.hull}, boundary_);
  if (verdict == MovementVerdict::undecided) ++statistics_.undecided;
  return verdict == MovementVerdict::valid;
}

void MovementMerger::run() {
  for (int a = 0; a < static_cast<int>(groups_.size()); ++a)
    for (const auto& [b, shared] : groups_[a].neighbours)
      if (a < b) push_pair(a, b, shared);
  const double total = std::max<size_t>(1, groups_.size());
  int merges = 0;
  Group merged;
  while (!queue_.empty()) {
    std::pop_heap(queue_.begin(), queue_.end(), std::greater<Pair>());
    const Pair pair = queue_.back();
    queue_.pop_back();
    Group& ga = groups_[pair.a];
    Group& gb = groups_[pair.b];
    if (!ga.alive || !gb.alive || ga.version != pair.version_a || gb.version != pair.version_b) continue;
    if (!try_merge(pair.a, pair.b, merged)) continue;
    // a takes the union; b's neighbours become a's, with their shared lengths.
    double shared = 0.0;
    std::vector<std::pair<int, double>> around = ga.neighbours;
    around.insert(around.end(), gb.neighbours.begin(), gb.neighbours.end());
    for (const auto& [g, length] : ga.neighbours)
      if (g == pair.b) shared = length;
    around.erase(std::remove_if(
                     around.begin(), around.end(),
                     [&](const std::pair<int, double>& n) {
      return n.first == pair.a || n.first == pair.b || !groups_[n.first].alive;
                     }),
                 around.end());
    merged.neighbours = combined(std::move(around));
    merged.boundary = std::max(0.0, ga.boundary + gb.boundary - 2.0 * shared);
    merged.version = ga.version + 1;
    merged.alive = true;
    std::swap(ga, merged);
    gb.alive = false;
    gb.neighbours.clear();
    for (const auto& [g, length] : ga.neighbours) {
      // g's entries for a and b become one for a.
      std::vector<std::pair<int, double>>& n = groups_[g].neighbours;
      for (auto& entry : n)
        if (entry.first == pair.b) entry.first = pair.a;
      n = combined(std::move(n));
      push_pair(pair.a, g, length);
    }
    ++statistics_.merges;
    if (progress_ && (++merges & 255) == 0) progress_(std::min(0.95, merges / total));
  }
  drop_held_groups();
}

void MovementMerger::drop_held_groups() {
  const Mesh& mesh = context_.mesh;
  const double tol = context_.tol;
  std::vector<Aabb> boxes;
  for (const Group& g : groups_) boxes.push_back(g.alive ? grown(g.box, tol) : Aabb{});
  const AabbTree tree(boxes);
  // A group that holds a dropped group's face stays: dropping it too would
  // leave that face bare.
  std::vector<char> holding(groups_.size(), 0);
  std::vector<int> found, holders;
  for (int g = 0; g < static_cast<int>(groups_.size()); ++g) {
    if (!groups_[g].alive || holding[g]) continue;
    holders.clear();
    bool held = true;
    for (int f : groups_[g].faces) {
      Aabb face_box;
      for (int k = 0; k < 3; ++k) face_box.extend(mesh.positions[mesh.triangles[f][k]]);
      found.clear();
      tree.overlapping(face_box, found);
      std::sort(found.begin(), found.end());
      int holder = -1;
      for (int h : found) {
        if (h == g || !groups_[h].alive) continue;
        bool all = true;
        for (int k = 0; k < 3 && all; ++k) all = holds(groups_[h].hull, mesh.positions[mesh.triangles[f][k]], tol);
        if (all) {
          holder = h;
          break;
        }
      }
      if (!(held = holder >= 0)) break;
      holders.push_back(holder);
    }
    if (!held) continue;
    groups_[g].alive = false;
    for (int h : holders) holding[h] = 1;
  }
}

std::vector<CoveringHull> MovementMerger::hulls() const {
  const Mesh& mesh = context_.mesh;
  const double tol = context_.tol;
  std::vector<CoveringHull> out;
  for (const Group& g : groups_) {
    if (!g.alive) continue;
    CoveringHull h;
    h.polytope = g.hull;
    h.faces = g.faces;
    h.planar = g.flat;
    h.thickness = 0.0;
    h.material = mesh.material_ids.empty() ? 0 : mesh.material_ids[g.faces.front()];
    for (int f : g.faces)
      if (!mesh.material_ids.empty()) h.material = std::min(h.material, mesh.material_ids[f]);
    h.volume = g.flat ? 0.0 : polytope_volume(g.hull);
    // A plane is the surface's own where a face of the group lies in it; a
    // flat hull's rim is where its surface ends.
    h.surface_planes.assign(g.hull.planes.size(), g.flat);
    for (size_t p = 0; p < g.hull.facets.size() && !g.flat; ++p)
      for (int f : g.faces) {
        bool in_plane = true;
        for (int k = 0; k < 3 && in_plane; ++k)
          in_plane = std::abs(g.hull.planes[p].signed_distance(mesh.positions[mesh.triangles[f][k]])) <= tol;
        if (in_plane) {
          h.surface_planes[p] = true;
          break;
        }
      }
    out.push_back(std::move(h));
  }
  std::sort(out.begin(), out.end(),
            [](const CoveringHull& x, const CoveringHull& y) { return x.faces.front() < y.faces.front(); });
  return out;
}

} // namespace hullcover::detail
