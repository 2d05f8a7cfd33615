#include "movement/uncovered_boundary.h"

#include "hullcover/geometry/planar_hull.h"

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

// Splits convex `polygon` by the line n . x = c into the part with
// n . x <= c (`inner`) and the rest (`outer`).
void split_by_line(const Polygon2& polygon, const Eigen::Vector2d& n, double c, Polygon2& inner, Polygon2& outer) {
  inner.clear();
  outer.clear();
  const size_t count = polygon.size();
  for (size_t i = 0; i < count; ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % count];
    const double da = n.dot(a) - c, db = n.dot(b) - c;
    if (da <= 0.0) inner.push_back(a);
    if (da >= 0.0) outer.push_back(a);
    if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0)) {
      const Eigen::Vector2d x = a + (b - a) * (da / (da - db));
      inner.push_back(x);
      outer.push_back(x);
    }
  }
  if (inner.size() < 3) inner.clear();
  if (outer.size() < 3) outer.clear();
}

// Removes convex `cut` (counter-clockwise), grown by `grow`, from every
// piece of `pieces`. Each side is pushed out by `grow`, and each corner is
// capped by a line across its bisector `grow` beyond it: pushed sides
// alone would carry a sharp corner out by grow / sin(half its angle), far
// beyond `grow`; capped, no point of the grown polygon lies farther than
// grow * sqrt(2) from `cut`.
void subtract(std::vector<Polygon2>& pieces, const Polygon2& cut, double grow) {
  // The grown polygon's half-planes n . x <= offset.
  std::vector<std::pair<Eigen::Vector2d, double>> sides;
  const size_t count = cut.size();
  for (size_t i = 0; i < count; ++i) {
    const Eigen::Vector2d edge = cut[(i + 1) % count] - cut[i];
    const double length = edge.norm();
    if (!(length > 0.0)) continue;
    const Eigen::Vector2d n(edge.y() / length, -edge.x() / length); // outward for a counter-clockwise cut
    sides.emplace_back(n, n.dot(cut[i]) + grow);
  }
  for (size_t i = 0; i < count; ++i) {
    const Eigen::Vector2d& corner = cut[i];
    const Eigen::Vector2d out =
        (corner - cut[(i + count - 1) % count]).normalized() + (corner - cut[(i + 1) % count]).normalized();
    if (!(out.norm() > 0.0) || !out.allFinite()) continue;
    const Eigen::Vector2d u = out.normalized();
    sides.emplace_back(u, u.dot(corner) + grow);
  }
  std::vector<Polygon2> kept;
  Polygon2 inner, outer, rest;
  for (Polygon2& piece : pieces) {
    rest = piece;
    for (size_t i = 0; i < sides.size() && !rest.empty(); ++i) {
      split_by_line(rest, sides[i].first, sides[i].second, inner, outer);
      if (!outer.empty()) kept.push_back(outer);
      rest.swap(inner);
    }
  }
  pieces.swap(kept);
}

double distance_to_segment_2d(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

// Whether segment p-q lies along one side of `polygon`, within `tol`.
bool on_side_of(const Polygon2& polygon, const Eigen::Vector2d& p, const Eigen::Vector2d& q, double tol) {
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
    if (distance_to_segment_2d(p, a, b) <= tol && distance_to_segment_2d(q, a, b) <= tol) return true;
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
  std::vector<Polygon2> pieces;
  Polygon2 cut;
  std::vector<Eigen::Vector2d> on_plane;
  for (size_t f = 0; f < facet_count; ++f) {
    const Plane& plane = hull.planes[f];
    const PlaneFrame frame = PlaneFrame::from_normal(hull.vertices[hull.facets[f][0]], plane.normal);
    Polygon2 facet;
    for (int v : hull.facets[f]) facet.push_back(frame.to_plane(hull.vertices[v]));
    make_counter_clockwise(facet);
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
      subtract(pieces, cut, tol);
    }
    std::vector<Eigen::Vector3d> corners;
    for (int v : hull.facets[f]) corners.push_back(hull.vertices[v]);
    faces.clear();
    if (!pieces.empty()) scene.faces_meeting(grown(bounding_box_of(corners), tol), faces);
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
      subtract(pieces, cut, tol);
    }
    const auto to_space = [&](const Eigen::Vector2d& q) { return frame.origin + q.x() * frame.u + q.y() * frame.v; };
    for (const Polygon2& piece : pieces) {
      BoundaryPiece b;
      b.normal = plane.normal;
      for (const Eigen::Vector2d& q : piece) b.corners.push_back(to_space(q));
      out.pieces.push_back(std::move(b));
      for (size_t i = 0; i < piece.size(); ++i) {
        const Eigen::Vector2d& p = piece[i];
        const Eigen::Vector2d& q = piece[(i + 1) % piece.size()];
        if (on_side_of(facet, p, q, tol)) out.segments.push_back({to_space(p), to_space(q)});
      }
    }
  }
}

} // namespace hullcover::detail
