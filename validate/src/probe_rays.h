#pragma once
// Where the accessible-space probe's rays start and which way they go
// (docs/definitions-and-proofs.md, "Free space: the strict definition"): along the normal from points of every
// face, however small, and beyond every open edge, in the face's plane and
// tilted to either side of it.

#include "hullcover/bvh/triangle_world.h"
#include "hullcover/mesh/prepared_mesh.h"

#include <Eigen/Core>

#include <functional>

namespace hullcover::validate::probe {

/// One probe ray, before its stand-off from the surface.
struct ProbeRay {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();     ///< on the face or the open edge, scene units
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ(); ///< unit
  int face = -1;                                        ///< the face it leaves (an open edge's face)
  bool opening = false;                                 ///< beyond an open edge rather than in front of a face
};

/// The front rays of mesh face `face` (none when it has no surface): its
/// centroid and a point near each corner, plus a triangular grid of about
/// area / spacing^2 points (spacing in scene units, > 0), all along the
/// face's unit normal. Every face's rays, face by face, are the probe's front
/// rays; faces are independent of one another.
void front_rays_of_face(const PreparedMesh& prepared, double spacing, int face,
                        const std::function<void(const ProbeRay&)>& trace);

/// The opening rays of `prepared.connectivity.edges[edge]` (none unless it
/// is open: a boundary edge, or the rim of a double-sided sheet, two faces
/// back to back): from points along it, one near each end and one per
/// `spacing` between, outward in the face's plane and tilted by
/// kOpeningTiltSine to either side. Every edge's, edge by edge, are the
/// probe's opening rays.
void opening_rays_of_edge(const PreparedMesh& prepared, double spacing, int edge,
                          const std::function<void(const ProbeRay&)>& trace);

/// Whether a ray from `start` along unit `dir` whose first mesh hit lies
/// `first_hit` along it is enclosed (docs/definitions-and-proofs.md): every face at that hit,
/// coincident ones within `tol` of it included, is met from behind. One
/// met from the front there (a ceiling coincident with the floor above)
/// ends the ray on a front, which is open space.
bool ends_on_backs(const bvh::TriangleWorld& triangles, const Mesh& mesh, const Eigen::Vector3d& start,
                   const Eigen::Vector3d& dir, double first_hit, double tol);

} // namespace hullcover::validate::probe
