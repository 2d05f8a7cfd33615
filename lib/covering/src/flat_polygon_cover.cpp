#include "flat_polygon_cover.h"

#include "hullcover/geometry/convex_polygon_2d.h"
#include "hullcover/geometry/tolerances.h"

#include <cmath>

namespace hullcover {
namespace {

using Polygon2d = std::vector<Eigen::Vector2d>;

// The convex hull of `points` in the frame, counter-clockwise (fewer than 3
// corners when they span no area).
Polygon2d convex_in_frame(const PlaneFrame& frame, const std::vector<Eigen::Vector3d>& points, double tol) {
  Polygon2d projected, polygon;
  for (const Eigen::Vector3d& p : points) projected.push_back(frame.to_plane(p));
  for (int i : convex_hull_2d(projected, tol)) polygon.push_back(projected[i]);
  return polygon;
}

// A polygon's box in its plane frame (of a non-empty polygon).
struct Box2d {
  Eigen::Vector2d low = Eigen::Vector2d::Zero(), high = Eigen::Vector2d::Zero();
};
Box2d box_of(const Polygon2d& polygon) {
  Box2d box{polygon.front(), polygon.front()};
  for (const Eigen::Vector2d& p : polygon) {
    box.low = box.low.cwiseMin(p);
    box.high = box.high.cwiseMax(p);
  }
  return box;
}
bool boxes_apart(const Box2d& a, const Box2d& b) {
  return (a.high.array() < b.low.array()).any() || (b.high.array() < a.low.array()).any();
}

// Every piece less `cutter`, dropping slivers no wider than about 2 tol. A
// piece whose box is apart from the cutter's is what subtracting would give
// back whole (convex polygons apart have a separating edge), kept without
// a copy: most faces in a large polygon's slab reach one piece or none.
std::vector<Polygon2d> subtract_from_all(std::vector<Polygon2d>&& pieces, const Polygon2d& cutter, double tol) {
  std::vector<Polygon2d> out;
  out.reserve(pieces.size());
  const auto keep = [&](Polygon2d&& rest) {
    if (polygon_area(rest) > tol * polygon_perimeter(rest)) out.push_back(std::move(rest));
  };
  const Box2d cutter_box = cutter.empty() ? Box2d{} : box_of(cutter);  // once for every piece
  for (Polygon2d& piece : pieces) {
    if (piece.empty() || cutter.empty() || boxes_apart(box_of(piece), cutter_box)) {
      if (piece.size() >= 3) keep(std::move(piece));
      continue;
    }
    for (Polygon2d& rest : subtract_convex_polygon(piece, cutter)) keep(std::move(rest));
  }
  return out;
}

} // namespace

Validity check_polygon_covered(const SceneIndex& index, const FlatPolygon& merged,
                               const std::vector<Eigen::Vector3d>& corners_a,
                               const std::vector<Eigen::Vector3d>& corners_b, std::vector<int>& scratch,
                               double slab_in_tolerances) {
  if (merged.corners.size() < 3) return Validity::valid;
  const double tol = index.tol();
  const PlaneFrame frame = PlaneFrame::from_normal(merged.corners.front(), merged.plane.normal);
  std::vector<Polygon2d> uncovered = {convex_in_frame(frame, merged.corners, tol)};
  uncovered = subtract_from_all(std::move(uncovered), convex_in_frame(frame, corners_a, tol), tol);
  uncovered = subtract_from_all(std::move(uncovered), convex_in_frame(frame, corners_b, tol), tol);
  if (uncovered.empty()) return Validity::valid;

  // Other faces in the slab may cover the rest (a near merge across a tile
  // of another patch; a merge that reaches over faces merged later).
  const double slab = slab_in_tolerances * tol;
  Aabb box;
  for (const Polygon2d& piece : uncovered)
    for (const Eigen::Vector2d& q : piece) box.extend(frame.origin + q.x() * frame.u + q.y() * frame.v);
  scratch.clear();
  index.face_tree.overlapping(grown(box, slab), scratch);
  const Mesh& mesh = index.mesh();
  std::vector<Eigen::Vector3d> corners(3);
  for (int f : scratch) {
    bool in_slab = true;
    for (int k = 0; k < 3; ++k) {
      corners[k] = mesh.positions[mesh.triangles[f][k]];
      in_slab = in_slab && std::abs(merged.plane.signed_distance(corners[k])) <= slab;
    }
    if (!in_slab) continue;
    uncovered = subtract_from_all(std::move(uncovered), convex_in_frame(frame, corners, tol), tol);
    if (uncovered.empty()) return Validity::valid;
    if (static_cast<int>(uncovered.size()) > kMaxUncoveredPieces) return Validity::polygon_spans_gap;
  }
  return Validity::polygon_spans_gap;
}

} // namespace hullcover
