#pragma once
/// \file tolerances.h
/// Every tolerance hullcover uses, in one place (as Box2D's constants.h and
/// Jolt's PhysicsSettings.h do). Read this before adding a threshold.
///
/// The base: ONE length per place, `tol` (hullcover/mesh/tolerance.h chooses
/// it: `kDefaultRelativeTolerance` x the diagonal of the island a test
/// happens in (hullcover/mesh/mesh_islands.h), never below the data's own
/// rounding floor there; printed by every command; overridable with --tol,
/// one length for all). Every sidedness and containment test uses it: "strictly inside"
/// means deeper than tol, "coincident" closer than tol. Every other length
/// threshold of the decomposer and the audit is a named multiple of tol
/// below. Directions have their own, dimensionless tolerances
/// (`kParallelSine`); a length is never compared with a
/// sine. The runtime (bvh) answers queries on hulls that carry no scene
/// tolerance: its thresholds are relative to each query's own size (section
/// "Runtime").

#include <algorithm>

namespace hullcover {

// ---- The scene tolerance ---------------------------------------------------

/// Default tolerance as a fraction of each place's diagonal (a place: the
/// islands whose boxes meet, hullcover/mesh/tolerance.h). The near-merge distance and the
/// prism cap are fractions of it too: a map keeps its defaults, and so its
/// hulls, in any world.
inline constexpr double kDefaultRelativeTolerance = 1e-5;

/// How many units of rounding error one sidedness test (a plane through three
/// rounded points, evaluated at a fourth) may accumulate; the floor is this
/// multiple of the data's own error bound.
inline constexpr double kRoundingErrorsPerPlaneTest = 8.0;

// ---- Named multiples of tol ------------------------------------------------

/// Rays of free space (the decomposer's witness rays, the audit's probe
/// rays) meet faces only this many tolerances past the surface they leave:
/// a neighbour in that surface's plane, within rounding of it, is no wall
/// in front of it. Hulls are judged along the whole ray, from the surface
/// itself (the strict definition's 0 < t < first hit): a hull entered and left within
/// the stand-off takes free space too.
inline constexpr double kRayStandOffInTolerances = 2.0;

/// The decomposer's rays meet a face only inside its bounding box grown by
/// this many tolerances (mesh_ray.h), and its face tree looks that far
/// around a ray. The box cuts off the tips a sharp corner's edges reach when
/// pushed out by tol. Not 1: an axis-aligned face's pushed edges lie on its
/// box grown by exactly tol, and so do the grown hulls' facets and the
/// sweeps' sides; a cut there would be decided by rounding, which moves with
/// the coordinates (a scene moved by 1e5 took another greedy path).
inline constexpr double kFaceBoxMarginInTolerances = 1.5;

/// Patches join as one planar patch only when every vertex of theirs lies in
/// a slab this many tolerances wide along their normal; the polygon's plane
/// runs through its middle, so every face lies within half a tol of its
/// hull's surface: coverage (within tol, docs/definitions-and-proofs.md) holds with room to
/// spare for a reader of rounded output.
inline constexpr double kPlanarSlabInTolerances = 1.0;
/// A finished planar patch re-checked against an edited scene (a cached
/// cell, cell_cache.h) counts faces within this many tol of its final plane
/// as covering it: each merge that built it counted faces within
/// kPlanarSlabInTolerances of its own plane, and each such plane, fitting a
/// subset of the patch's points within a slab, parts from the final plane
/// by at most two slabs more over that subset.
inline constexpr double kRecheckSlabInTolerances = 3.0 * kPlanarSlabInTolerances;

/// A re-bake (scene_change.h) counts a kept hull as touched by an edit when
/// it comes within this many tolerances (the scene's largest) of a changed
/// face's reach or a sweep crossing it: wider than every growth a check
/// gives the boxes it looks up (the recheck slab, the rays' stand-off, the
/// sweeps' start behind their face), so nothing a check reads lies beyond.
inline constexpr double kSceneChangeSlackInTolerances = 4.0 * (kRecheckSlabInTolerances + kRayStandOffInTolerances);

/// A solid hull whose interior shrunk by tol is empty (inradius <= tol) has
/// no inside for rays to meet; it is then at most 4 inradii wide across one
/// of its facets (the tetrahedron of the facet planes its inscribed ball
/// touches holds it). A solid no wider than this many tolerances across a
/// facet is thin and is also held to a flat polygon's condition 4 across
/// that facet (no face outside the patch reaching below it through its
/// interior).
inline constexpr double kThinHullSlabInTolerances = 4.0;

/// A prism thinner than this many tolerances is no thicker than the noise
/// of the data: it is made flat instead.
inline constexpr double kMinPrismThicknessInTolerances = 2.0;

/// Exact mode's bar half-length: its sheets only have to stop a flat polygon
/// spanning an open edge in its own plane; the opening beyond the edge is
/// kept by the exact conditions.
inline constexpr double kExactBarHalfLengthInTolerances = 4.0;

/// A hull grown point by point (incremental_hull.h) gives up on a new
/// triangle less high than this many tolerances (no reliable normal).
inline constexpr double kMinTriangleHeightInTolerances = 1.0;

/// A point less than this many tolerances in front of every facet is taken
/// as on a hull being grown: the hull kept differs from the exact one by a
/// small fraction of the tolerance every later test allows.
inline constexpr double kVisibleBeyondTolerances = 1.0 / 16.0;

/// Two planes of one hull that stay this many tolerances apart or less
/// across the whole hull are one plane when the hull is shrunk by tol (a
/// grown hull's coplanar triangles): the shrunk facet is kept once, off by
/// this small fraction of tol at most.
inline constexpr double kOnePlaneInTolerances = 1.0 / 16.0;

// ---- The free-space definition ----------------------------------------------

/// Openings (docs/definitions-and-proofs.md, "Free space: the strict definition") run from every open edge
/// outward in its face's plane, and tilted "a little" to either side of
/// it: by the angle whose sine this is (about 5.7 degrees). The decomposer
/// keeps the three fans of rays (in the plane, and tilted either way) free,
/// and the audit traces the same three; a definition, not a tolerance, so
/// both read it here.
inline constexpr double kOpeningTiltSine = 0.1;

// ---- Directions -------------------------------------------------------------

/// An edge whose sine with a direction is below this runs along it (a face
/// seen edge-on bounds no column of rays). Dimensionless; far above the
/// relative rounding of a cross product (about 1e-16), so the plane of any
/// edge it keeps has a well-defined normal.
inline constexpr double kParallelSine = 1e-9;

/// Two planes whose normals differ by less than this in 1 - cos are one
/// plane across `extent`: over that length their offsets drift apart by at
/// most tol, since 1 - cos(a) ~ a^2 / 2 and the drift is extent x a.
/// Used for the planes of a patch's faces (extent: the largest island's
/// diagonal; a patch lies within one island). A
/// hull's shrunk facets use kOnePlaneInTolerances instead: their planes are
/// compared by distance across the hull, not by angle.
inline double same_plane_cosine_gap(double tol, double extent) {
  const double ratio = tol / std::max(extent, tol);
  return 0.5 * ratio * ratio;
}

// ---- Runtime ----------------------------------------------------------------
// The runtime (bvh) reads hulls that carry no scene tolerance, so its
// thresholds are fractions of the sizes a test compares, or dimensionless.

/// The triangle baseline (TriangleWorld, which is given the scene's tol)
/// inflates query shapes by this many tolerances in its broad phase, so a triangle FCL's iterative narrow phase misses by
/// rounding still reaches the exact test.
inline constexpr double kTriangleMarginInTolerances = 4.0;

/// A query's convex shape is hulled without Qhull (point_hull.h): points
/// closer than this fraction of the point set's extent to a plane count as
/// on it (a query shape carries no scene tolerance).
inline constexpr double kPointHullRelativeTolerance = 1e-9;

/// A hull Qhull builds thinner than this fraction of its points' extent is
/// flat, and the decomposer's hull builder refuses it as Qhull refuses
/// exactly coplanar points (convex_hull_3d.h). Points one plane holds in
/// exact arithmetic come off it by rounding once a scene is turned and
/// moved (a double-sided wall at 1e5 lies within 1e-12 of its plane); built
/// as a solid, that sliver's facets have normals made of noise and it
/// would span what the flat union may not. The point hull's fraction.
inline constexpr double kFlatHullRelativeWidth = kPointHullRelativeTolerance;

/// The narrow phase (hull_contact.cpp) takes a distance below this fraction
/// of a hull's size (1 + its box diagonal) as zero: the direction between
/// closest points that near is rounding noise, so the separating-axis path
/// gives the normal instead. The same relative slack decides its other
/// exact-arithmetic ties: an edge pair whose cross product is below this
/// fraction of their lengths' product (a sine) is parallel and yields no
/// axis, and a point whose closest point on its front facet is as far as
/// that facet's plane, to this fraction, projects inside the facet. 1e-12 is thousands of ulps (above the
/// rounding of the few dozen operations behind each value) yet far below
/// any feature a covering keeps.
inline constexpr double kTouchingFraction = 1e-12;

/// A plane normal read from a runtime file may differ from unit length by
/// this much. The narrow phase reads signed distances straight off these
/// planes, so a normal's length scales every distance: 1e-9 lets through
/// the rounding of any normalisation in double precision (~1e-16) and
/// distances off by at most a billionth, and refuses a corrupt or
/// mis-scaled file.
inline constexpr double kUnitNormalSlack = 1e-9;

/// HullWorld::distance grows its search box around the shape, while it
/// holds no hull, to twice its reach plus this fraction of (1 + the world
/// box's diagonal): the first ring is small next to the world, so the first
/// hulls found are near ones (few exact distances to compute), and doubling
/// reaches past the far side of the world in about a dozen rounds. The 1
/// keeps a world of zero extent growing.
inline constexpr double kDistanceReachGrowth = 1e-3;

/// A sweep whose start and end rotations agree to this relative precision
/// (Eigen's isApprox, Frobenius norm) counts as a pure translation, with an
/// exact swept box. Two poses built from one rotation differ by rounding
/// only (~1e-16); a turn small enough to pass moves a point 1e6 units away
/// by about 1e-6.
inline constexpr double kSweepSameRotation = 1e-12;

// ---- Audit ------------------------------------------------------------------

/// The independent re-check (hullcover/validate/validity_recheck.h) takes a
/// point within this many tolerances of a hull's planes as ON them: a face
/// is on a hull (condition 2) when no hull vertex is more than 2 tol in
/// front of the face's plane (its corners, for coverage, must lie within 1
/// tol of the hull's facets: a distance, not a plane test); a face within 2 tol of a
/// flat hull's plane is that hull's own (condition 4); a point within 2 tol
/// of a flat polygon's rim is on the rim, not in the interior a face below
/// must not reach. Twice the base: the face may be up to tol off a facet
/// (the decomposer's tests allow that), and the facet's own corners up to
/// tol off the plane the re-check fits through them (Newell's method, not
/// the decomposer's planes). "Strictly inside" stays deeper than one tol.
inline constexpr double kOnHullInTolerances = 2.0;

/// A region (a box-tree node's box) that lies this many tolerances short of
/// being deeper than tol behind one of a hull's planes, beyond the rounding
/// of that test, holds no mesh vertex or edge point the hull's own tests
/// would find deeper than tol inside: condition 1's walks pass it over
/// (region_outside_interior in convex_polytope.h). Half a tol: the data's
/// floor (kRoundingErrorsPerPlaneTest) already makes a tol many roundings.
inline constexpr double kRegionOutsideSlackInTolerances = 0.5;

} // namespace hullcover
