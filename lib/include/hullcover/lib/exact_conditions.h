#pragma once
/// \file exact_conditions.h
/// The conditions hullcover adds to the paper's four (section 4.1) in
/// `ValidityMode::exact`. The paper's conditions look only at mesh elements
/// strictly inside a hull and guard an opening with one bar at its edge's
/// midpoint; on real maps that loses free space (../shared/DESIGN.md, "Where
/// the paper's four conditions are not enough", causes 1-3). Each condition
/// below closes one cause. Free space is what DESIGN.md's probe samples:
/// the space swept from every face along its normal, and from every open
/// edge outward in its face's plane, up to the free-space reach.
///
///  E1 front space: no face's front space enters the hull's interior,
///     except through the hull's own faces met from the front (there the
///     face's space ends, as a valley's does at its far slope), or where it
///     leaves the hull only through the hull's own faces met from behind (it
///     is enclosed space, which DESIGN.md allows: a floor under a table top).
///     Catches back-to-back coincident faces, double-sided sheets, a floor
///     under a prism's beveled side, a hull reaching over free space.
///  E2 openings: the same for the opening beyond every open edge, boundary
///     or fold (the rim of a double-sided sheet), along the whole edge, with
///     no allowance for enclosed space; for flat polygons the bar becomes a
///     sheet along the whole edge.
///  E3 crossing faces: where a face's interior crosses the hull's interior
///     (self-intersecting input, where vertices and edges stay outside), its
///     front space there must leave the hull only through the hull's own
///     faces (enclosed, as E1 allows: a floor running into a pillar).
///
/// All use the one tolerance: "interior" is the hull shrunk by `tol`.

#include "hullcover/lib/convex_polytope.h"
#include "hullcover/lib/planar_hull.h"
#include "hullcover/lib/scene_index.h"

namespace hullcover {

/// A piece of free space: a face's triangle, or an open edge, swept along
/// unit `direction` from t = 0 to the reach. It is the inner side of
/// `planes`, each shrunk by its `insets` entry (negative: grown).
struct FreeSpaceSweep {
  std::vector<Plane> planes;
  std::vector<double> insets;
  Plane start;  ///< the base's plane facing back: signed distance = -t
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
  std::vector<Eigen::Vector3d> base;     ///< the face or edge swept
  std::vector<Eigen::Vector3d> corners;  ///< the base at t = 0 and at the reach
  double reach = 0.0;             ///< scene units, from the base (the free-space reach plus the rays' stand-off)
  bool enclosed_allowed = false;  ///< front space may be enclosed (first meet a face from behind)
};

/// The front space of triangle `corners` (unit front `normal`); it starts
/// `tol` behind the face, so faces coincident with it are met.
FreeSpaceSweep front_space_sweep(const std::vector<Eigen::Vector3d>& corners, const Eigen::Vector3d& normal,
                                 double reach, double tol);
/// The opening beyond the edge p0-p1 of a face with unit normal
/// `face_normal`, whose far corner is `inner` (the sweep runs away from it).
FreeSpaceSweep opening_sweep(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& inner,
                             const Eigen::Vector3d& face_normal, double reach, double tol);

/// A solid hull's interior: the hull shrunk by tol (what "strictly inside"
/// means), as planes and facet polygons. Empty for a hull thinner than 2 tol.
struct HullInterior {
  std::vector<Plane> planes;                         ///< the hull's planes moved in by tol
  std::vector<std::vector<Eigen::Vector3d>> facets;  ///< per plane, its facet (empty when gone)
  bool empty() const {
    for (const auto& f : facets)
      if (!f.empty()) return false;
    return true;
  }
};

/// The interior of `hull` (facets and planes in the same order).
HullInterior hull_interior(const ConvexPolytope& hull, double tol);

/// Rays of the free space start this many tolerances off the surface they
/// leave, as the audit's probe rays do.
inline constexpr double kRayStandOffInTolerances = 2.0;

/// E1/E2: true when free space of `sweep` lies inside `interior` (a solid
/// hull shrunk by tol). Each region of an interior facet through which the
/// sweep enters (and, for front space, each facet it leaves through) is
/// judged by a grid of witness rays, as the audit's probe judges its rays:
/// a ray from the base loses space when it is inside before its first mesh
/// hit and within the reach; a ray whose first hit is the back of a face
/// runs through enclosed space, which front space may. Exact up to that
/// sampling: rays between the witnesses are not traced.
bool sweep_enters_hull(const SceneIndex& index, const FreeSpaceSweep& sweep, const HullInterior& interior,
                       std::vector<int>& scratch);

/// E2 (and the paper's condition 3) for a flat polygon: true when the bar or
/// sheet crosses the polygon's relative interior shrunk by `tol`. One lying
/// in the polygon's plane does not cross it: it guards an open edge resting
/// on the polygon (a wall's culled bottom edge on a floor), whose opening the
/// polygon itself closes.
bool bar_crosses_polygon(const FlatPolygon& polygon, const BoundaryBar& bar, double tol);

/// E2 for a solid hull and the bar swept along the edge: true when some
/// point of the quad `sheet` (four corners in order) lies deeper than `tol`
/// behind every plane.
bool sheet_enters_interior(const std::vector<Plane>& planes, const std::vector<Eigen::Vector3d>& sheet, double tol);

/// E3: true when part of the front sweep's base (a face) lies deeper than
/// `tol` inside the solid hull and its front space from there, judged like
/// `sweep_enters_hull`'s, is lost.
bool crossing_face_leaks(const SceneIndex& index, const FreeSpaceSweep& sweep, const HullInterior& interior,
                         std::vector<int>& scratch);

} // namespace hullcover
