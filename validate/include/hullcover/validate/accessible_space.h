#pragma once
/// \file accessible_space.h
/// The accessible-space probe: the strict definition (docs/definitions-and-proofs.md) of
/// free space ("Accuracy: what no free space lost means"), decided exactly
/// along rays.
///
/// - front space: rays from points of every face (however small: its
///   centroid, a point near each corner, and more in proportion to its
///   area) along its normal;
/// - openings: rays from points along every open edge (boundary edge, or
///   the rim of a double-sided sheet), outward in the face's plane and
///   tilted by kOpeningTiltSine to either side of it.
/// Each ray runs from its origin on the surface, with no distance cap, to its
/// first mesh hit past kRayStandOffInTolerances x tol (nearer faces, within
/// rounding of the surface it leaves, are not met), or, when it meets
/// nothing, out of the box of the scene and every hull (beyond which no hull
/// lies). A ray whose first hit is the BACK of every face met there
/// is *enclosed* (the floor under a one-sided table top): allowed, counted.
/// Every other ray is open: its segment is clipped exactly against every
/// hull whose box it meets (Cyrus-Beck on the hull's planes moved inward by
/// tol), and any stretch left is lost space, with its length and its
/// deepest point. A flat hull has no inside and loses nothing.
///
/// OctoMap: the cell of each lost ray's deepest point goes into an octree
/// (its origin the scene's box centre) that can be written for a viewer;
/// its cell count is a picture of where the lost rays are, not a separate
/// verdict.

#include "hullcover/validate/allowance_audit.h"

#include "hullcover/bvh/hull_world.h"
#include "hullcover/bvh/triangle_world.h"
#include "hullcover/mesh/prepared_mesh.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace hullcover::validate {

/// Default ray spacing as a fraction of the bounding-box diagonal of each
/// face's island (mesh_islands.h; a map inside a world is audited as finely
/// as alone): about one front ray per spacing^2 of face area and one
/// opening point per spacing of open edge (plus a few per face and edge
/// however small). The octree's cells are this fraction of the scene's.
inline constexpr double kDefaultProbeSpacingRelative = 0.0025;

/// How finely the probe looks; the default is relative to the scene.
struct ProbeOptions {
  /// Optional cap on every ray's length, scene units (> 0). Default none:
  /// the strict definition has no cap; a user may trade exactness for an
  /// agent's reach.
  std::optional<double> probe_distance;
  /// Ray spacing on faces and open edges, and the octree's cell size,
  /// scene units (> 0); default kDefaultProbeSpacingRelative x each
  /// island's diagonal for the rays, x the scene's for the octree.
  std::optional<double> resolution;
  std::string octree_path; ///< write the lost cells' octree here (.bt) when not empty
  /// What the covering was allowed to take (allowance_audit.h); none: exact mode.
  AllowanceOptions allowance;
  /// Called now and then with the fraction of the rays' faces and edges
  /// done (0..1, never decreasing), front rays first, then openings, from
  /// one thread at a time; may be empty.
  std::function<void(double)> progress;
};

/// One place where free space is lost: a ray's deepest point inside a hull.
struct LostPlace {
  Eigen::Vector3d point = Eigen::Vector3d::Zero(); ///< the deepest point, scene coordinates
  int face = -1;                                   ///< the face the ray left (an open edge's face)
  int hull = -1;                                   ///< the hull it is inside; -1 for no place
  double depth = 0.0;                              ///< depth inside the hull, scene units (> tol)
  bool opening = false;                            ///< found by an opening ray
};

/// What one kind of ray (front or opening) found.
struct RayTally {
  long rays = 0;            ///< rays traced
  long enclosed = 0;        ///< rays whose first hit is the back of a face: allowed
  long lost = 0;            ///< open rays with a stretch deeper than tol inside some hull
  double lost_length = 0.0; ///< total length of those stretches (overlapping hulls counted once), scene units
  LostPlace deepest;        ///< the deepest lost point of this kind (hull -1 when none)
};

/// What the probe found.
struct ProbeReport {
  std::optional<double> probe_distance;                    ///< the cap used, scene units; none by default
  double resolution = 0.0;                                 ///< octree cell size used, scene units
  double finest_spacing = 0.0;                             ///< the finest ray spacing used (an island's), scene units
  double coarsest_spacing = 0.0;                           ///< the coarsest, scene units
  RayTally front;                                          ///< rays in front of faces
  RayTally opening;                                        ///< rays beyond open edges
  long lost_cells = 0;                                     ///< octree cells holding a lost ray's deepest point
  double max_lost_depth = 0.0;                             ///< the deepest lost point's depth, either kind, scene units
  Eigen::Vector3d octree_origin = Eigen::Vector3d::Zero(); ///< scene point at the octree's origin (the box centre)
  std::vector<LostPlace> worst; ///< the deepest lost point per hull, deepest first, at most kWorstPlaces
  AllowanceReport allowance;    ///< the allowance's figures (allowance_audit.h), when a knob is set

  /// Lost rays, front and openings together.
  long lost_rays() const { return front.lost + opening.lost; }
};
/// How many hulls' deepest lost places a report keeps.
inline constexpr size_t kWorstPlaces = 10;

/// Probes `prepared`'s free space (ray casts on `triangles`) and decides it
/// against the hulls of `hulls`. Fails with `invalid_argument` for a
/// non-positive or infinite probe distance or resolution, or a resolution
/// so fine the octree would need more than its 16 levels over the scene,
/// or an agent radius not above 2 tol or a max deviation not positive;
/// `unwritable_file` when the octree cannot be written; `internal_error`
/// when anything else goes wrong; `invalid_argument` for a negative thread
/// count. Faces' front rays, then edges' opening rays, are traced on
/// `threads` threads (0: every core), each face's or edge's findings added
/// to the report in face and edge order on the calling thread (which alone
/// calls options.progress, its fraction never decreasing): the report, to
/// the last bit, is the same for any thread count.
Result<ProbeReport> probe_accessible_space(const PreparedMesh& prepared, const bvh::TriangleWorld& triangles,
                                           const bvh::HullWorld& hulls, const ProbeOptions& options, int threads = 1);

} // namespace hullcover::validate
