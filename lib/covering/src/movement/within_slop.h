#pragma once
/// \file within_slop.h
/// The cheap certificate of a movement hull's proof (movement_validity.h): a
/// part of the uncovered boundary every point of which lies within E - tol
/// of a triangle is at least r - E from every reachable centre (a centre
/// nearer would be nearer than r to that triangle). Decided by one
/// triangle (the distance to it is convex: the corners decide), or, over
/// a crease, by two on either side of a plane between them.

#include "movement/movement_context.h"
#include "movement/uncovered_boundary.h"

#include <Eigen/Core>

#include <vector>

namespace hullcover::detail {

/// Whether every point of convex polygon `corners` lies within E - tol of
/// one triangle, or each of the two parts a plane between two triangles
/// cuts it into lies so within one of them (a piece over a crease).
/// `near` is scratch.
bool held_within_slop(const MovementContext& context, const std::vector<Eigen::Vector3d>& corners,
                      std::vector<int>& near);

/// The same for a segment (a side of the uncovered boundary).
bool segment_within_slop(const MovementContext& context, const BoundarySegment& segment, std::vector<int>& near);

} // namespace hullcover::detail
