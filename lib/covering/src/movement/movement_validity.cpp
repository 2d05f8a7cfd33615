#include "movement/movement_validity.h"

#include "movement/within_slop.h"

#include "hullcover/geometry/triangle_distance.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace hullcover::detail {
namespace {

enum class RegionVerdict { clear, reached, undecided };

RegionVerdict worse(RegionVerdict a, RegionVerdict b) {
  if (a == RegionVerdict::reached || b == RegionVerdict::reached) return RegionVerdict::reached;
  return a == RegionVerdict::undecided || b == RegionVerdict::undecided ? RegionVerdict::undecided
                                                                        : RegionVerdict::clear;
}

// Distance from `p` to convex polygon `corners` (in one plane with unit
// normal `normal`).
double distance_to_polygon(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& corners,
                           const Eigen::Vector3d& normal) {
  const size_t n = corners.size();
  // Inside when on one side of every edge, either winding.
  bool left = true, right = true;
  for (size_t i = 0; i < n; ++i) {
    const double side = (corners[(i + 1) % n] - corners[i]).cross(p - corners[i]).dot(normal);
    left &= side >= 0.0;
    right &= side <= 0.0;
  }
  if (left || right) return std::abs(normal.dot(p - corners[0]));
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < n; ++i)
    best = std::min(best, (closest_point_on_segment(p, corners[i], corners[(i + 1) % n]) - p).norm());
  return best;
}

// The clearance below which every point of a box clears it (an agent's
// centre is at least r from every triangle). A point at this clearance or
// more is never cleared, so the cheap witnesses below count such points
// alone: a hull they refuse, the halving refuses too.
double clearing_of(const MovementContext& context) {
  return context.agent.radius - kClearingMarginInTols * context.tol;
}

// Whether no reachable centre lies in a region: `lower(c)` bounds from
// below the distance from point c to the region, and `inside(c)` tells
// whether a centre at c breaks the promise: it lies in the region or
// within tol of it (or, for a hull's inside, anywhere in it). Boxes from
// `start` are halved along their longest side until each is cleared: it
// misses the region, the reach grid holds no reachable cell in it, or
// every point of it is nearer than r - kClearingMarginInTols tol to a
// triangle (by the clearance at its centre plus its half-diagonal, or by
// its farthest corner from the nearest triangle). A point within tol of
// the region at clearance r - tol or more in a reachable cell is a
// witness: a point within tol of clearance r counts as one an agent's
// centre may be at, and one within tol of the region as in it. A box that
// is neither cleared nor holds a witness at its centre has a point at
// clearance r - kClearingMarginInTols tol or more, and meets the region:
// once its half-diagonal is below (1 - kClearingMarginInTols) tol, its
// centre is a witness unless its cell is not reachable, so a region that
// just touches where a centre may be is decided, never searched to the
// smallest box.
template <class Box, class Lower, class Inside>
RegionVerdict no_centre_in(const MovementContext& context, const Box& start, int& boxes_left, Lower&& lower,
                           Inside&& inside) {
  const double r = context.agent.radius;
  const double tol = context.tol;
  const double clearing = clearing_of(context);
  const double smallest = std::min(kSmallestProofBoxInSlops * context.agent.slop, kSmallestProofBoxInTols * tol);
  // Each box with the triangle nearest its parent's centre: most boxes are
  // cleared by their parent's triangle before any search.
  std::vector<std::pair<Box, int>> stack{{start, -1}};
  // The triangles any box of the search may be nearest to, gathered at
  // the first search (most regions are cleared before any): a short list
  // scanned is cheaper than the tree walked from its root for each box.
  std::vector<int> candidates;
  bool gathered = false, short_list = false;
  const double reach_of_start = r + half_diagonal_of(start) + tol;
  const auto nearest = [&](const Eigen::Vector3d& c, double limit, int hint) {
    if (!gathered) {
      short_list = context.clearance.faces_meeting_at_most(grown(bounds_of(start), reach_of_start),
                                                           kMostScannedTriangles, candidates);
      gathered = true;
    }
    return short_list ? context.clearance.nearest_among(candidates, c, limit, hint)
                      : context.clearance.nearest(c, limit, hint);
  };
  while (!stack.empty()) {
    const auto [box, hint] = stack.back();
    stack.pop_back();
    const Eigen::Vector3d c = centre_of(box);
    const double half = half_diagonal_of(box);
    if (lower(c) > half) continue;
    // The grid first: most boxes away from the agents' space are cleared
    // by it, far more cheaply than by distances to triangles.
    if (!context.grid.any_reachable(box)) continue;
    if (hint >= 0 && context.clearance.box_within(box, hint, clearing)) continue;
    const NearestFace near = nearest(c, r + half + tol, hint);
    if (near.distance + half < clearing) continue;
    if (near.face >= 0 && near.face != hint && context.clearance.box_within(box, near.face, clearing)) continue;
    if (near.distance >= r - tol && inside(c) && context.grid.reachable_at(c)) return RegionVerdict::reached;
    if (half < smallest || --boxes_left < 0) return RegionVerdict::undecided;
    const auto [low, high] = halves_of(box);
    stack.emplace_back(high, near.face);
    stack.emplace_back(low, near.face);
  }
  return RegionVerdict::clear;
}

// no_centre_in from `start`, searched with boxes along the scene's axes
// when its bounding box along them is as tight (its half diagonal no more
// than the padding longer): a region along the scene's axes, as most of a
// level's walls and floors are, is searched as cheaply as before.
template <class Lower, class Inside>
RegionVerdict no_centre_in_box(const MovementContext& context, const OrientedBox& start, int& boxes_left, Lower&& lower,
                               Inside&& inside) {
  const Aabb bounds = start.bounds();
  if (half_diagonal_of(bounds) - start.half_diagonal() <= kProofBoxPaddingInTols * context.tol)
    return no_centre_in(context, bounds, boxes_left, lower, inside);
  return no_centre_in(context, start, boxes_left, lower, inside);
}

// A point a little less than r - E in front of or behind `piece`, over its
// centroid, its corners (drawn a tenth of the way in) or the middles of
// its sides, that may be a reachable centre: the cheap way most candidates
// that take reachable space are refused, before any halving.
bool witness_beside(const MovementContext& context, const BoundaryPiece& piece) {
  const double r = context.agent.radius;
  const double tol = context.tol;
  const double offset = r - context.agent.slop - 2.0 * tol;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : piece.corners) centroid += p;
  centroid /= static_cast<double>(piece.corners.size());
  const auto reachable = [&](const Eigen::Vector3d& base) {
    for (double side : {1.0, -1.0}) {
      const Eigen::Vector3d c = base + side * offset * piece.normal;
      if (context.grid.reachable_at(c) && context.clearance.nearest(c, r).distance >= clearing_of(context)) return true;
    }
    return false;
  };
  if (reachable(centroid)) return true;
  const size_t n = piece.corners.size();
  for (size_t i = 0; i < n; ++i)
    if (reachable(piece.corners[i] + 0.1 * (centroid - piece.corners[i])) ||
        reachable(0.5 * (piece.corners[i] + piece.corners[(i + 1) % n])))
      return true;
  return false;
}

// A point a little less than r - E from `p`, straight away from the mesh
// point nearest to it, that may be a reachable centre: where a hull's edge
// hovers over a surface, the centre resting on that surface under it.
bool witness_away_from_mesh(const MovementContext& context, const Eigen::Vector3d& p) {
  const double r = context.agent.radius;
  const double tol = context.tol;
  const NearestFace near = context.clearance.nearest(p, r);
  if (near.face < 0 || !(near.distance > 0.0)) return false;
  const Eigen::Vector3i& t = context.mesh.triangles[near.face];
  const Eigen::Vector3d foot = closest_point_on_triangle(p, context.mesh.positions[t[0]], context.mesh.positions[t[1]],
                                                         context.mesh.positions[t[2]]);
  const Eigen::Vector3d c = p + (r - context.agent.slop - 2.0 * tol) * (p - foot).normalized();
  return context.grid.reachable_at(c) && context.clearance.nearest(c, r).distance >= clearing_of(context);
}

// The column over `piece`: the points within r - E of its plane whose
// projection lies in it. A point nearest to the hull on the piece (from
// outside or, for a centre inside the hull, from within) lies in it.
struct Column {
  const BoundaryPiece& piece;
  double reach; // r - E

  // Distance from c to the column, from below.
  double distance(const Eigen::Vector3d& c) const {
    const double height = piece.normal.dot(c - piece.corners[0]);
    const Eigen::Vector3d foot = c - height * piece.normal;
    const double across = distance_to_polygon(foot, piece.corners, piece.normal);
    const double over = std::max(0.0, std::abs(height) - reach);
    return std::sqrt(across * across + over * over);
  }
};

// The halving rule of pieces and sides: with `held[h]` whether half h is
// held within the slop, the verdict of proving the others by
// `prove(h, patience_left)` (a half held resets the patience, none spends
// one), or nothing once the patience is spent: the whole is then searched.
template <typename Prove>
std::optional<RegionVerdict> prove_halves(const bool (&held)[2], int patience, Prove&& prove) {
  const bool progress = held[0] || held[1];
  if (!progress && patience <= 0) return std::nullopt;
  RegionVerdict verdict = RegionVerdict::clear;
  for (int h = 0; h < 2 && verdict != RegionVerdict::reached; ++h)
    if (!held[h]) verdict = worse(verdict, prove(h, progress ? kHalvingsWithoutProgress : patience - 1));
  return verdict;
}

// Proves no reachable centre in the column over `piece`: the piece lies
// within E of one triangle or two (within_slop.h), or its halves do
// (halved across its widest extent while wider than twice the slop,
// `depth` times at most, and while a half is held or for `patience`
// halvings without one), or the column holds no reachable centre.
// `known_unheld`: the caller found the piece not held.
RegionVerdict prove_piece(const MovementContext& context, const BoundaryPiece& piece, int depth, int& boxes_left,
                          std::vector<int>& near, bool witness_tried = false, int patience = kHalvingsWithoutProgress,
                          bool known_unheld = false) {
  const double reach = context.agent.radius - context.agent.slop;
  // A column whose box holds no reachable cell holds no centre: decided at
  // once, before any distance (and its witnesses, halves and boxes, all
  // inside that box, would find none either).
  Aabb start = bounding_box_of(piece.corners);
  for (int side : {-1, 1})
    for (const Eigen::Vector3d& p : piece.corners) start.extend(p + side * reach * piece.normal);
  if (!context.grid.any_reachable(start)) return RegionVerdict::clear;
  if (!known_unheld && held_within_slop(context, piece.corners, near)) return RegionVerdict::clear;
  if (!witness_tried && witness_beside(context, piece)) return RegionVerdict::reached;
  const double slop = context.agent.slop;
  const double tol = context.tol;
  size_t a = 0, b = 0;
  double widest = 0.0;
  for (size_t i = 0; i < piece.corners.size(); ++i)
    for (size_t j = i + 1; j < piece.corners.size(); ++j) {
      const double d = (piece.corners[i] - piece.corners[j]).squaredNorm();
      if (d > widest) {
        widest = d;
        a = i;
        b = j;
      }
    }
  if (depth > 0 && std::sqrt(widest) > 2.0 * slop) {
    const Eigen::Vector3d across = (piece.corners[b] - piece.corners[a]).normalized();
    const Plane cut{across, across.dot(0.5 * (piece.corners[a] + piece.corners[b]))};
    const BoundaryPiece halves[2] = {{clip_polygon(piece.corners, cut, 0.0), piece.normal},
                                     {clip_polygon(piece.corners, cut.flipped(), 0.0), piece.normal}};
    const bool held[2] = {halves[0].corners.size() < 3 || held_within_slop(context, halves[0].corners, near),
                          halves[1].corners.size() < 3 || held_within_slop(context, halves[1].corners, near)};
    if (const std::optional<RegionVerdict> verdict = prove_halves(held, patience, [&](int h, int patience_left) {
          return prove_piece(context, halves[h], depth - 1, boxes_left, near, false, patience_left, true);
        }))
      return *verdict;
  }
  // The column's box: along the piece's normal, its longest side and the
  // direction across both (a rectangle's box is the rectangle's).
  Eigen::Matrix3d axes = axes_about(piece.normal);
  Eigen::Vector3d longest = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < piece.corners.size(); ++i) {
    const Eigen::Vector3d side = piece.corners[(i + 1) % piece.corners.size()] - piece.corners[i];
    if (side.squaredNorm() > longest.squaredNorm()) longest = side;
  }
  const Eigen::Vector3d in_plane = longest - longest.dot(axes.col(0)) * axes.col(0);
  if (in_plane.norm() > tol) {
    axes.col(1) = in_plane.normalized();
    axes.col(2) = axes.col(0).cross(axes.col(1));
  }
  const Column column{piece, reach};
  return no_centre_in_box(
      context, box_along(axes, piece.corners, Eigen::Vector3d(1.0, 0.0, 0.0), reach, kProofBoxPaddingInTols * tol),
      boxes_left, [&](const Eigen::Vector3d& c) { return column.distance(c); },
      [&](const Eigen::Vector3d& c) { return column.distance(c) < tol; });
}

// Proves no reachable centre within r - E of segment a-b: it lies within E
// of one triangle or two, or its halves do (halved as a piece is), or the
// space around it holds no reachable centre.
RegionVerdict prove_segment(const MovementContext& context, const BoundarySegment& segment, int depth, int& boxes_left,
                            std::vector<int>& near, bool witness_tried = false, int patience = kHalvingsWithoutProgress,
                            bool known_unheld = false) {
  const double reach = context.agent.radius - context.agent.slop;
  Aabb start;
  start.extend(segment.a);
  start.extend(segment.b);
  start = grown(start, reach);
  // As for a piece: no reachable cell near the segment, no centre.
  if (!context.grid.any_reachable(start)) return RegionVerdict::clear;
  if (!known_unheld && segment_within_slop(context, segment, near)) return RegionVerdict::clear;
  const double tol = context.tol;
  const Eigen::Vector3d middle = 0.5 * (segment.a + segment.b);
  if (!witness_tried && witness_away_from_mesh(context, middle)) return RegionVerdict::reached;
  if (depth > 0 && (segment.b - segment.a).norm() > 2.0 * context.agent.slop) {
    // As for a piece: halved on while a half is held within E, or for
    // `patience` halvings without one.
    const BoundarySegment halves[2] = {{segment.a, middle}, {middle, segment.b}};
    const bool held[2] = {segment_within_slop(context, halves[0], near), segment_within_slop(context, halves[1], near)};
    if (const std::optional<RegionVerdict> verdict = prove_halves(held, patience, [&](int h, int patience_left) {
          return prove_segment(context, halves[h], depth - 1, boxes_left, near, false, patience_left, true);
        }))
      return *verdict;
  }
  const auto distance = [&](const Eigen::Vector3d& c) {
    return (closest_point_on_segment(c, segment.a, segment.b) - c).norm();
  };
  // The box along the segment: a capsule's.
  const Eigen::Vector3d along = segment.b - segment.a;
  const Eigen::Matrix3d axes = along.norm() > tol ? axes_about(along) : Eigen::Matrix3d::Identity();
  return no_centre_in_box(
      context, box_along(axes, {segment.a, segment.b}, Eigen::Vector3d::Ones(), reach, kProofBoxPaddingInTols * tol),
      boxes_left, [&](const Eigen::Vector3d& c) { return distance(c) - reach; },
      [&](const Eigen::Vector3d& c) { return distance(c) < reach + tol; });
}

double area_of(const std::vector<Eigen::Vector3d>& polygon) {
  double area = 0.0;
  for (size_t i = 1; i + 1 < polygon.size(); ++i)
    area += 0.5 * (polygon[i] - polygon[0]).cross(polygon[i + 1] - polygon[0]).norm();
  return area;
}

} // namespace

MovementVerdict check_movement_hull(const MovementContext& context, const ConvexPolytope& hull, bool flat,
                                    const std::vector<const ConvexPolytope*>& known, UncoveredBoundary& boundary) {
  const AgentShape& agent = context.agent;
  const double r = agent.radius;
  const double reach = r - agent.slop; // r - E
  const double tol = context.tol;
  boundary.clear();
  uncovered_boundary(context.clearance, hull, flat, known, tol, boundary);
  if (boundary.overflow) return MovementVerdict::undecided;
  std::vector<int> near;
  // The budget grows with the area to prove: one triangle clears a box only
  // once the box is about r wide.
  double area = 0.0;
  for (const BoundaryPiece& piece : boundary.pieces) area += area_of(piece.corners);
  int boxes_left = static_cast<int>(
      std::min<double>(kMostProofBoxesOfAHull, kMostProofBoxes + kProofBoxesPerSquareRadius * area / (r * r)));
  // The cheap witnesses of every piece and segment first: most candidates
  // a merge tries take space some agent reaches, and one witness refuses
  // them before any piece is proven by halving. The verdict is the one the
  // proofs below would give: a piece or segment with a witness is not
  // within the slop of one triangle (the witness would then be nearer than
  // r - tol to it), so its own proof would stop at the same witness.
  for (const BoundaryPiece& piece : boundary.pieces)
    if (witness_beside(context, piece)) return MovementVerdict::centre_near_boundary;
  for (const BoundarySegment& segment : boundary.segments)
    if (witness_away_from_mesh(context, 0.5 * (segment.a + segment.b))) return MovementVerdict::centre_near_boundary;
  bool undecided = false;
  for (const BoundaryPiece& piece : boundary.pieces) {
    const RegionVerdict verdict = prove_piece(context, piece, kMostPieceHalvings, boxes_left, near, true);
    if (verdict == RegionVerdict::reached) return MovementVerdict::centre_near_boundary;
    undecided |= verdict == RegionVerdict::undecided;
  }
  for (const BoundarySegment& segment : boundary.segments) {
    const RegionVerdict verdict = prove_segment(context, segment, kMostPieceHalvings, boxes_left, near, true);
    if (verdict == RegionVerdict::reached) return MovementVerdict::centre_near_boundary;
    undecided |= verdict == RegionVerdict::undecided;
  }
  // A centre deeper than r - E inside the hull; none can be when the hull
  // is thinner than 2 (r - E) (its inradius is less than r - E).
  if (!flat && thinnest_width(hull) >= 2.0 * (reach - tol)) {
    Aabb start = bounding_box_of(hull.vertices);
    start.min.array() += reach - tol;
    start.max.array() -= reach - tol;
    if (!start.empty()) {
      const RegionVerdict verdict = no_centre_in(
          context, start, boxes_left,
          [&](const Eigen::Vector3d& c) { return deepest_signed_distance(hull.planes, c) + reach - tol; },
          [&](const Eigen::Vector3d& c) {
        // Inside H, or within tol of H shrunk (which lies inside H unless r - E < 3 tol).
        const double depth = deepest_signed_distance(hull.planes, c);
        return depth < -tol || depth + reach - tol < tol;
          });
      if (verdict == RegionVerdict::reached) return MovementVerdict::centre_inside;
      undecided |= verdict == RegionVerdict::undecided;
    }
  }
  return undecided ? MovementVerdict::undecided : MovementVerdict::valid;
}

} // namespace hullcover::detail
