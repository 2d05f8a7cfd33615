#include "movement/within_slop.h"

#include "hullcover/geometry/tolerances.h"

#include <Eigen/Geometry>

#include <optional>

namespace hullcover::detail {
namespace {

// Whether every one of `points` lies within E - tol of one triangle near
// them: the distance to a triangle is convex, so its largest value on
// their convex hull is at one of them.
bool within_slop_of_one_face(const MovementContext& context, const std::vector<Eigen::Vector3d>& points,
                             std::vector<int>& near) {
  const double reach = context.agent.slop - context.tol;
  near.clear();
  context.clearance.faces_meeting(grown(bounding_box_of(points), reach), near);
  for (int face : near) {
    bool within = true;
    for (const Eigen::Vector3d& p : points)
      if (!(within = context.clearance.to_face(p, face) <= reach)) break;
    if (within) return true;
  }
  return false;
}

// Where the uncovered boundary passes over a crease (a hull facet across
// two triangles that meet at an angle), no triangle lies within E of all
// of a piece, though each of its points lies within E of one of the two:
// a plane between the corners nearest to one and those nearest to the
// other parts it into two that one triangle each holds within E, where
// halving would go on until each part is narrower than the slop. The
// plane through the triangles' planes' meeting line that bisects them;
// none when the points' nearest triangles within E - tol (of `near`) are
// not exactly two, or no such plane separates them.
std::optional<Plane> cut_between_nearest_pair(const MovementContext& context,
                                              const std::vector<Eigen::Vector3d>& points,
                                              const std::vector<int>& near) {
  const double reach = context.agent.slop - context.tol;
  int faces[2] = {-1, -1};
  std::vector<int> side(points.size(), 0);
  for (size_t i = 0; i < points.size(); ++i) {
    int nearest = -1;
    double best = reach;
    for (int face : near) {
      const double d = context.clearance.to_face(points[i], face);
      if (d <= best) {
        best = d;
        nearest = face;
      }
    }
    if (nearest < 0) return std::nullopt;
    if (faces[0] < 0 || faces[0] == nearest)
      faces[0] = nearest;
    else if (faces[1] < 0 || faces[1] == nearest)
      faces[1] = nearest, side[i] = 1;
    else
      return std::nullopt;
  }
  if (faces[1] < 0) return std::nullopt;
  Plane planes[2];
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector3i& t = context.mesh.triangles[faces[k]];
    const Eigen::Vector3d& a = context.mesh.positions[t[0]];
    const Eigen::Vector3d n = (context.mesh.positions[t[1]] - a).cross(context.mesh.positions[t[2]] - a);
    if (!(n.norm() > 0.0)) return std::nullopt;
    planes[k] = {n.normalized(), n.normalized().dot(a)};
  }
  for (double sign : {1.0, -1.0}) {
    const Eigen::Vector3d normal = planes[0].normal - sign * planes[1].normal;
    const double length = normal.norm();
    if (!(length > kTouchingFraction)) continue;
    const Plane cut{normal / length, (planes[0].offset - sign * planes[1].offset) / length};
    bool separates = true;
    for (size_t i = 0; i < points.size() && separates; ++i)
      separates = side[i] == 0 ? cut.signed_distance(points[i]) <= 0.0 : cut.signed_distance(points[i]) >= 0.0;
    if (separates) return cut;
  }
  return std::nullopt;
}

} // namespace

bool held_within_slop(const MovementContext& context, const std::vector<Eigen::Vector3d>& corners,
                      std::vector<int>& near) {
  if (within_slop_of_one_face(context, corners, near)) return true;
  const std::optional<Plane> cut = cut_between_nearest_pair(context, corners, near);
  if (!cut) return false;
  for (const Plane& side : {*cut, cut->flipped()}) {
    const std::vector<Eigen::Vector3d> part = clip_polygon(corners, side, 0.0);
    if (part.size() >= 3 && !within_slop_of_one_face(context, part, near)) return false;
  }
  return true;
}

bool segment_within_slop(const MovementContext& context, const BoundarySegment& segment, std::vector<int>& near) {
  if (within_slop_of_one_face(context, {segment.a, segment.b}, near)) return true;
  const std::optional<Plane> cut = cut_between_nearest_pair(context, {segment.a, segment.b}, near);
  if (!cut) return false;
  const double at_a = cut->signed_distance(segment.a), at_b = cut->signed_distance(segment.b);
  if (!(at_a != at_b)) return false;
  const Eigen::Vector3d across = segment.a + (segment.b - segment.a) * (at_a / (at_a - at_b));
  return within_slop_of_one_face(context, {segment.a, across}, near) &&
         within_slop_of_one_face(context, {across, segment.b}, near);
}

} // namespace hullcover::detail
