#include "hullcover/lib/validity_conditions.h"

namespace hullcover {

const char* validity_name(Validity v) {
  switch (v) {
    case Validity::valid: return "valid";
    case Validity::vertex_inside: return "vertex_inside";
    case Validity::edge_inside: return "edge_inside";
    case Validity::face_not_on_hull: return "face_not_on_hull";
    case Validity::bar_inside: return "bar_inside";
    case Validity::bar_crosses_polygon: return "bar_crosses_polygon";
    case Validity::face_below_polygon: return "face_below_polygon";
    case Validity::too_many_vertices: return "too_many_vertices";
    case Validity::materials_differ: return "materials_differ";
    case Validity::hull_failed: return "hull_failed";
  }
  return "unknown";
}

Aabb bounding_box_of(const std::vector<Eigen::Vector3d>& points) {
  Aabb box;
  for (const Eigen::Vector3d& p : points) box.extend(p);
  return box;
}

bool planes_support_points(const std::vector<Plane>& planes, const std::vector<Eigen::Vector3d>& points, double tol) {
  for (const Plane& plane : planes)
    for (const Eigen::Vector3d& p : points)
      if (plane.signed_distance(p) > tol) return false;
  return true;
}

Validity check_solid_hull(const SceneIndex& index, const ConvexPolytope& hull, std::vector<int>& scratch) {
  const double tol = index.tol();
  const Aabb box = grown(bounding_box_of(hull.vertices), tol);
  const Mesh& mesh = index.mesh();

  scratch.clear();
  index.vertex_tree.overlapping(box, scratch);
  for (int v : scratch)
    if (deepest_signed_distance(hull.planes, mesh.positions[v]) < -tol) return Validity::vertex_inside;

  scratch.clear();
  index.edge_tree.overlapping(box, scratch);
  for (int e : scratch) {
    const MeshEdge& edge = index.prepared->connectivity.edges[e];
    if (segment_enters_interior(hull.planes, mesh.positions[edge.v0], mesh.positions[edge.v1], tol))
      return Validity::edge_inside;
  }

  scratch.clear();
  index.bars_overlapping(box, scratch);
  for (int b : scratch)
    if (segment_enters_interior(hull.planes, index.bars[b].a, index.bars[b].b, tol)) return Validity::bar_inside;
  return Validity::valid;
}

namespace {

bool bar_crosses_polygon(const FlatPolygon& polygon, const BoundaryBar& bar, double tol) {
  const double da = polygon.plane.signed_distance(bar.a);
  const double db = polygon.plane.signed_distance(bar.b);
  if ((da > tol && db > tol) || (da < -tol && db < -tol)) return false;
  // A bar lying in the plane (within tol) does not cross the polygon: it is
  // the bar of an open edge resting on it (a wall's culled bottom edge on a
  // floor), whose opening the polygon itself closes.
  if (std::abs(da - db) <= tol) return false;
  const Eigen::Vector3d crossing = bar.a + (bar.b - bar.a) * (da / (da - db));
  return deepest_signed_distance(polygon.sides, crossing) < -tol;
}

// Does the part of triangle t within tol of the polygon's plane reach the
// polygon's interior (shrunk by tol)?
bool triangle_touches_polygon_interior(const FlatPolygon& polygon, const std::vector<Eigen::Vector3d>& triangle,
                                       double tol) {
  std::vector<Eigen::Vector3d> part = clip_polygon(triangle, polygon.plane, -tol);
  part = clip_polygon(part, {-polygon.plane.normal, -polygon.plane.offset}, -tol);
  for (const Plane& side : polygon.sides) {
    if (part.empty()) return false;
    part = clip_polygon(part, side, tol);
  }
  return !part.empty();
}

} // namespace

Validity check_flat_polygon(const SceneIndex& index, const FlatPolygon& polygon,
                            const std::function<bool(int)>& in_patch, std::vector<int>& scratch) {
  const double tol = index.tol();
  const Aabb box = grown(bounding_box_of(polygon.corners), tol);
  const Mesh& mesh = index.mesh();

  scratch.clear();
  index.bars_overlapping(box, scratch);
  for (int b : scratch)
    if (bar_crosses_polygon(polygon, index.bars[b], tol)) return Validity::bar_crosses_polygon;

  scratch.clear();
  index.face_tree.overlapping(box, scratch);
  std::vector<Eigen::Vector3d> triangle(3);
  for (int f : scratch) {
    if (in_patch(f)) continue;
    bool below = false;
    for (int k = 0; k < 3; ++k) {
      triangle[k] = mesh.positions[mesh.triangles[f][k]];
      below |= polygon.plane.signed_distance(triangle[k]) < -tol;
    }
    if (below && triangle_touches_polygon_interior(polygon, triangle, tol)) return Validity::face_below_polygon;
  }
  return Validity::valid;
}

} // namespace hullcover
