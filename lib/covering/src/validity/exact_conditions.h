#pragma once
/// \file exact_conditions.h
/// The conditions hullcover adds to the paper's four (section 4.1) in
/// `ValidityMode::exact`. The paper's conditions look only at mesh elements
/// strictly inside a hull and guard an opening with one bar at its edge's
/// midpoint; on real maps that loses free space (docs/definitions-and-proofs.md, "Exact mode:
/// no free space lost"). Each condition
/// below closes one cause. Free space is what the audit's probe samples:
/// the space swept from every face along its normal, and from every open
/// edge outward in its face's plane, up to each ray's first mesh hit, with
/// no distance cap (the free-space reach is a cap only when a user sets one).
/// A ray whose first hit is the back of every face met there runs through
/// enclosed space, which hulls may fill; a ray that escapes or ends on the
/// front of a face is open.
///
///  E1 front space: no face's front space enters the hull's interior,
///     except through the hull's own faces met from the front (there the
///     face's space ends, as a valley's does at its far slope), or where it
///     leaves the hull only through the hull's own faces met from behind (it
///     is enclosed space, which the strict definition allows: a floor under a table top).
///     Catches back-to-back coincident faces, double-sided sheets, a floor
///     under a prism's beveled side, a hull reaching over free space.
///  E2 openings: the same for the opening beyond every open edge, boundary
///     or fold (the rim of a double-sided sheet), along the whole edge, with
///     the same allowance for enclosed space (docs/definitions-and-proofs.md: a doorway stays open
///     because its rays end on the next room's walls from the front); for
///     flat polygons the bar becomes a sheet along the whole edge.
///  E3 crossing faces: where a face's interior crosses the hull's interior
///     (self-intersecting input, where vertices and edges stay outside), its
///     front space there must leave the hull only through the hull's own
///     faces (enclosed, as E1 allows: a floor running into a pillar).
///
/// All use the one tolerance: "interior" is the hull shrunk by `tol`.

#include "validity/free_space_sweep.h"
#include "hullcover/geometry/planar_hull.h"
#include "validity/scene_index.h"
#include "validity/witness_rays.h"

namespace hullcover {

/// E1/E2: true when free space of `sweep` lies inside `interior` (a solid
/// hull shrunk by tol). Each region of an interior facet through which the
/// sweep enters, split by the facet it leaves through, is decided by
/// region_loses_space (witness_rays.h), as the audit decides its rays: a
/// ray from the base loses space when it is inside before its first mesh
/// hit; a ray whose first hit is the back of a face runs through enclosed
/// space, which hulls may fill. Exact, and conservative where the work
/// bound runs out. `storage` is reused storage.
bool sweep_enters_hull(const SceneIndex& index, const FreeSpaceSweep& sweep, const HullInterior& interior,
                       detail::SweepJudgeStorage& storage);

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
/// `sweep_enters_hull`'s, is lost. `storage` is reused storage.
bool crossing_face_leaks(const SceneIndex& index, const FreeSpaceSweep& sweep, const HullInterior& interior,
                         detail::SweepJudgeStorage& storage);

} // namespace hullcover
