#include "movement/uncovered_boundary.h"

#include "hullcover/geometry/planar_hull.h"
#include "hullcover/geometry/triangle_distance.h"

#include <algorithm>
#include <cmath>

namespace hullcover::detail {
namespace {

using Polygon2 = std::vector<Eigen::Vector2d>;

double signed_area(const Polygon2& p) {
  double a = 0.0;
  for (size_t i = 0; i < p.size(); ++i) {
    const Eigen::Vector2d& u = p[i];
    const Eigen::Vector2d& v = p[(i + 1) % p.size()];
    a += u.x() * v.y() - u.y() * v.x();
  }
  return 0.5 * a;
}

using Polygon3 = std::vector<Eigen::Vector3d>;

// Removes convex `cut` (counter-clockwise in `frame`'s plane), grown by
// `grow`, from every piece of `pieces` (polygons in that plane). Each side
// is pushed out by `grow`, and each corner is capped by a line across its
// bisector `grow` beyond it: pushed sides alone would carry a sharp corner
// out by grow / sin(half its angle), far beyond `grow`; capped, no point of
// the grown polygon lies farther than grow * sqrt(2) from `cut`.
void subtract(std::vector<Polygon3>& pieces, const Polygon2& cut, const PlaneFrame& frame, double grow) {
  // The grown polygon's half-planes n . x <= offset in the frame, each as
  // a plane across the facet's.
  std::vector<Plane> sides;
  const auto add_side = [&](const Eigen::Vector2d& n, double offset) {
    const Eigen::Vector3d normal = n.x() * frame.u + n.y() * frame.v;
    sides.push_back({normal, offset + normal.dot(frame.origin)});
  };
  const size_t count = cut.size();
  for (size_t i = 0; i < count; ++i) {
    const Eigen::Vector2d edge = cut[(i + 1) % count] - cut[i];
    const double length = edge.norm();
    if (!(length > 0.0)) continue;
    const Eigen::Vector2d n(edge.y() / length, -edge.x() / length); // outward for a counter-clockwise cut
    add_side(n, n.dot(cut[i]) + grow);
  }
  for (size_t i = 0; i < count; ++i) {
    const Eigen::Vector2d& corner = cut[i];
    const Eigen::Vector2d out =
        (corner - cut[(i + count - 1) % count]).normalized() + (corner - cut[(i + 1) % count]).normalized();
    if (!(out.norm() > 0.0) || !out.allFinite()) continue;
    const Eigen::Vector2d u = out.normalized();
    add_side(u, u.dot(corner) + grow);
  }
  std::vector<Polygon3> kept;
  Polygon3 inner, outer, rest;
  for (Polygon3& piece : pieces) {
    rest = piece;
    for (size_t i = 0; i < sides.size() && rest.size() >= 3; ++i) {
      split_polygon(rest, sides[i], inner, outer);
      if (outer.size() >= 3) kept.push_back(outer);
      rest.swap(inner);
    }
  }
  pieces.swap(kept);
}

// Whether segment p-q lies along one side of `polygon`, within `tol`.
bool on_side_of(const Polygon3& polygon, const Eigen::Vector3d& p, const Eigen::Vector3d& q, double tol) {
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector3d& a = polygon[i];
    const Eigen::Vector3d& b = polygon[(i + 1) % polygon.size()];
    if ((closest_point_on_segment(p, a, b) - p).norm() <= tol && (closest_point_on_segment(q, a, b) - q).norm() <= tol)
      return true;
  }
  return false;
}

void make_counter_clockwise(Polygon2& p) {
  if (signed_area(p) < 0.0) std::reverse(p.begin(), p.end());
}

} // namespace

void uncovered_boundary(const SceneClearance& scene, const ConvexPolytope& hull, bool flat,
                        const std::vector<const ConvexPolytope*>& known, double tol, UncoveredBoundary& out) {
  const Mesh& mesh = scene.mesh();
  std::vector<int> faces;
  const size_t facet_count = flat ? std::min<size_t>(1, hull.facets.size()) : hull.facets.size();
  std::vector<Polygon3> pieces;
  Polygon2 cut;
  std::vector<Eigen::Vector2d> on_plane;
  for (size_t f = 0; f < facet_count; ++f) {
    const Plane& plane = hull.planes[f];
    const PlaneFrame frame = PlaneFrame::from_normal(hull.vertices[hull.facets[f][0]], plane.normal);
    Polygon3 facet;
    for (int v : hull.facets[f]) facet.push_back(hull.vertices[v]);
    pieces.assign(1, facet);
    // The parts first: they hold most of a merged hull's boundary.
    for (const ConvexPolytope* part : known) {
      if (pieces.empty()) break;
      on_plane.clear();
      for (const Eigen::Vector3d& p : part->vertices)
        if (std::abs(plane.signed_distance(p)) <= tol) on_plane.push_back(frame.to_plane(p));
      if (on_plane.size() < 3) continue;
      const std::vector<int> corners = convex_hull_2d(on_plane, tol);
      if (corners.size() < 3) continue;
      cut.clear();
      for (int c : corners) cut.push_back(on_plane[c]);
      make_counter_clockwise(cut);
      subtract(pieces, cut, frame, tol);
      if (pieces.size() + out.pieces.size() > kMostUncoveredPieces) {
        out.overflow = true;
        return;
      }
    }
    faces.clear();
    if (!pieces.empty()) scene.faces_meeting(grown(bounding_box_of(facet), tol), faces);
    std::sort(faces.begin(), faces.end());
    for (int face : faces) {
      if (pieces.empty()) break;
      const Eigen::Vector3i& t = mesh.triangles[face];
      bool in_plane = true;
      cut.clear();
      for (int k = 0; k < 3 && in_plane; ++k) {
        in_plane = std::abs(plane.signed_distance(mesh.positions[t[k]])) <= tol;
        cut.push_back(frame.to_plane(mesh.positions[t[k]]));
      }
      if (!in_plane || !(std::abs(signed_area(cut)) > 0.0)) continue;
      make_counter_clockwise(cut);
      subtract(pieces, cut, frame, tol);
      if (pieces.size() + out.pieces.size() > kMostUncoveredPieces) {
        out.overflow = true;
        return;
      }
    }
    if (pieces.size() + out.pieces.size() > kMostUncoveredPieces) {
      out.overflow = true;
      return;
    }
    for (Polygon3& piece : pieces) {
      for (size_t i = 0; i < piece.size(); ++i) {
        const Eigen::Vector3d& p = piece[i];
        const Eigen::Vector3d& q = piece[(i + 1) % piece.size()];
        if (on_side_of(facet, p, q, tol)) out.segments.push_back({p, q});
      }
      out.pieces.push_back({std::move(piece), plane.normal});
    }
  }
}

} // namespace hullcover::detail
