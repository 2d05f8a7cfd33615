#include "hullcover/geometry/incremental_hull.h"

#include "hullcover/geometry/tolerances.h"

#include <Eigen/Geometry>

#include <algorithm>

namespace hullcover {
std::optional<ConvexPolytope> add_point_to_hull(const ConvexPolytope& hull, const Eigen::Vector3d& p, int id,
                                                double tol) {
  const int facet_count = static_cast<int>(hull.facets.size());
  if (facet_count < 2 || hull.planes.size() != hull.facets.size()) return std::nullopt;
  std::vector<double> distance(facet_count);
  std::vector<char> visible(facet_count);
  bool any_visible = false;
  for (int f = 0; f < facet_count; ++f) {
    distance[f] = hull.planes[f].signed_distance(p);
    visible[f] = distance[f] > kVisibleBeyondTolerances * tol;
    any_visible |= visible[f] != 0;
  }
  if (!any_visible) {
    // Within a sliver of every plane, yet perhaps far past a sharp edge.
    if (*std::max_element(distance.begin(), distance.end()) <= 0.0 ||
        distance_to_facet_fans(hull, p) <= kVisibleBeyondTolerances * tol)
      return hull;
    return std::nullopt;
  }

  // Which facet owns each directed edge u -> v: a sorted list, not a map,
  // as this runs for most merges and a map allocates per edge.
  struct DirectedEdge {
    int from, to, facet;
    bool operator<(const DirectedEdge& other) const { return from != other.from ? from < other.from : to < other.to; }
  };
  std::vector<DirectedEdge> owner;
  size_t edge_count = 0;
  for (int f = 0; f < facet_count; ++f) edge_count += hull.facets[f].size();
  owner.reserve(edge_count);
  for (int f = 0; f < facet_count; ++f) {
    const std::vector<int>& poly = hull.facets[f];
    for (size_t i = 0; i < poly.size(); ++i) owner.push_back({poly[i], poly[(i + 1) % poly.size()], f});
  }
  std::sort(owner.begin(), owner.end());
  for (size_t i = 1; i < owner.size(); ++i)
    if (!(owner[i - 1] < owner[i])) return std::nullopt; // an edge used twice the same way: not a surface
  const auto owner_of = [&](int from, int to) {
    const DirectedEdge key{from, to, -1};
    const auto it = std::lower_bound(owner.begin(), owner.end(), key);
    return it != owner.end() && !(key < *it) ? it->facet : -1;
  };

  ConvexPolytope out;
  out.vertices = hull.vertices;
  out.vertex_ids = hull.vertex_ids;
  const int new_vertex = static_cast<int>(out.vertices.size());
  out.vertices.push_back(p);
  out.vertex_ids.push_back(id);

  // Facets that stay, and a new triangle on every horizon edge.
  std::vector<std::vector<int>> new_triangles;
  for (int f = 0; f < facet_count; ++f) {
    if (!visible[f]) continue;
    const std::vector<int>& poly = hull.facets[f];
    for (size_t i = 0; i < poly.size(); ++i) {
      const int u = poly[i], v = poly[(i + 1) % poly.size()];
      const int across = owner_of(v, u);
      if (across < 0) return std::nullopt; // not closed
      if (!visible[across]) new_triangles.push_back({u, v, new_vertex});
    }
  }
  for (int f = 0; f < facet_count; ++f) {
    if (visible[f]) continue;
    out.facets.push_back(hull.facets[f]);
    out.planes.push_back(hull.planes[f]);
  }
  for (std::vector<int>& t : new_triangles) {
    const Eigen::Vector3d& a = out.vertices[t[0]];
    const Eigen::Vector3d e0 = out.vertices[t[1]] - a, e1 = out.vertices[t[2]] - a;
    const Eigen::Vector3d n = e0.cross(e1);
    const double base = std::max({e0.norm(), e1.norm(), (e1 - e0).norm()});
    if (n.norm() <= kMinTriangleHeightInTolerances * tol * base) return std::nullopt;
    Plane plane;
    plane.normal = n.normalized();
    plane.offset = plane.normal.dot(a);
    out.facets.push_back(std::move(t));
    out.planes.push_back(plane);
  }

  // Drop vertices no facet uses any more (they are now inside).
  std::vector<int> remap(out.vertices.size(), -1);
  for (const std::vector<int>& poly : out.facets)
    for (int v : poly) remap[v] = 0;
  ConvexPolytope compact;
  for (size_t v = 0; v < out.vertices.size(); ++v)
    if (remap[v] == 0) {
      remap[v] = static_cast<int>(compact.vertices.size());
      compact.vertices.push_back(out.vertices[v]);
      compact.vertex_ids.push_back(out.vertex_ids[v]);
    }
  for (std::vector<int>& poly : out.facets)
    for (int& v : poly) v = remap[v];
  compact.facets = std::move(out.facets);
  compact.planes = std::move(out.planes);

  // Its own check: convex within tol, and a closed surface (V - E + F = 2).
  long edge_uses = 0;
  for (size_t f = 0; f < compact.facets.size(); ++f) {
    edge_uses += static_cast<long>(compact.facets[f].size());
    for (const Eigen::Vector3d& v : compact.vertices)
      if (compact.planes[f].signed_distance(v) > tol) return std::nullopt;
  }
  if (static_cast<long>(compact.vertices.size()) - edge_uses / 2 + static_cast<long>(compact.facets.size()) != 2)
    return std::nullopt;
  return compact;
}

} // namespace hullcover
