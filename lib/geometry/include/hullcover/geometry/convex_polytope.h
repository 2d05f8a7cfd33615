#pragma once
/// \file convex_polytope.h
/// Planes and convex polytopes (hulls, prisms, flat polygons) and the
/// sidedness questions every validity condition asks of them.
///
/// Convention: a plane's normal is a unit vector pointing OUT of the
/// polytope; a point x is on the inner side when `signed_distance(x) <= 0`.
/// "Strictly inside" always means deeper than the tolerance `tol` behind
/// every plane (docs/definitions-and-proofs.md).

#include "hullcover/geometry/aabb.h"

#include <Eigen/Core>

#include <vector>

namespace hullcover {

/// The plane normal . x = offset, normal of unit length.
struct Plane {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double offset = 0.0;

  /// normal . p - offset: positive on the side the normal points to.
  double signed_distance(const Eigen::Vector3d& p) const { return normal.dot(p) - offset; }
  /// The same plane facing the other way (its inner side is this one's outer).
  Plane flipped() const { return {-normal, -offset}; }
};

/// A convex polytope with its boundary polygons. A flat polytope (a convex
/// polygon, thickness 0) has two facets, front and back, on the same
/// vertices; its extra planes bound it sideways.
struct ConvexPolytope {
  std::vector<Eigen::Vector3d> vertices;
  /// Vertex indices of each facet, counter-clockwise seen from outside.
  std::vector<std::vector<int>> facets;
  /// `planes[i]` carries `facets[i]` for i < facets.size(); any planes after
  /// those have no facet (the side planes of a flat polygon). The polytope
  /// is the intersection of all their inner sides.
  std::vector<Plane> planes;
  /// Mesh vertex id of each vertex, when the polytope was built from mesh
  /// vertices (empty otherwise, e.g. a prism's extruded corners are -1).
  std::vector<int> vertex_ids;
};

/// Moves `polytope` by `offset`: its vertices, and its planes' offsets
/// (n . (p + offset) - (d + n . offset) = n . p - d). What a computation
/// made about a local origin, to round at the shape's size rather than at
/// its distance from the scene's origin, uses to put its result back.
void move_polytope(ConvexPolytope& polytope, const Eigen::Vector3d& offset);

/// Largest signed distance of `p` over `planes`: <= -tol means strictly
/// inside, > tol strictly outside.
double deepest_signed_distance(const std::vector<Plane>& planes, const Eigen::Vector3d& p);

/// Distance from `p` to the facets of `polytope` (its boundary, inside or
/// out), each facet fanned into triangles from its first corner, scene
/// units. The fans lie in the polytope (their corners are its vertices), so
/// for a point outside this is never less than its true distance to the
/// polytope: "within tol of the hull" by this measure is within tol. A
/// polytope without facets gives infinity. Cannot fail.
double distance_to_facet_fans(const ConvexPolytope& polytope, const Eigen::Vector3d& p);

/// True when some point of segment a-b lies deeper than `tol` behind every
/// plane, i.e. the segment enters the polytope's interior shrunk by `tol`.
bool segment_enters_interior(const std::vector<Plane>& planes, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                             double tol);

/// True when no point of `box` lies deeper than `tol` behind every plane,
/// with room to spare: some plane has the whole box in front of its
/// tol-shrunk copy by kRegionOutsideSlackInTolerances tol plus the
/// rounding of this test and of deepest_signed_distance. So no point in
/// the box is then found inside by deepest_signed_distance (< -tol) and no
/// segment in it by segment_enters_interior: a box tree's walk may skip
/// the box. False for an empty box or no planes; never true in doubt.
bool region_outside_interior(const std::vector<Plane>& planes, const Aabb& box, double tol);

/// region_outside_interior for the many boxes of one walk down a box tree
/// about one hull (condition 1's vertex and edge walks): a box that meets
/// the hull is asked every plane before the answer is no, so only the
/// planes of the hull's kPlanes largest facets, which leave the most of its
/// box outside, are asked, their magnitudes taken once. True only when
/// region_outside_interior is true for them, and so for the hull.
class InteriorRegionTest {
public:
  /// How many of the hull's planes the test asks.
  static constexpr int kPlanes = 4;
  /// A hull filling more than this fraction of its box leaves too little of
  /// it outside for the node tests to pay for themselves: worthwhile() is
  /// then false (Red Eclipse's absorption spent 40% of its bake in them).
  static constexpr double kMostFilledFraction = 0.5;
  /// Keeps the hull's planes it needs: `hull` need not outlive it. `box`:
  /// the box the walks query (the hull's, grown by tol).
  InteriorRegionTest(const ConvexPolytope& hull, const Aabb& box, double tol);
  /// True only when no point of `box` lies strictly inside the hull
  /// (region_outside_interior on the kept planes).
  bool outside(const Aabb& box) const;
  /// Whether a walk should ask outside() at all: the hull fills at most
  /// kMostFilledFraction of the box.
  bool worthwhile() const { return worthwhile_; }

private:
  struct TestPlane {
    Plane plane;
    Eigen::Vector3d magnitude; ///< |normal|, per axis
  };
  TestPlane planes_[kPlanes];
  int count_ = 0;
  double tol_ = 0.0;
  bool worthwhile_ = false;
};

/// Keeps the part of convex polygon `polygon` (any winding) on the inner
/// side of `plane` offset inward by `inset` (signed distance <= -inset).
/// Returns an empty polygon when nothing is left.
std::vector<Eigen::Vector3d> clip_polygon(const std::vector<Eigen::Vector3d>& polygon, const Plane& plane,
                                          double inset);

/// `clip_polygon` written into `out` (cleared first; its capacity is kept,
/// so a caller clipping in a loop allocates once). `out` must not be
/// `polygon`.
void clip_polygon_into(const std::vector<Eigen::Vector3d>& polygon, const Plane& plane, double inset,
                       std::vector<Eigen::Vector3d>& out);

/// True when every corner of `polygon` lies strictly on the inner side of
/// `plane` offset inward by `inset` (signed distance < -inset): a cut by it
/// keeps the polygon whole. True for an empty polygon.
bool corners_strictly_inside(const std::vector<Eigen::Vector3d>& polygon, const Plane& plane, double inset);

/// `clip_polygon` in place: `polygon` becomes its part on the inner side
/// (`spare` is reused storage). One wholly on that side (every corner
/// strictly, as most are when a piece is clipped to many planes) is left
/// as it is, uncopied: the same polygon clip_polygon gives.
void clip_polygon_in_place(std::vector<Eigen::Vector3d>& polygon, const Plane& plane, double inset,
                           std::vector<Eigen::Vector3d>& spare);

/// `polygon` cut by `plane` into its part on the inner side (`inner`, as
/// clip_polygon with no inset) and on the outer side (`outer`, as
/// clip_polygon by the flipped plane), bit for bit, in one pass. Neither
/// output may be `polygon`.
void split_polygon(const std::vector<Eigen::Vector3d>& polygon, const Plane& plane, std::vector<Eigen::Vector3d>& inner,
                   std::vector<Eigen::Vector3d>& outer);

/// `clip_polygon` by every plane of `planes` in turn, with the same inset;
/// stops early once nothing is left.
std::vector<Eigen::Vector3d> clip_polygon_to_planes(std::vector<Eigen::Vector3d> polygon,
                                                    const std::vector<Plane>& planes, double inset);
/// The same in place (`spare` is reused storage, not `polygon`).
void clip_polygon_to_planes_in_place(std::vector<Eigen::Vector3d>& polygon, const std::vector<Plane>& planes,
                                     double inset, std::vector<Eigen::Vector3d>& spare);

/// A solid hull's interior: the hull shrunk by tol (what "strictly inside"
/// means), as planes and facet polygons. Empty for a hull thinner than 2 tol.
struct HullInterior {
  std::vector<Plane> planes;                        ///< the hull's planes moved in by tol
  std::vector<std::vector<Eigen::Vector3d>> facets; ///< per plane, its facet (empty when gone)
  /// Whether no facet is left: the hull is thinner than 2 tol.
  bool empty() const {
    for (const auto& f : facets)
      if (!f.empty()) return false;
    return true;
  }
};

/// The interior of `hull` (facets and planes in the same order). Shared by
/// the decomposer's exact conditions and the audit's reach check, so both
/// mean the same by "deeper than tol".
HullInterior hull_interior(const ConvexPolytope& hull, double tol);

/// How thin `hull` is: across its thinnest facet, the depth of the vertex
/// farthest behind that facet's plane; `across`, when given, gets that
/// facet's outward normal. Facets whose normal is not finite are passed
/// over; infinity when none is left.
double thinnest_width(const ConvexPolytope& hull, Eigen::Vector3d* across = nullptr);

/// Volume of a closed polytope (0 for a flat one), from its facets.
double polytope_volume(const ConvexPolytope& polytope);

} // namespace hullcover
