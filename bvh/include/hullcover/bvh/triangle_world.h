#pragma once
/// \file triangle_world.h
/// The baseline: the same queries over the original triangles, in one
/// `fcl::BVHModel<fcl::OBBRSS>`. Benchmarks compare HullWorld against it;
/// the audit uses it as the reference for how characters collide with the
/// scene as modelled.
///
/// Results name triangles where HullWorld's name hulls (`Contact::hull`,
/// `OverlapResult::hulls`, `RayHit::hull` hold triangle ids). Each triangle
/// pushes along its own normal: a shape deep inside a thin closed wall gets
/// contacts from both sides (the paper's "stuck in the wall").

#include "hullcover/bvh/hull_world.h"
#include "hullcover/geometry/mesh.h"

#include <functional>
#include <memory>

namespace hullcover::bvh {

/// The scene's triangles as a world: the queries HullWorld answers, on
/// triangles (see the file comment for how results differ).
class TriangleWorld {
public:
  /// Builds over every triangle of `mesh` with a surface (altitude above
  /// `tol`, scene units; others can touch nothing) that `no_surface` (one
  /// flag per triangle, or empty) does not flag: an audit passes the faces
  /// the decomposer found zero-area at their own island's tolerance. Fails
  /// with `invalid_argument` for a mesh that fails validate_mesh, flags of
  /// another length, or no triangle left.
  static Result<std::shared_ptr<const TriangleWorld>> build(const Mesh& mesh, double tol,
                                                            const std::vector<char>& no_surface = {});

  ~TriangleWorld();
  TriangleWorld(const TriangleWorld&) = delete;
  TriangleWorld& operator=(const TriangleWorld&) = delete;

  /// Triangles a shape overlaps, by FCL (broad and narrow phase).
  [[nodiscard]] Status overlap(const OverlapRequest& request, OverlapResult& result) const;
  /// Does the shape overlap any triangle: FCL's collide asked for one
  /// contact, so it stops at the first (the baseline of HullWorld::touches).
  /// `result.hull` is that triangle's mesh face id.
  [[nodiscard]] Status touches(const OverlapRequest& request, TouchResult& result) const;
  /// Exact contacts (hull_contact.h) with every triangle FCL finds within a
  /// small margin of the shape.
  [[nodiscard]] Status contacts(const ContactRequest& request, ContactResult& result) const;
  /// First triangle hit, through the OBB tree.
  [[nodiscard]] Status ray_cast(const RayRequest& request, RayResult& result) const;
  /// Every triangle the ray hits up to its max distance, nearest first (ties
  /// by face id): coincident faces all show.
  [[nodiscard]] Status ray_hits(const RayRequest& request, std::vector<RayHit>& hits) const;
  /// Nearest triangle by FCL's distance query; spheres and capsules.
  [[nodiscard]] Status distance(const DistanceRequest& request, DistanceResult& result) const;

  /// How many triangles the world holds.
  int triangle_count() const { return static_cast<int>(triangles_.size()); }

private:
  TriangleWorld() = default;
  struct Fcl;
  std::vector<RuntimeHull> triangles_; // each triangle as a flat hull, for the exact narrow phase
  std::vector<int> face_of_;           // mesh face id of triangles_[i]
  double margin_ = 0.0;                // broad-phase inflation (a few tol)
  double tol_ = 0.0;                   // a ray meets a triangle within tol of its edges
  std::unique_ptr<Fcl> fcl_;

  /// Calls `on_hit` for every triangle hit within `reach` (which `on_hit`
  /// may shorten), through the OBB tree.
  void traverse_ray(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double& reach,
                    const std::function<void(const RayHit&)>& on_hit) const;
  void candidates(const QueryShape& shape, const Eigen::Isometry3d& pose, double inflate, std::vector<int>& out) const;
};

} // namespace hullcover::bvh
