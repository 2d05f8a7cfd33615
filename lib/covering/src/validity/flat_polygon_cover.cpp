#include "validity/flat_polygon_cover.h"

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

// A convex piece of the part still uncovered, with its box. `kept`: it
// passed the sliver test, which then need not be made again while it is
// carried whole from one cutter to the next.
struct UncoveredPiece {
  Polygon2d corners;
  Box2d box;
  bool kept = false;
};

// Whether a piece is wider than a sliver of about 2 tol.
bool wider_than_sliver(const Polygon2d& piece, double tol) {
  return polygon_area(piece) > tol * polygon_perimeter(piece);
}

// The uncovered pieces and the storage their subtraction reuses, for one
// polygon's check.
struct Uncovered {
  std::vector<UncoveredPiece> pieces, next;
  std::vector<Polygon2d> cut;
  PolygonSubtractionStorage subtraction;
};

// Every piece less `cutter`, dropping slivers no wider than about 2 tol. A
// piece apart from the cutter (their boxes first: most faces in a large
// polygon's slab reach one piece or none) is what subtracting would give
// back whole, and is carried over without a copy.
void subtract_from_all(Uncovered& uncovered, const Polygon2d& cutter, double tol) {
  std::vector<UncoveredPiece>& out = uncovered.next;
  out.clear();
  const Box2d cutter_box = cutter.empty() ? Box2d{} : box_of(cutter); // once for every piece
  for (UncoveredPiece& piece : uncovered.pieces) {
    if (cutter.empty() || boxes_apart(piece.box, cutter_box) || convex_polygons_apart(piece.corners, cutter)) {
      if (piece.kept || (piece.corners.size() >= 3 && wider_than_sliver(piece.corners, tol))) {
        piece.kept = true;
        out.push_back(std::move(piece));
      }
      continue;
    }
    uncovered.cut.clear();
    subtract_overlapping_convex_polygon(piece.corners, cutter, uncovered.cut, uncovered.subtraction);
    for (Polygon2d& rest : uncovered.cut)
      if (wider_than_sliver(rest, tol)) {
        const Box2d box = box_of(rest);
        out.push_back({std::move(rest), box, true});
      }
  }
  uncovered.pieces.swap(out);
}

// Whether the box of `corners` in the frame is apart from every piece's: the
// face's polygon, inside that box, then leaves every piece whole.
bool apart_from_every_piece(const PlaneFrame& frame, const std::vector<Eigen::Vector3d>& corners,
                            const std::vector<UncoveredPiece>& pieces) {
  Box2d box;
  box.low = box.high = frame.to_plane(corners.front());
  for (const Eigen::Vector3d& c : corners) {
    const Eigen::Vector2d q = frame.to_plane(c);
    box.low = box.low.cwiseMin(q);
    box.high = box.high.cwiseMax(q);
  }
  for (const UncoveredPiece& piece : pieces)
    if (!boxes_apart(piece.box, box)) return false;
  return true;
}

} // namespace

Validity check_polygon_covered(const SceneIndex& index, const FlatPolygon& merged,
                               const std::vector<Eigen::Vector3d>& corners_a,
                               const std::vector<Eigen::Vector3d>& corners_b, std::vector<int>& scratch,
                               double slab_in_tolerances) {
  if (merged.corners.size() < 3) return Validity::valid;
  const double tol = index.tol();
  const PlaneFrame frame = PlaneFrame::from_normal(merged.corners.front(), merged.plane.normal);
  Uncovered uncovered;
  Polygon2d whole = convex_in_frame(frame, merged.corners, tol);
  if (!whole.empty()) {
    const Box2d box = box_of(whole);
    uncovered.pieces.push_back({std::move(whole), box, false});
  }
  subtract_from_all(uncovered, convex_in_frame(frame, corners_a, tol), tol);
  subtract_from_all(uncovered, convex_in_frame(frame, corners_b, tol), tol);
  if (uncovered.pieces.empty()) return Validity::valid;

  // Other faces in the slab may cover the rest (a near merge across a tile
  // of another patch; a merge that reaches over faces merged later).
  const double slab = slab_in_tolerances * tol;
  Aabb box;
  for (const UncoveredPiece& piece : uncovered.pieces)
    for (const Eigen::Vector2d& q : piece.corners) box.extend(frame.origin + q.x() * frame.u + q.y() * frame.v);
  scratch.clear();
  index.face_tree.overlapping(grown(box, slab), scratch);
  const MeshView& mesh = index.mesh();
  std::vector<Eigen::Vector3d> corners(3);
  for (int f : scratch) {
    bool in_slab = true;
    for (int k = 0; k < 3; ++k) {
      corners[k] = mesh.positions[mesh.triangles[f][k]];
      in_slab = in_slab && std::abs(merged.plane.signed_distance(corners[k])) <= slab;
    }
    // A face reaching no piece's box leaves every piece as it is.
    if (!in_slab || apart_from_every_piece(frame, corners, uncovered.pieces)) continue;
    subtract_from_all(uncovered, convex_in_frame(frame, corners, tol), tol);
    if (uncovered.pieces.empty()) return Validity::valid;
    if (static_cast<int>(uncovered.pieces.size()) > kMaxUncoveredPieces) return Validity::polygon_spans_gap;
  }
  return Validity::polygon_spans_gap;
}

} // namespace hullcover
