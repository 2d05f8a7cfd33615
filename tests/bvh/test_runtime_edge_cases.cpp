// The runtime on knife edges, HullWorld against TriangleWorld on the same
// triangles: shapes exactly touching, 1e-9 apart and 1e-9 in, resting on
// a facet, its edge or its corner; rays along edges, through vertices and
// grazing faces; hulls 1e-6 thick and flat; the scene moved 1e5 and 1e7
// from the origin. Every output must be finite, every normal unit and
// pointing out of the hull toward the shape (moving the shape along it
// separates them), and both worlds must agree on yes/no, depth and rays.

#include "box_hulls.h"
#include "covering_fixture.h"
#include "poses.h"

#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/bvh/triangle_world.h"
#include "hullcover/geometry/tolerances.h"
#include "hullcover/mesh/scene_builder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace hullcover::bvh {
namespace {

using V = Eigen::Vector3d;
using test::at;

const V kUp = V::UnitY();

// Exact answers may be off by the rounding of a few dozen operations at the
// coordinates' magnitude: 64 ulps of the largest coordinate (plus one, for
// scenes at the origin). Far below every gap these tests set.
constexpr double kRoundingUlps = 64.0;
double rounding_at(const V& p) {
  return kRoundingUlps * std::numeric_limits<double>::epsilon() * (1.0 + p.cwiseAbs().maxCoeff());
}

// Two unit normals are the same direction when their dot product is within
// this of 1: planes fitted through rounded coordinates 1e7 out turn by
// about 1e-16 x 1e7 / size, far less.
constexpr double kSameDirection = 1e-9;

// How far a shape is moved along a contact's normal beyond its depth to
// check that this separates it: above the rounding at every offset here
// (about 1e-7 at 1e7), small next to the unit-sized shapes.
constexpr double kSeparationStep = 1e-6;

// Contacts asked of either world: more than the triangles any shape here touches.
constexpr int kAllContacts = 16;
// Rays run this far: past everything in these scenes.
constexpr double kRayReach = 100.0;

// ---- Sanity of every output -------------------------------------------------

void expect_unit(const V& n, const std::string& what) {
  ASSERT_TRUE(n.allFinite()) << what;
  EXPECT_NEAR(n.norm(), 1.0, kUnitNormalSlack) << what;
}

void expect_sane(const ContactResult& r, const std::string& what) {
  for (const Contact& c : r.contacts) {
    EXPECT_TRUE(std::isfinite(c.depth) && c.depth >= 0.0) << what << " depth " << c.depth;
    EXPECT_TRUE(c.point.allFinite()) << what;
    expect_unit(c.normal, what + " contact normal");
  }
}

void expect_sane(const RayResult& r, const std::string& what) {
  if (!r.hit) return;
  EXPECT_TRUE(std::isfinite(r.first.t) && r.first.t >= 0.0) << what << " t " << r.first.t;
  EXPECT_TRUE(r.first.point.allFinite()) << what;
  expect_unit(r.first.normal, what + " ray normal");
}

// ---- Scenes -------------------------------------------------------------------

struct BlockWorlds {
  std::shared_ptr<const HullWorld> hulls;
  std::shared_ptr<const TriangleWorld> triangles;
  double tol = 0.0; // the triangle world's
};

// The block [0,2] x [0,1] x [0,3] moved by `offset`, decomposed at the
// defaults (a closed box: one hull), with the triangle world of its mesh.
BlockWorlds block_worlds(const V& offset) {
  Mesh m;
  add_box(m, offset, offset + V(2, 1, 3));
  const auto d = test::decompose_and_check(m);
  EXPECT_TRUE(d);
  if (!d) return {};
  EXPECT_EQ(d->covering.hulls.size(), 1u);
  return {build_hull_world(d->covering).value(), TriangleWorld::build(d->prepared.mesh, d->tol()).value(), d->tol()};
}

// A sphere of radius `r` at `centre` against both worlds: apart when
// `depth` is NAN, else touching that deep, the deepest contact of each
// pushing along `normal` (either way along it when `either_way`).
void check_sphere(const BlockWorlds& w, const std::string& what, const V& centre, double r, double depth,
                  const V& normal, bool either_way = false) {
  ContactResult h, t;
  ASSERT_TRUE(w.hulls->contacts({QueryShape::sphere(r), at(centre), kAllContacts}, h).ok()) << what;
  ASSERT_TRUE(w.triangles->contacts({QueryShape::sphere(r), at(centre), kAllContacts}, t).ok()) << what;
  expect_sane(h, what);
  expect_sane(t, what);
  ASSERT_EQ(h.contacts.empty(), std::isnan(depth)) << what << " (hulls)";
  ASSERT_EQ(t.contacts.empty(), std::isnan(depth)) << what << " (triangles)";
  if (std::isnan(depth)) return;
  for (const ContactResult* result : {&h, &t}) {
    const Contact& c = result->contacts.front();
    const std::string who = what + (result == &h ? " (hulls)" : " (triangles)");
    EXPECT_NEAR(c.depth, depth, rounding_at(centre)) << who;
    const double along = c.normal.dot(normal);
    EXPECT_GT(either_way ? std::abs(along) : along, 1.0 - kSameDirection) << who << " normal " << c.normal.transpose();
  }
}

struct KnownRay {
  std::string name;
  V origin, direction; // before any offset
  double t;            // expected first hit; NAN for none
};

// A ray against both worlds: the expected hit or none; met from outside, a
// facet faces the ray (at an edge or corner, any of its facets does).
void check_ray(const BlockWorlds& w, const KnownRay& k, const V& offset = V::Zero()) {
  const RayRequest ray{offset + k.origin, k.direction, kRayReach};
  RayResult h, t;
  ASSERT_TRUE(w.hulls->ray_cast(ray, h).ok()) << k.name;
  ASSERT_TRUE(w.triangles->ray_cast(ray, t).ok()) << k.name;
  expect_sane(h, k.name);
  expect_sane(t, k.name);
  const bool expected = !std::isnan(k.t);
  ASSERT_EQ(h.hit, expected) << k.name << " (hulls)";
  ASSERT_EQ(t.hit, expected) << k.name << " (triangles)";
  if (!expected) return;
  EXPECT_NEAR(h.first.t, k.t, rounding_at(ray.origin)) << k.name << " (hulls)";
  EXPECT_NEAR(t.first.t, k.t, rounding_at(ray.origin)) << k.name << " (triangles)";
  if (k.t > 0.0) {
    EXPECT_LE(h.first.normal.dot(k.direction), 0.0) << k.name << " (hulls)";
    EXPECT_LE(t.first.normal.dot(k.direction), 0.0) << k.name << " (triangles)";
  }
}

// ---- Contacts on a knife edge ---------------------------------------------

// A shape placed by `pose_at(gap)`: `gap` above the block's top (negative:
// into it), the top being the only facet it can touch first.
struct Resting {
  std::string name;
  QueryShape shape;
  std::function<Eigen::Isometry3d(double gap)> pose_at;
};

Eigen::Isometry3d upright_at(const V& p) {
  Eigen::Isometry3d pose = at(p);
  pose.linear() = Eigen::AngleAxisd(-M_PI / 2, V::UnitX()).toRotationMatrix(); // local z -> world y
  return pose;
}

// Shapes resting on the block's top (y = 1 before the offset): on the face,
// along and across its edges, on its corner, and a box with the block's own
// footprint (its sides in the block's side planes).
std::vector<Resting> resting_shapes(const V& o) {
  QueryShape tetra;
  tetra.kind = ShapeKind::convex;
  tetra.points = {V(0, 0, 0), V(0.4, 0, 0), V(0, 0, 0.4), V(0.1, 0.4, 0.1)};
  return {
      {"sphere on the face", QueryShape::sphere(0.5), [o](double g) { return at(o + V(1, 1.5 + g, 1.5)); }},
      {"sphere on an edge", QueryShape::sphere(0.5), [o](double g) { return at(o + V(2, 1.5 + g, 1.5)); }},
      {"sphere on a corner", QueryShape::sphere(0.5), [o](double g) { return at(o + V(2, 1.5 + g, 3)); }},
      {"capsule lying along the edge", QueryShape::capsule(0.25, 0.5),
       [o](double g) { return at(o + V(2, 1.25 + g, 1.5)); }},
      {"capsule upright", QueryShape::capsule(0.25, 0.5),
       [o](double g) { return upright_at(o + V(1, 1.75 + g, 1.5)); }},
      {"box on the face", QueryShape::box(V(0.3, 0.2, 0.4)), [o](double g) { return at(o + V(1, 1.2 + g, 1.5)); }},
      {"box on the whole top", QueryShape::box(V(1, 0.5, 1.5)), [o](double g) { return at(o + V(1, 1.5 + g, 1.5)); }},
      {"tetrahedron on the face", tetra, [o](double g) { return at(o + V(0.8, 1 + g, 1.2)); }},
  };
}

// Places every resting shape `gap` above the top and checks both worlds:
// touching exactly when gap <= 0, at depth max(0, -gap), pushed up; the
// hull world's normal among the triangle world's; moving the shape by depth
// plus a step along it separates it from both.
void check_resting(const BlockWorlds& w, const V& offset, double gap) {
  for (const Resting& r : resting_shapes(offset)) {
    const Eigen::Isometry3d pose = r.pose_at(gap);
    const std::string what = r.name + " at gap " + std::to_string(gap);
    const double slack = rounding_at(pose.translation());
    ContactResult h, t;
    ASSERT_TRUE(w.hulls->contacts({r.shape, pose, kAllContacts}, h).ok()) << what;
    ASSERT_TRUE(w.triangles->contacts({r.shape, pose, kAllContacts}, t).ok()) << what;
    expect_sane(h, what);
    expect_sane(t, what);
    TouchResult touch;
    OverlapResult overlap;
    ASSERT_TRUE(w.hulls->touches({r.shape, pose}, touch).ok());
    ASSERT_TRUE(w.hulls->overlap({r.shape, pose}, overlap).ok());
    EXPECT_EQ(touch.touching, !h.contacts.empty()) << what;
    EXPECT_EQ(overlap.hulls.size(), h.contacts.size()) << what;
    // FCL's yes/no (the baseline's touches and overlap) is iterative: it is
    // held to the exact answer only beyond the triangle world's margin.
    if (std::abs(gap) > kTriangleMarginInTolerances * w.tol) {
      TouchResult fcl_touch;
      OverlapResult fcl_overlap;
      ASSERT_TRUE(w.triangles->touches({r.shape, pose}, fcl_touch).ok());
      ASSERT_TRUE(w.triangles->overlap({r.shape, pose}, fcl_overlap).ok());
      std::vector<int> exact;
      for (const Contact& tc : t.contacts) exact.push_back(tc.hull);
      std::sort(exact.begin(), exact.end());
      EXPECT_EQ(fcl_touch.touching, gap <= 0.0) << what << " (FCL)";
      EXPECT_EQ(fcl_overlap.hulls, exact) << what << ": FCL's triangles against the exact contacts'";
    }
    const bool expected = gap <= 0.0;
    ASSERT_EQ(!h.contacts.empty(), expected) << what << " (hulls)";
    ASSERT_EQ(!t.contacts.empty(), expected) << what << " (triangles)";
    DistanceResult gap_to;
    ASSERT_TRUE(w.hulls->distance({r.shape, pose}, gap_to).ok());
    EXPECT_TRUE(gap_to.on_world.allFinite() && gap_to.on_shape.allFinite()) << what;
    EXPECT_EQ(gap_to.touching, expected) << what;
    EXPECT_NEAR(gap_to.distance, std::max(gap, 0.0), slack) << what;
    if (!expected) continue;
    const Contact& c = h.contacts.front();
    EXPECT_NEAR(c.depth, -gap, slack) << what;
    EXPECT_NEAR(t.contacts.front().depth, -gap, slack) << what << " (triangles)";
    EXPECT_GT(c.normal.dot(kUp), 1.0 - kSameDirection) << what << " normal " << c.normal.transpose();
    bool shared = false;
    for (const Contact& tc : t.contacts) shared |= tc.normal.dot(c.normal) > 1.0 - kSameDirection;
    EXPECT_TRUE(shared) << what << ": no triangle pushes along " << c.normal.transpose();
    Eigen::Isometry3d moved = pose;
    moved.translation() += (c.depth + kSeparationStep) * c.normal;
    ASSERT_TRUE(w.hulls->touches({r.shape, moved}, touch).ok());
    ASSERT_TRUE(w.triangles->contacts({r.shape, moved, kAllContacts}, t).ok());
    EXPECT_FALSE(touch.touching) << what << " still touches the hull once moved along its normal";
    EXPECT_TRUE(t.contacts.empty()) << what << " still touches a triangle once moved along the normal";
  }
}

// A billionth of the block's size apart, exactly touching, a billionth in.
constexpr double kKnifeGap = 1e-9;

TEST(RuntimeEdgeCases, TouchingAndRestingShapesAgreeWithTheTriangles) {
  const BlockWorlds w = block_worlds(V::Zero());
  ASSERT_TRUE(w.hulls && w.triangles);
  for (const double gap : {kKnifeGap, 0.0, -kKnifeGap}) check_resting(w, V::Zero(), gap);
  // Clearly apart and clearly in, where FCL's yes/no must agree too.
  const double clear = 2.0 * kTriangleMarginInTolerances * w.tol;
  for (const double gap : {clear, -clear}) check_resting(w, V::Zero(), gap);
}

// The least form of a capsule touching a triangle's edge from the
// triangle's own plane (the block's side triangle under the capsule lying
// along its top edge, above): the axis is in front of neither facet of the
// flat hull, only of a side plane, which has no facet. A sphere at the same
// place, and the same capsule tilted out of the plane, are found.
TEST(RuntimeEdgeCases, ACapsuleInAFlatHullsPlaneTouchesItsRim) {
  const RuntimeHull triangle = flat_triangle_hull(V(0, 0, 0), V(0, 0, 2), V(2, 0, 0)); // in y = 0
  const double r = 0.25, off = 0.2; // the axis runs along z, `off` beyond the edge x = 0
  const V a(-off, 0, 0.5), b(-off, 0, 1.5);
  const double slack = rounding_at(V(2, 2, 2));
  ASSERT_TRUE(sphere_contact(triangle, V(-off, 0, 1), r));
  const V tilt(0, 0.1 * off, 0); // any tilt puts one end in front of a facet
  ASSERT_TRUE(capsule_contact(triangle, a - tilt, b + tilt, r));
  EXPECT_NEAR(closest_to_segment(triangle, a, b).distance, off, slack);
  EXPECT_TRUE(capsule_touches(triangle, a, b, r));
  const std::optional<Contact> c = capsule_contact(triangle, a, b, r);
  ASSERT_TRUE(c) << "capsule in the triangle's plane, " << off << " from its edge, radius " << r;
  EXPECT_NEAR(c->depth, r - off, slack);
  EXPECT_GT(c->normal.dot(-V::UnitX()), 1.0 - kSameDirection);
}

// ---- Rays on edges and vertices ---------------------------------------------

// The block [0,2] x [0,1] x [0,3]; every expected t by hand.
std::vector<KnownRay> edge_rays() {
  return {
      {"along an edge", V(-1, 0, 0), V(1, 0, 0), 1.0},
      {"along a face's plane", V(-1, 1, 1.5), V(1, 0, 0), 1.0},
      {"diagonally through a vertex, into the block", V(-1, -1, -1), V(1, 1, 1), std::sqrt(3.0)},
      {"touching an edge only", V(-1, 0, 1.5), V(1, 1, 0), std::sqrt(2.0)},
      {"touching a vertex only", V(-1, 0, -1), V(1, 1, 1), std::sqrt(3.0)},
      {"from an edge, away", V(2, 1, 1.5), V(1, 1, 0), 0.0},
      {"from a vertex, away", V(2, 1, 3), V(1, 1, 1), 0.0},
      {"from a vertex, along its edge", V(2, 1, 3), V(1, 0, 0), 0.0},
      {"straight down on an edge", V(2, 5, 1.5), V(0, -1, 0), 4.0},
      {"clear of an edge by a unit", V(-1, 2, 1.5), V(1, 0, 0), NAN},
  };
}

void check_rays(const BlockWorlds& w, const V& offset) {
  for (const KnownRay& k : edge_rays()) check_ray(w, k, offset);
}

TEST(RuntimeEdgeCases, RaysAlongEdgesAndThroughVerticesAgreeWithTheTriangles) {
  const BlockWorlds w = block_worlds(V::Zero());
  ASSERT_TRUE(w.hulls && w.triangles);
  check_rays(w, V::Zero());
}

// A billionth off an edge the hull is missed, exactly; the triangles count
// a hit within tol of their edges (TriangleWorld), so they may meet it, but
// only there.
TEST(RuntimeEdgeCases, ARayJustClearOfAnEdgeMissesTheHull) {
  const BlockWorlds w = block_worlds(V::Zero());
  ASSERT_TRUE(w.hulls && w.triangles);
  const RayRequest ray{V(-1, 1 + kKnifeGap, 1.5), V(1, 0, 0), kRayReach};
  RayResult h, t;
  ASSERT_TRUE(w.hulls->ray_cast(ray, h).ok());
  ASSERT_TRUE(w.triangles->ray_cast(ray, t).ok());
  EXPECT_FALSE(h.hit);
  expect_sane(t, "just clear");
  if (t.hit) {
    EXPECT_NEAR(t.first.t, 1.0, rounding_at(ray.origin)) << "only at the edge it passes";
  }
}

// ---- Thin and flat hulls --------------------------------------------------------

// A slab a millionth as thick as it is wide, as one box hull, against its
// twelve triangles; the triangle world's tol is below the thickness so its
// sides keep their surface (the default, 1e-5 x diagonal, would weld them).
TEST(RuntimeEdgeCases, AHullAMillionthThick) {
  const double thickness = 2e-6, width = 2.0;
  const double thin_tol = thickness / 16.0;
  Mesh m;
  add_box(m, V(0, 0, 0), V(width, thickness, width));
  const BlockWorlds w{HullWorld::build({test::box_hull(V(0, 0, 0), V(width, thickness, width))}).value(),
                      TriangleWorld::build(m, thin_tol).value(), thin_tol};
  ASSERT_EQ(w.triangles->triangle_count(), 12);
  const double r = 0.5;
  check_sphere(w, "touching the top", V(1, thickness + r, 1), r, 0.0, kUp);
  check_sphere(w, "a billionth into the top", V(1, thickness + r - kKnifeGap, 1), r, kKnifeGap, kUp);
  check_sphere(w, "a billionth above the top", V(1, thickness + r + kKnifeGap, 1), r, NAN, kUp);
  check_sphere(w, "touching the bottom", V(1, -r, 1), r, 0.0, -kUp);
  check_sphere(w, "touching the thin side edge-on", V(width + r, thickness / 2, 1), r, 0.0, V::UnitX());
  check_sphere(w, "a billionth into the thin side", V(width + r - kKnifeGap, thickness / 2, 1), r, kKnifeGap,
               V::UnitX());
  // Stuck in the middle of the slab: the hull pushes out through the top or
  // the bottom, the whole radius and half the thickness; the triangles
  // push out of both sides.
  ContactResult h;
  ASSERT_TRUE(w.hulls->contacts({QueryShape::sphere(r), at(V(1, thickness / 2, 1)), kAllContacts}, h).ok());
  ASSERT_EQ(h.contacts.size(), 1u);
  expect_sane(h, "stuck");
  EXPECT_GT(std::abs(h.contacts[0].normal.y()), 1.0 - kSameDirection);
  EXPECT_NEAR(h.contacts[0].depth, r + thickness / 2, rounding_at(V(1, 1, 1)));
  ContactResult t;
  ASSERT_TRUE(w.triangles->contacts({QueryShape::sphere(r), at(V(1, thickness / 2, 1)), kAllContacts}, t).ok());
  expect_sane(t, "stuck (triangles)");
  bool up = false, down = false;
  for (const Contact& c : t.contacts) {
    up |= c.normal.dot(kUp) > 1.0 - kSameDirection;
    down |= c.normal.dot(-kUp) > 1.0 - kSameDirection;
  }
  EXPECT_TRUE(up && down) << "the slab's triangles push out of both its sides";
  // Rays: down onto the top, through the slab's edge-on side in its
  // mid-plane, and along its top plane.
  check_ray(w, {"down", V(1, 3, 1), -kUp, 3.0 - thickness});
  check_ray(w, {"edge-on", V(-1, thickness / 2, 1), V::UnitX(), 1.0});
  check_ray(w, {"along the top", V(-1, thickness, 1), V::UnitX(), 1.0});
}

// A double-sided floor (each face also given the other way round) leaves
// no room for a prism: its hulls are flat. Touched from either side, edge-on
// at its rim, or cut through its plane, they answer as its triangles do.
TEST(RuntimeEdgeCases, FlatHullsOfADoubleSidedFloor) {
  Mesh m;
  test::add_quad_facing(m, V(0, 0, 0), V(4, 0, 0), V(4, 0, 4), V(0, 0, 4), kUp);
  for (int f = 0; f < 2; ++f) {
    m.triangles.emplace_back(m.triangles[f][0], m.triangles[f][2], m.triangles[f][1]);
    m.material_ids.push_back(0);
  }
  const auto d = test::decompose_and_check(m);
  ASSERT_TRUE(d);
  for (const CoveringHull& hull : d->covering.hulls) ASSERT_EQ(hull.thickness, 0.0) << "expected flat hulls";
  const BlockWorlds w{build_hull_world(d->covering).value(), TriangleWorld::build(d->prepared.mesh, d->tol()).value(),
                      d->tol()};
  const double r = 0.5;
  check_sphere(w, "touching from above", V(1, r, 1), r, 0.0, kUp);
  check_sphere(w, "touching from below", V(1, -r, 1), r, 0.0, -kUp);
  check_sphere(w, "a billionth in from above", V(1, r - kKnifeGap, 1), r, kKnifeGap, kUp);
  check_sphere(w, "a billionth in from below", V(1, kKnifeGap - r, 1), r, kKnifeGap, -kUp);
  check_sphere(w, "a billionth above", V(1, r + kKnifeGap, 1), r, NAN, kUp);
  check_sphere(w, "touching the rim edge-on", V(4 + r, 0, 2), r, 0.0, V::UnitX());
  check_sphere(w, "a billionth into the rim", V(4 + r - kKnifeGap, 0, 2), r, kKnifeGap, V::UnitX());
  check_sphere(w, "centred in its plane", V(1, 0, 2), r, r, kUp, true);
  check_ray(w, {"down", V(1, 2, 1), -kUp, 2.0});
  check_ray(w, {"up", V(1, -3, 1), kUp, 3.0});
  check_ray(w, {"through the rim", V(5, 1, 2), V(-1, -1, 0), std::sqrt(2.0)});
}

// ---- Far from the origin ----------------------------------------------------------

// The same knife edges with the block 1e5 and 1e7 out along the diagonal,
// where an ulp of a coordinate is 1.5e-11 and 1.9e-9: gaps of a billionth
// no longer exist there, so they are a thousand roundings instead.
TEST(RuntimeEdgeCases, FarFromTheOrigin) {
  for (const double far : {1e5, 1e7}) {
    const V offset = V::Constant(far);
    SCOPED_TRACE("offset " + std::to_string(far));
    const BlockWorlds w = block_worlds(offset);
    ASSERT_TRUE(w.hulls && w.triangles);
    const double gap = 1e3 * rounding_at(offset);
    const double clear = 2.0 * kTriangleMarginInTolerances * w.tol;
    for (const double g : {clear, gap, 0.0, -gap, -clear}) check_resting(w, offset, g);
    check_rays(w, offset);
  }
}

} // namespace
} // namespace hullcover::bvh
