#pragma once
// Whether a point lies in enclosed space under the strict definition
// (docs/definitions-and-proofs.md, "Free space: the strict definition"): on no face's open front ray. Hulls may
// fill such space; the allowance audit's balls and the behaviour proxies may
// reach into it without taking free space.

#include "hullcover/bvh/triangle_world.h"
#include "hullcover/geometry/aabb_tree.h"
#include "hullcover/geometry/convex_polytope.h"
#include "hullcover/mesh/prepared_mesh.h"

#include <Eigen/Core>

#include <vector>

namespace hullcover::validate::probe {

/// The mesh's front columns, one per face with a surface, and the ray casts
/// that settle a point on them. Const once built: one judge serves many
/// threads.
class EnclosedSpace {
public:
  /// `prepared` and `triangles` (the same mesh's faces) must outlive it.
  EnclosedSpace(const PreparedMesh& prepared, const bvh::TriangleWorld& triangles);

  /// True when no face's front ray through `p` is open: every face whose
  /// front column holds p (grown by `tol`, scene units, sideways) has its
  /// ray through p, or its nearest genuine ray within tol of p, end on a
  /// back, or not reach p from that face at all. Opening rays, from edges,
  /// make surfaces rather than volumes and are left to the probe's rays.
  /// Inside the mesh's bounding box, only the columns whose boxes (each
  /// cut where it leaves that box) come within tol of p are tried; outside
  /// it, every column (columns have no end, as the definition's rays).
  bool holds(const Eigen::Vector3d& p, double tol) const;

private:
  bool on_open_ray(const Eigen::Vector3d& p, const Eigen::Vector3d& m, double tol) const;
  /// Whether the face of `prism` puts p (within tol of its column) on an
  /// open ray; `tried` holds the normals whose ray through p was cast.
  bool open_through(const Eigen::Vector3d& p, int prism, double tol, std::vector<int>& tried) const;

  const PreparedMesh& prepared_;
  const bvh::TriangleWorld& triangles_;
  std::vector<Eigen::Vector3d> normals_; // every distinct unit face normal
  /// A face's front column: in front of `front`, behind its `sides`
  /// (polygon_side_planes); `normal` indexes normals_, `face` the mesh.
  struct FrontPrism {
    Plane front;
    std::vector<Plane> sides;
    int normal = 0;
    int face = -1;
  };
  std::vector<FrontPrism> prisms_;
  /// The mesh's bounding box: where the column boxes below end.
  Aabb bounds_;
  /// Over each prism's column within bounds_: a face's triangle swept along
  /// its normal until its box leaves bounds_ (sideways growth by tol is
  /// left to the query's box, so one tree serves every tol).
  AabbTree columns_;
};

} // namespace hullcover::validate::probe
