#include "movement/movement_merging.h"

#include "hullcover/geometry/aabb_tree.h"
#include "hullcover/geometry/triangle_distance.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace hullcover::detail {
namespace {

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

MovementMerger::MovementMerger(const MovementContext& context, const MeshConnectivity& connectivity,
                               std::vector<MovementGroup> groups, const std::vector<int>& region, double near_distance,
                               int max_hull_vertices, GroupProver& prover)
    : context_(context), max_hull_vertices_(max_hull_vertices), prover_(prover) {
  const Mesh& mesh = context.mesh;
  // (face, group) by face: a region's merger touches only its own faces.
  std::vector<std::pair<int, int>> face_group;
  for (MovementGroup& g : groups) {
    for (int f : g.faces) face_group.emplace_back(f, static_cast<int>(entries_.size()));
    entries_.push_back({std::move(g), {}, 0, true});
  }
  std::sort(face_group.begin(), face_group.end());
  const auto group_of_face = [&](int f) {
    const auto it = std::lower_bound(face_group.begin(), face_group.end(), std::pair<int, int>{f, -1});
    return it != face_group.end() && it->first == f ? it->second : -1;
  };
  // Neighbours: groups with faces sharing an edge (any edge, open or not),
  // with its length, and groups with faces within the near distance of
  // each other.
  std::vector<std::vector<std::pair<int, double>>> neighbours(entries_.size());
  std::vector<int> edges;
  for (const auto& [f, g] : face_group)
    for (int k = 0; k < 3; ++k)
      if (connectivity.face_edges[f][k] >= 0) edges.push_back(connectivity.face_edges[f][k]);
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (int e : edges) {
    const MeshEdge& edge = connectivity.edges[e];
    const double length = (mesh.positions[edge.v1] - mesh.positions[edge.v0]).norm();
    for (int i = 0; i < edge.use_count; ++i)
      for (int j = i + 1; j < edge.use_count; ++j) {
        const int ga = group_of_face(connectivity.edge_uses[edge.first_use + i].face);
        const int gb = group_of_face(connectivity.edge_uses[edge.first_use + j].face);
        if (ga < 0 || gb < 0 || ga == gb) continue;
        neighbours[ga].emplace_back(gb, length);
        neighbours[gb].emplace_back(ga, length);
      }
  }
  if (near_distance > 0.0) {
    std::vector<Aabb> boxes;
    for (const auto& [f, g] : face_group) {
      Aabb box;
      for (int k = 0; k < 3; ++k) box.extend(mesh.positions[mesh.triangles[f][k]]);
      boxes.push_back(grown(box, 0.5 * near_distance));
    }
    const AabbTree tree(boxes);
    std::vector<int> found;
    Eigen::Vector3d s[3], t[3];
    for (int i = 0; i < static_cast<int>(face_group.size()); ++i) {
      found.clear();
      tree.overlapping(boxes[i], found);
      triangle_of(mesh, face_group[i].first, s);
      const int ga = face_group[i].second;
      for (int j : found) {
        const int gb = face_group[j].second;
        if (j <= i || ga == gb) continue;
        triangle_of(mesh, face_group[j].first, t);
        if (!triangles_within(s, t, near_distance)) continue;
        neighbours[ga].emplace_back(gb, 0.0);
        neighbours[gb].emplace_back(ga, 0.0);
      }
    }
  }
  for (size_t g = 0; g < entries_.size(); ++g) entries_[g].neighbours = combined(std::move(neighbours[g]));
  for (int a = 0; a < static_cast<int>(entries_.size()); ++a)
    for (const auto& [b, shared] : entries_[a].neighbours)
      if (a < b && (region.empty() || region[a] != region[b])) push_pair(a, b, shared);
}

void MovementMerger::push_pair(int a, int b, double shared) {
  if (a > b) std::swap(a, b);
  const Entry& ea = entries_[a];
  const Entry& eb = entries_[b];
  const double cost =
      std::max(0.0, ea.group.boundary + eb.group.boundary - 2.0 * shared) / std::sqrt(ea.group.area + eb.group.area);
  queue_.push_back({cost, a, b, ea.version, eb.version});
  std::push_heap(queue_.begin(), queue_.end(), std::greater<Pair>());
  // Every merge queues its group's pairs anew, and a large group has many:
  // the entries of groups that changed since are dropped once they could
  // crowd the memory (pandora flying kept 60 million).
  if (queue_.size() >= queue_compacted_at_ + kQueueGrowthBeforeCompaction) {
    queue_.erase(std::remove_if(
                     queue_.begin(), queue_.end(),
                     [&](const Pair& p) {
      const Entry& x = entries_[p.a];
      const Entry& y = entries_[p.b];
      return !x.alive || !y.alive || x.version != p.version_a || y.version != p.version_b;
                     }),
                 queue_.end());
    std::make_heap(queue_.begin(), queue_.end(), std::greater<Pair>());
    queue_compacted_at_ = queue_.size();
  }
}

bool MovementMerger::try_merge(int a, int b, MovementGroup& merged) {
  const MovementGroup& ga = entries_[a].group;
  const MovementGroup& gb = entries_[b].group;
  merged.corners = sorted_union(ga.corners, gb.corners);
  merged.faces = sorted_union(ga.faces, gb.faces);
  merged.area = ga.area + gb.area;
  merged.area_vector = ga.area_vector + gb.area_vector;
  if (!make_group_hull(context_, max_hull_vertices_, ga.hull.planes[0].normal, prover_.builder, merged)) return false;
  ++prover_.candidates;
  const MovementVerdict verdict =
      check_movement_hull(context_, merged.hull, merged.flat, {&ga.hull, &gb.hull}, prover_.boundary);
  if (verdict == MovementVerdict::undecided) ++prover_.undecided;
  return verdict == MovementVerdict::valid;
}

void MovementMerger::merge(const std::function<void(double)>& progress) {
  const double total = std::max<size_t>(1, entries_.size());
  MovementGroup merged;
  while (!queue_.empty()) {
    std::pop_heap(queue_.begin(), queue_.end(), std::greater<Pair>());
    const Pair pair = queue_.back();
    queue_.pop_back();
    Entry& ea = entries_[pair.a];
    Entry& eb = entries_[pair.b];
    if (!ea.alive || !eb.alive || ea.version != pair.version_a || eb.version != pair.version_b) continue;
    if (!try_merge(pair.a, pair.b, merged)) continue;
    // a takes the union; b's neighbours become a's, with their shared lengths.
    double shared = 0.0;
    std::vector<std::pair<int, double>> around = ea.neighbours;
    around.insert(around.end(), eb.neighbours.begin(), eb.neighbours.end());
    for (const auto& [g, length] : ea.neighbours)
      if (g == pair.b) shared = length;
    around.erase(std::remove_if(
                     around.begin(), around.end(),
                     [&](const std::pair<int, double>& n) {
      return n.first == pair.a || n.first == pair.b || !entries_[n.first].alive;
                     }),
                 around.end());
    merged.boundary = std::max(0.0, ea.group.boundary + eb.group.boundary - 2.0 * shared);
    std::swap(ea.group, merged);
    ea.neighbours = combined(std::move(around));
    ++ea.version;
    eb.alive = false;
    eb.neighbours.clear();
    for (const auto& [g, length] : ea.neighbours) {
      // g's entries for a and b become one for a.
      std::vector<std::pair<int, double>>& n = entries_[g].neighbours;
      for (auto& entry : n)
        if (entry.first == pair.b) entry.first = pair.a;
      n = combined(std::move(n));
      push_pair(pair.a, g, length);
    }
    ++merges_;
    if (progress && (merges_ & 255) == 0) progress(std::min(0.95, merges_ / total));
  }
}

std::vector<MovementGroup> MovementMerger::take_groups() {
  std::vector<MovementGroup> out;
  for (Entry& e : entries_)
    if (e.alive) out.push_back(std::move(e.group));
  entries_.clear();
  return out;
}

void drop_held_groups(const MovementContext& context, std::vector<MovementGroup>& groups) {
  const Mesh& mesh = context.mesh;
  const double tol = context.tol;
  std::vector<Aabb> boxes;
  for (const MovementGroup& g : groups) boxes.push_back(grown(g.box, tol));
  const AabbTree tree(boxes);
  std::vector<char> alive(groups.size(), 1);
  // A group that holds a dropped group's face stays: dropping it too would
  // leave that face bare.
  std::vector<char> holding(groups.size(), 0);
  std::vector<int> found, holders;
  for (int g = 0; g < static_cast<int>(groups.size()); ++g) {
    if (holding[g]) continue;
    holders.clear();
    bool held = true;
    for (int f : groups[g].faces) {
      Aabb face_box;
      for (int k = 0; k < 3; ++k) face_box.extend(mesh.positions[mesh.triangles[f][k]]);
      found.clear();
      tree.overlapping(face_box, found);
      std::sort(found.begin(), found.end());
      int holder = -1;
      for (int h : found) {
        if (h == g || !alive[h]) continue;
        bool all = true;
        for (int k = 0; k < 3 && all; ++k) all = holds(groups[h].hull, mesh.positions[mesh.triangles[f][k]], tol);
        if (all) {
          holder = h;
          break;
        }
      }
      if (!(held = holder >= 0)) break;
      holders.push_back(holder);
    }
    if (!held) continue;
    alive[g] = 0;
    for (int h : holders) holding[h] = 1;
  }
  size_t kept = 0;
  for (size_t g = 0; g < groups.size(); ++g) {
    if (!alive[g]) continue;
    if (kept != g) groups[kept] = std::move(groups[g]); // never onto itself: that would empty it
    ++kept;
  }
  groups.resize(kept);
}

std::vector<CoveringHull> hulls_of_groups(const Mesh& mesh, double tol, const std::vector<MovementGroup>& groups) {
  std::vector<CoveringHull> out;
  for (const MovementGroup& g : groups) {
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
