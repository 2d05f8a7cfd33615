#pragma once
/// \file accessible_space.h
/// The accessible-space probe (../shared/DESIGN.md, "what no free space lost
/// means"): free space is sampled from the scene itself, then every sample
/// is tested against the hulls.
///
/// - front free space: rays from sample points on every face along its
///   normal, up to the probe distance R or the first mesh hit.
/// - openings: rays from points along every boundary edge, outward in the
///   face's plane, up to R or the first hit (a doorway stays open).
/// A front ray whose first hit is the BACK of every face met there is
/// *enclosed* space (a floor under a table top): counted apart, allowed. One
/// face met from the front at that hit (a ceiling coincident with the floor
/// above) makes the ray open, as DESIGN.md's strict definition says.
/// Not yet the strict definition in full: R caps the rays, points along
/// them are sampled, and opening rays are never enclosed.
/// The accessible (not enclosed) points go into an OctoMap octree as free
/// cells, the surface as occupied; every free cell is tested too, which
/// gives the lost volume: a cell counts as lost when a free sample in it
/// is, or when the whole cell lies inside a hull.
///
/// "Lost" means strictly inside a hull: deeper than the tolerance.

#include "hullcover/bvh/hull_world.h"
#include "hullcover/bvh/triangle_world.h"
#include "hullcover/covering/covering.h"
#include "hullcover/mesh/prepared_mesh.h"

#include <optional>
#include <string>
#include <vector>

namespace hullcover::validate {

/// Default probe distance as a fraction of the bounding-box diagonal: the
/// decomposer's default free-space reach, so it probes what exact mode keeps.
inline constexpr double kDefaultProbeRelative = kDefaultFreeSpaceReachRelative;
/// Default octree resolution (and sample spacing) per probe distance.
inline constexpr double kDefaultCellsPerProbe = 8.0;

/// How far and how finely the probe looks; every default is relative to the scene.
struct ProbeOptions {
  std::optional<double> probe_distance;  ///< R, scene units (> 0)
  std::optional<double> resolution;      ///< octree cell size and sample spacing, scene units (> 0)
  std::string octree_path;  ///< write the octree here (.bt) when not empty; its origin is the scene's box centre
};

/// One place where free space is lost.
struct LostPlace {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< the lost sample, scene coordinates
  int face = -1;  ///< the face (or open edge's face) the probing ray came from
  int hull = -1;  ///< the hull it is inside
  double depth = 0.0;    ///< how deep inside the hull
  bool opening = false;  ///< found by an opening ray
};

/// What the probe found. Points are free samples; "lost" ones lie deeper
/// than the tolerance inside a hull.
struct ProbeReport {
  double probe_distance = 0.0;  ///< R used, scene units
  double resolution = 0.0;      ///< octree cell and sample spacing used, scene units
  long front_points = 0, front_lost = 0;  ///< samples in front of faces (accessible), and the lost ones
  long enclosed_points = 0, enclosed_in_hulls = 0;  ///< allowed, reported
  long opening_points = 0, opening_lost = 0;  ///< samples beyond open edges, and the lost ones
  long free_cells = 0, lost_cells = 0;  ///< lost: holds a lost free sample, or lies wholly inside a hull
  long straddling_cells = 0;  ///< free cells whose centre alone is inside a hull (a hull's surface crosses them)
  double free_volume = 0.0, lost_volume = 0.0;  ///< scene units cubed
  double max_lost_depth = 0.0;  ///< the deepest lost sample's depth
  Eigen::Vector3d octree_origin = Eigen::Vector3d::Zero();  ///< scene point at the octree's origin (the box centre)
  std::vector<LostPlace> worst;  ///< deepest first, at most kWorstPlaces
};
/// How many of the deepest lost places a report keeps.
inline constexpr size_t kWorstPlaces = 10;

/// Probes `prepared`'s free space (ray casts on `triangles`) and tests it
/// against `hulls`. Fails with `invalid_argument` for a non-positive probe
/// distance or resolution, or a resolution so fine the octree would need
/// more than its 16 levels over the scene; `unwritable_file` when the
/// octree cannot be written.
Result<ProbeReport> probe_accessible_space(const PreparedMesh& prepared, const bvh::TriangleWorld& triangles,
                                           const bvh::HullWorld& hulls, const ProbeOptions& options);

} // namespace hullcover::validate
