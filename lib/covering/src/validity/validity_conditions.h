#pragma once
/// \file validity_conditions.h
/// The paper's validity conditions (section 4.1) for a candidate hull,
/// tested against the whole mesh with the one tolerance.
///
///  1. the hull contains no mesh vertex and no part of a mesh edge in its
///     interior;
///  2. every face of the patch lies on the hull's boundary with its normal
///     pointing out (`planes_support_points`);
///  3. no boundary constraint bar penetrates the hull (for a flat polygon:
///     crosses its relative interior);
///  4. for a flat polygon, no face outside the patch that touches the
///     polygon's relative interior has a vertex on its negative side.
///
/// In `ValidityMode::exact` (the index's mode) the conditions of
/// exact_conditions.h are checked too: bars become sheets along whole open
/// edges, and faces must not face into or cross a solid hull.

#include "hullcover/geometry/convex_polytope.h"
#include "hullcover/geometry/planar_hull.h"
#include "validity/scene_index.h"
#include "hullcover/covering/validity.h"

#include <functional>
#include <vector>

namespace hullcover {

/// Condition 2 between two point sets: every plane (outward, from faces of
/// one patch) has every point (hull vertices of the other patch) behind it
/// or within `tol` in front.
bool planes_support_points(const std::vector<Plane>& planes, const std::vector<Eigen::Vector3d>& points, double tol);

/// One piece of free space the exact conditions judge: the front space of
/// face `item` (fan < 0), or fan `fan` of the opening beyond open edge
/// `item` (the scene index's numbering of open edges).
struct SweepRef {
  int item = -1;
  int fan = -1;
  bool operator==(const SweepRef& o) const { return item == o.item && fan == o.fan; }
};

/// The pieces of free space that rejected the latest hulls, most recent
/// first. Candidates tried one after another (a face offered to patch after
/// patch when dissolving, a patch's neighbours in turn) mostly fail on the
/// same piece, and check_solid_hull judges these first. It changes only
/// which failed condition is reported, never whether a hull is valid: the
/// conditions are a conjunction, each judged on its own.
class RecentRejections {
public:
  static constexpr int kKept = 4;
  /// Most recent first; unused slots have item -1.
  const SweepRef* begin() const { return refs_; }
  const SweepRef* end() const { return refs_ + kKept; }
  /// `ref` rejected a hull: it goes first.
  void note(const SweepRef& ref) {
    int at = kKept - 1;
    for (int i = 0; i < kKept; ++i)
      if (refs_[i] == ref) at = i;
    for (int i = at; i > 0; --i) refs_[i] = refs_[i - 1];
    refs_[0] = ref;
  }

private:
  SweepRef refs_[kKept];
};

/// Conditions 1 and 3 (exact mode: and E1-E3) for a solid hull. `scratch`
/// is reused storage. `recent`, when given, is judged first among the
/// pieces of free space the hull's box meets, and told the piece that
/// rejects this hull.
Validity check_solid_hull(const SceneIndex& index, const ConvexPolytope& hull, std::vector<int>& scratch,
                          RecentRejections* recent = nullptr);

/// Condition 4 alone, for a flat polygon or a solid thin enough to act as
/// one (within `half_width` of the polygon's plane, scene units): a face
/// outside the patch that reaches more than `half_width` below the plane
/// and meets the polygon's interior (its sides moved in by `half_width` too)
/// is `face_below_polygon` (a floor's hull spanning a hole in it: a pit, a
/// stairwell). Else `valid`.
Validity check_faces_below_polygon(const SceneIndex& index, const FlatPolygon& polygon, double half_width,
                                   const std::function<bool(int)>& in_patch, std::vector<int>& scratch);

/// Conditions 3 (exact mode: E2) and 4 for a flat polygon; `in_patch(face)` tells whether a
/// face belongs to the patch (condition 4 looks only at faces outside it).
Validity check_flat_polygon(const SceneIndex& index, const FlatPolygon& polygon,
                            const std::function<bool(int)>& in_patch, std::vector<int>& scratch);

} // namespace hullcover
