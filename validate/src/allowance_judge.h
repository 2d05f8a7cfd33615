#pragma once
// The allowance audit's work on one probe ray (allowance_audit.h): the
// farthest lost point from the mesh, and the reachable balls reaching into a
// hull, both decided over every point of the ray by Lipschitz bisection.

#include "hullcover/validate/allowance_audit.h"

#include "enclosed_space.h"
#include "probe_rays.h"

#include "hullcover/bvh/hull_world.h"
#include "hullcover/bvh/triangle_world.h"
#include "hullcover/geometry/aabb_tree.h"
#include "hullcover/mesh/prepared_mesh.h"

#include <memory>
#include <utility>
#include <vector>

namespace hullcover::validate::probe {

/// A distance known to lie between two bounds (scene units): exact when the
/// point is apart from everything, an interval of width tol when it is
/// within tol of something (the query touches it).
struct DistanceBounds {
  double low = 0.0, high = 0.0;
};

/// One point of a ray (distance t along it) with what is known of its
/// distances to the mesh and the hulls.
struct Sample {
  double t = 0.0;
  DistanceBounds mesh, hulls;
  int face = -1;                                     ///< the nearest mesh face
  int hull = -1;                                     ///< the nearest hull
  Eigen::Vector3d nearest = Eigen::Vector3d::Zero(); ///< on the nearest hull (locates the meeting when touching)
};

/// Judges open rays against an allowance. Judging is const and writes only
/// the report it is given: one judge serves many threads, each ray's figures
/// going to its own report (add_allowance_figures adds them up in order).
class AllowanceJudge {
public:
  /// `prepared`, `triangles` and `hulls` must outlive the judge;
  /// `hull_tolerance` is the tolerance at each hull's box (PlaceTolerance,
  /// scene units), which the probe computes once for both. The mesh's
  /// faces with a surface are held as flat hulls for exact point-to-mesh
  /// distances. Throws std::runtime_error when they cannot be (no face with
  /// a surface).
  AllowanceJudge(const PreparedMesh& prepared, const bvh::TriangleWorld& triangles, const bvh::HullWorld& hulls,
                 const std::vector<double>& hull_tolerance, const AllowanceOptions& options);

  /// Judges one open ray: `start` (off the surface by the stand-off) along
  /// unit `ray.direction` for `length`, with `stretches` the parts of the
  /// ray from `ray.origin` deeper than tol inside hull `second` (distances
  /// from the origin: the strict probe judges hulls from there). Adds
  /// its figures to `out` (counts added, extremes kept when strictly beyond
  /// out's), whose options it does not read.
  void judge(const ProbeRay& ray, const Eigen::Vector3d& start, double length, double stand_off,
             const std::vector<std::pair<std::pair<double, double>, int>>& stretches, AllowanceReport& out) const;

private:
  // Each ray is judged at its face's tolerance (`tol`, the island's:
  // hullcover/mesh/tolerance.h), as the probe stands it off.
  DistanceBounds to_mesh(const Eigen::Vector3d& p, double tol, int* face = nullptr) const;
  DistanceBounds to_hulls(const Eigen::Vector3d& p, double tol, int& hull, Eigen::Vector3d& nearest) const;
  void farthest_lost(const ProbeRay& ray, const Eigen::Vector3d& start, double from, double to, int hull, double tol,
                     AllowanceReport& out) const;
  void reachable_balls(const ProbeRay& ray, const Eigen::Vector3d& start, double from, double to, double tol,
                       AllowanceReport& out) const;
  void balls_over(const ProbeRay& ray, const Eigen::Vector3d& start, double from, double to, double tol,
                  int& evaluations, AllowanceReport& out) const;
  std::vector<std::pair<double, double>> near_hulls(const Eigen::Vector3d& start, const Eigen::Vector3d& dir,
                                                    double from, double to) const;
  double most_clear_between(const Eigen::Vector3d& start, const Eigen::Vector3d& dir, const Sample& a,
                            const Sample& b) const;
  /// What the ball of radius r around c does with the hulls' interiors.
  enum class BallReach { not_deep, enclosed, free };
  BallReach ball_takes_free_space(const Eigen::Vector3d& c, double r, double tol) const;

  const PreparedMesh& prepared_;
  const bvh::HullWorld& hulls_;
  AabbTree hull_tree_;
  std::shared_ptr<const bvh::HullWorld> mesh_;
  std::vector<int> face_of_; // mesh face id of mesh_'s hull i
  EnclosedSpace enclosed_;
  // Per hull, shrunk by the margin a ball may reach in, at the tolerance of
  // the hull's place (agent radius only).
  std::vector<HullInterior> interiors_;
  AllowanceOptions options_;
};

/// Adds `part` (one ray's or one face's figures) to `total`, as if judged
/// into it: counts added, the farthest lost point and the deepest ball taken
/// from `part` only when strictly beyond total's, so adding parts in ray
/// order gives the figures of judging every ray into one report.
void add_allowance_figures(AllowanceReport& total, const AllowanceReport& part);

} // namespace hullcover::validate::probe
