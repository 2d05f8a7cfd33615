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
///  E3 `face_crosses_hull`: no face's interior crosses the hull's interior
///     (self-intersecting input, where vertices and edges stay outside).
///
/// All use the one tolerance: "interior" is the hull shrunk by `tol`.

#include "hullcover/lib/convex_polytope.h"
#include "hullcover/lib/planar_hull.h"
#include "hullcover/lib/scene_index.h"

#include <functional>

namespace hullcover {

/// A piece of free space: a face's triangle, or an open edge, swept along
/// unit `direction` from t = 0 to the reach. It is the inner side of
/// `planes`, each shrunk by its `insets` entry (negative: grown).
struct FreeSpaceSweep {
  std::vector<Plane> planes;
  std::vector<double> insets;
  Plane start;  ///< the base's plane facing back: signed distance = -t
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
  std::vector<Eigen::Vector3d> corners;  ///< the base at t = 0 and at the reach
  bool enclosed_allowed = false;  ///< front space may run into a hull that only faces of it close
};

/// The front space of triangle `corners` (unit front `normal`); it starts
/// `tol` behind the face, so faces coincident with it are met.
FreeSpaceSweep front_space_sweep(const std::vector<Eigen::Vector3d>& corners, const Eigen::Vector3d& normal,
                                 double reach, double tol);
/// The opening beyond the edge p0-p1 of a face with unit normal
/// `face_normal`, whose far corner is `inner` (the sweep runs away from it).
FreeSpaceSweep opening_sweep(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& inner,
                             const Eigen::Vector3d& face_normal, double reach, double tol);

/// Tells whether a mesh face ends the free space along the segment from
/// `from` (on the sweep's base) to `to` before it: see `mesh_blocks_segment`.
using SegmentBlocked = std::function<bool(const Eigen::Vector3d& from, const Eigen::Vector3d& to)>;

/// E1/E2: true when `sweep` enters the solid hull `hull` deeper than `tol`
/// through a facet other than one carrying the patch's faces (a plane of
/// `face_planes`) met from the front beyond tol of the sweep's base; with
/// `enclosed_allowed`, only when it also leaves through a facet carrying no
/// face. The ray through the middle of each such region is the witness; it
/// does not count when `blocked` says a mesh face stands in its way.
bool sweep_enters_hull(const FreeSpaceSweep& sweep, const ConvexPolytope& hull, const std::vector<Plane>& face_planes,
                       double tol, const SegmentBlocked& blocked);

/// True when a face of the mesh passes through segment from-to: from
/// farther than tol on one side of its plane to within tol of it or beyond,
/// within tol of the triangle. The faces the segment starts on never do.
bool mesh_blocks_segment(const SceneIndex& index, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
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

/// E3: true when part of triangle `corners` lies deeper than `tol` inside
/// the hull bounded by `planes`.
bool triangle_enters_interior(const std::vector<Plane>& planes, const std::vector<Eigen::Vector3d>& corners,
                              double tol);

} // namespace hullcover
