#pragma once
/// \file cooking_margin.h
/// Hulls an engine's own hull builder rebuilds as they are.
///
/// Engines cook a convex collider by running their own hull builder on its
/// points, in float. Jolt's, like Quickhull generally, drops a point that
/// lies within its hull tolerance of the planes of the hull built so far
/// (1 mm by default), then refuses the result when an input point ends
/// farther outside the built hull than 4 tolerances ("Hull building failed,
/// point ... had an error"). A corner at the tip of a knife-thin wedge is
/// the case that fails: laterally it stands millimetres out of the hull of
/// the other corners, but within a hundredth of a millimetre of both faces'
/// planes, so the builder cannot see it.
///
/// The rule an export keeps (docs/exports.md), for an engine whose hull
/// tolerance is t. A corner's **margin** is how far it stands in front of
/// the farthest facet plane of the hull of the other corners; its
/// **reach** is its distance from that hull, what the surface loses if the
/// builder drops it. A corner is at risk when its margin is under 2t (a
/// builder drops within t) while its reach is over 4t (the error Jolt's
/// builder refuses); for an apex over a flat base of the other corners,
/// its height is its margin and its distance from the base its reach. A
/// corner that reaches less (a slight bend in a wide
/// face) is left alone: dropping it moves the surface by less than the
/// engine's own check allows. An at-risk corner is replaced by the six
/// corners of an axis-aligned octahedron of half-diagonal 2t about it: the
/// hull still holds the corner, each new corner stands 2t clear of the
/// other five, and no point moves farther than 2t out. Up to 4 rounds
/// take corners a round's octahedra leave at risk.

#include "hullcover/geometry/convex_polytope.h"

#include <string>
#include <vector>

namespace hullcover::app {

/// What the repair did to a set of hulls.
struct CookingRepair {
  std::vector<ConvexPolytope> hulls; ///< one per input hull, same order
  int repaired = 0;                  ///< hulls given octahedra
  double margin = 0.0;               ///< the octahedra's half-diagonal, 2t (scene units): the most any point moved out
  int corners_replaced = 0;          ///< corners replaced, over all rounds
  /// One sentence per hull that still has a corner at risk after the last
  /// round, naming the hull, the corner's margin and its reach.
  std::vector<std::string> failures;
};

/// The margin of corner `v` of `hull`: the largest signed distance from it
/// to a facet plane of the hull of the other corners (when those are flat,
/// its height above their plane). Scene units. `reach` is set to its
/// distance from the hull of the others (their polygon when they are flat;
/// 0 when the corner is not outside them).
double corner_margin(const ConvexPolytope& hull, int v, double& reach);

/// Leaves no hull of `hulls` a corner at risk for an engine of hull
/// tolerance `hull_tolerance` (scene units, > 0), as described above;
/// hulls with none are kept as they are.
CookingRepair repair_cooking_margins(const std::vector<ConvexPolytope>& hulls, double hull_tolerance);

} // namespace hullcover::app
