#pragma once
/// \file scene_clearance.h
/// Clearance: the distance from a point to the nearest triangle of the
/// scene. What decides where an agent's centre can be (clearance >= r) in
/// a movement covering, and the bounds that let a whole box be decided at
/// once.

#include "hullcover/geometry/aabb.h"
#include "hullcover/geometry/aabb_tree.h"
#include "hullcover/geometry/mesh.h"
#include "movement/oriented_box.h"

#include <Eigen/Core>

#include <vector>

namespace hullcover::detail {

/// The nearest triangle to a point, and how far it is.
struct NearestFace {
  double distance = 0.0; ///< scene units; the limit asked when no face is nearer
  int face = -1;         ///< -1 when no face is nearer than the limit
};

/// Distances from points and boxes to the triangles of one mesh (which
/// must outlive it). Read-only once built: threads may share it.
class SceneClearance {
public:
  explicit SceneClearance(const Mesh& mesh);

  /// The nearest triangle to `p`, looking no farther than `limit` (> 0).
  NearestFace nearest(const Eigen::Vector3d& p, double limit) const;
  /// The same, searching only nearer than triangle `hint` (a face likely
  /// near: the one nearest to a neighbouring point), which prunes most of
  /// the search; `hint` itself when no face is nearer. -1: no hint.
  NearestFace nearest(const Eigen::Vector3d& p, double limit, int hint) const;
  /// nearest(p, limit, hint) among `faces` alone: the same distance when
  /// `faces` holds every triangle within `limit` of `p`, and the same
  /// triangle but where two are exactly as near (a search over a region
  /// asks many points of it, and a short list beats the tree).
  NearestFace nearest_among(const std::vector<int>& faces, const Eigen::Vector3d& p, double limit, int hint) const;
  /// Distance from `p` to triangle `face`.
  double to_face(const Eigen::Vector3d& p, int face) const;
  /// Whether every point of `box` lies nearer than `limit` to triangle
  /// `face`. The distance to a triangle is convex, so its largest value on
  /// a box is at a corner; when every corner projects into the triangle it
  /// is the largest distance from the triangle's plane, which one product
  /// gives for the whole box. Every point of the box then has clearance
  /// below `limit` too.
  bool box_within(const Aabb& box, int face, double limit) const;
  /// The same for a box along any axes.
  bool box_within(const OrientedBox& box, int face, double limit) const;
  /// The faces whose boxes meet `box` into `out` (cleared first), when
  /// there are at most `most`; false (and `out` partial) when more.
  bool faces_meeting_at_most(const Aabb& box, size_t most, std::vector<int>& out) const;
  /// Appends the faces whose boxes meet `box`.
  void faces_meeting(const Aabb& box, std::vector<int>& out) const { tree_.overlapping(box, out); }

  const Mesh& mesh() const { return mesh_; }

private:
  /// The squared distance from `p` to triangle `face`: what the searches
  /// compare, one root taken at the end.
  double squared_to_face(const Eigen::Vector3d& p, int face) const;
  /// The squared distance from `p` to the plane of triangle `face` (0 for
  /// a needle): no more than squared_to_face, but for rounding far below
  /// tol, and a few products where the closest point takes dozens; a
  /// triangle whose plane lies no nearer than the best so far is passed by.
  double squared_to_plane(const Eigen::Vector3d& p, int face) const {
    const double s = planes_[face].head<3>().dot(p) - planes_[face][3];
    return s * s;
  }

  /// box_within for either kind of box.
  template <class Box>
  bool within(const Box& box, int face, double limit) const;

  const Mesh& mesh_;
  std::vector<Aabb> boxes_;             ///< each triangle's
  std::vector<Eigen::Vector4d> planes_; ///< each triangle's unit normal and offset (zero for a needle)
  AabbTree tree_;
};

} // namespace hullcover::detail
