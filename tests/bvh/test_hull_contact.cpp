// The exact narrow phase against an independent reference: a rotated box
// hull, where the closest point is a clamp in the box's own frame.

#include "hullcover/bvh/hull_contact.h"
#include "hullcover/covering/convex_hull_3d.h"
#include "hullcover/geometry/convex_polytope.h"
#include "hullcover/geometry/planar_hull.h"

#include <gtest/gtest.h>

#include <random>

namespace hullcover::bvh {
namespace {

struct OrientedBox {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  Eigen::Vector3d half = Eigen::Vector3d::Ones();

  // Signed distance of p (negative inside), closest surface point and the
  // outward direction there: the reference, by clamping in the box frame.
  double signed_distance(const Eigen::Vector3d& p, Eigen::Vector3d* surface, Eigen::Vector3d* normal) const {
    const Eigen::Vector3d local = pose.inverse() * p;
    const Eigen::Vector3d clamped = local.cwiseMax(-half).cwiseMin(half);
    if ((local - clamped).norm() > 0.0) {
      *surface = pose * clamped;
      *normal = (p - *surface).normalized();
      return (local - clamped).norm();
    }
    Eigen::Index axis = 0;
    (half - local.cwiseAbs()).minCoeff(&axis);
    Eigen::Vector3d n_local = Eigen::Vector3d::Zero();
    n_local[axis] = local[axis] >= 0 ? 1.0 : -1.0;
    Eigen::Vector3d on = local;
    on[axis] = n_local[axis] * half[axis];
    *surface = pose * on;
    *normal = pose.linear() * n_local;
    return -(half[axis] - std::abs(local[axis]));
  }
};

RuntimeHull hull_of(const OrientedBox& box) {
  std::vector<Eigen::Vector3d> corners;
  for (int i = 0; i < 8; ++i)
    corners.push_back(box.pose * Eigen::Vector3d((i & 1) ? box.half.x() : -box.half.x(),
                                                 (i & 2) ? box.half.y() : -box.half.y(),
                                                 (i & 4) ? box.half.z() : -box.half.z()));
  ConvexHullBuilder builder;
  Result<ConvexPolytope> p = builder.build(corners);
  EXPECT_TRUE(p.ok());
  return make_runtime_hull(p.value(), 0);
}

OrientedBox random_box(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), size(0.3, 2.0);
  OrientedBox b;
  b.pose = Eigen::Translation3d(100 * u(rng), 20 * u(rng), -50 * u(rng)) *
           Eigen::Quaterniond(Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng)).normalized());
  b.half = Eigen::Vector3d(size(rng), size(rng), size(rng));
  return b;
}

constexpr double kExact = 1e-9; // metre-sized shapes: nanometres

TEST(SphereContact, MatchesTheExactReferenceAtRandomPoses) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> u(-1.0, 1.0), radius(0.1, 1.0);
  int overlapping = 0, near_touching = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const OrientedBox box = random_box(rng);
    const RuntimeHull hull = hull_of(box);
    const double r = radius(rng);
    Eigen::Vector3d c = box.pose * Eigen::Vector3d(u(rng) * (box.half.x() + r), u(rng) * (box.half.y() + r),
                                                   u(rng) * (box.half.z() + r));
    if (trial % 4 == 0) { // near touching: put the surface just inside or outside the radius
      Eigen::Vector3d s, n;
      const double d = box.signed_distance(c, &s, &n);
      c += n * (r - d + (trial % 8 == 0 ? 1e-7 : -1e-7));
      ++near_touching;
    }
    Eigen::Vector3d surface, normal;
    const double d = box.signed_distance(c, &surface, &normal);
    const std::optional<Contact> contact = sphere_contact(hull, c, r);
    ASSERT_EQ(contact.has_value(), d <= r) << "trial " << trial << " d " << d << " r " << r;
    if (!contact) continue;
    ++overlapping;
    EXPECT_NEAR(contact->depth, r - d, kExact) << trial;
    EXPECT_NEAR(contact->normal.dot(normal), 1.0, 1e-9) << trial;
    EXPECT_NEAR((contact->point - surface).norm(), 0.0, 1e-7) << trial;
  }
  EXPECT_GT(overlapping, 500);
  EXPECT_GT(near_touching, 400);
}

// Capsules that do not pierce the box: the exact distance is the minimum
// over the axis of the point distance (convex along the axis: ternary
// search), independent of the hull code.
TEST(CapsuleContact, MatchesTheExactReferenceAtRandomPoses) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0), radius(0.1, 0.8);
  int compared = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    const OrientedBox box = random_box(rng);
    const RuntimeHull hull = hull_of(box);
    const double r = radius(rng);
    const Eigen::Vector3d mid = box.pose * Eigen::Vector3d(u(rng) * 2.5, u(rng) * 2.5, u(rng) * 2.5);
    const Eigen::Vector3d axis = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized() * (0.2 + std::abs(u(rng)));
    const Eigen::Vector3d a = mid - axis, b = mid + axis;
    Eigen::Vector3d s, n;
    const auto f = [&](double t) { return box.signed_distance(a + t * (b - a), &s, &n); };
    double lo = 0.0, hi = 1.0;
    for (int it = 0; it < 200; ++it) {
      const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
      if (f(m1) < f(m2))
        hi = m2;
      else
        lo = m1;
    }
    const double t = 0.5 * (lo + hi);
    const double d = f(t);
    if (d <= 1e-6) continue; // pierced or touching: not what this reference covers
    Eigen::Vector3d surface, normal;
    box.signed_distance(a + t * (b - a), &surface, &normal);
    const std::optional<Contact> contact = capsule_contact(hull, a, b, r);
    ASSERT_EQ(contact.has_value(), d <= r) << trial;
    if (!contact) continue;
    ++compared;
    EXPECT_NEAR(contact->depth, r - d, 1e-7) << trial;
    EXPECT_GT(contact->normal.dot(normal), 1.0 - 1e-6) << trial;
  }
  EXPECT_GT(compared, 100);
}

TEST(CapsuleContact, PiercingCapsuleIsPushedOutAlongTheShortestAxis) {
  OrientedBox box;
  box.half = Eigen::Vector3d(2.0, 0.5, 1.0);
  const RuntimeHull hull = hull_of(box);
  // Through the box along x, 0.2 above its centre: out through +y by 0.3 + r.
  const std::optional<Contact> c = capsule_contact(hull, {-5, 0.2, 0}, {5, 0.2, 0}, 0.25);
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->depth, 0.3 + 0.25, kExact);
  EXPECT_NEAR((c->normal - Eigen::Vector3d::UnitY()).norm(), 0.0, kExact);
}

TEST(BoxContact, RestingBoxOnABoxAndATiltedOne) {
  OrientedBox floor;
  floor.pose.translation() = Eigen::Vector3d(0, -1, 0);
  floor.half = Eigen::Vector3d(5, 1, 5);
  const RuntimeHull hull = hull_of(floor);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(1, 0.4, -2);
  const std::optional<Contact> c = box_contact(hull, pose, Eigen::Vector3d(0.5, 0.5, 0.5));
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->depth, 0.1, kExact);
  EXPECT_NEAR((c->normal - Eigen::Vector3d::UnitY()).norm(), 0.0, kExact);
  // Tilted 45 degrees about z: its lowest edge is 0.5 * sqrt(2) below its centre.
  pose.linear() = Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(0, 0.6, 0);
  const std::optional<Contact> tilted = box_contact(hull, pose, Eigen::Vector3d(0.5, 0.5, 0.5));
  ASSERT_TRUE(tilted);
  EXPECT_NEAR(tilted->depth, 0.5 * std::sqrt(2.0) - 0.6, kExact);
  EXPECT_NEAR((tilted->normal - Eigen::Vector3d::UnitY()).norm(), 0.0, kExact);
  pose.translation() = Eigen::Vector3d(0, 0.8, 0);
  EXPECT_FALSE(box_contact(hull, pose, Eigen::Vector3d(0.5, 0.5, 0.5)));
}

TEST(RayHit, FacesEdgesVerticesGrazingAndFromInside) {
  OrientedBox unit;
  unit.pose.translation() = Eigen::Vector3d(0.5, 0.5, 0.5);
  unit.half = Eigen::Vector3d(0.5, 0.5, 0.5);
  const RuntimeHull hull = hull_of(unit);
  const auto hit = [&](const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
    return ray_hit(hull, o, d.normalized(), 100.0);
  };
  auto h = hit({-1, 0.5, 0.5}, {1, 0, 0});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, 1.0, kExact);
  EXPECT_NEAR((h->normal - Eigen::Vector3d(-1, 0, 0)).norm(), 0.0, kExact);
  h = hit({-1, -1, 0.5}, {1, 1, 0}); // an edge
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, std::sqrt(2.0), kExact);
  h = hit({-1, -1, -1}, {1, 1, 1}); // a vertex
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, std::sqrt(3.0), kExact);
  h = hit({-1, 1, 0.5}, {1, 0, 0}); // grazing the top face
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, 1.0, kExact);
  EXPECT_FALSE(hit({-1, 1.001, 0.5}, {1, 0, 0}));
  h = hit({0.5, 0.5, 0.7}, {1, 0, 0}); // from inside
  ASSERT_TRUE(h);
  EXPECT_EQ(h->t, 0.0);
  EXPECT_NEAR((h->normal - Eigen::Vector3d(0, 0, 1)).norm(), 0.0, kExact); // nearest facet
  EXPECT_FALSE(hit({-1, 0.5, 0.5}, {-1, 0, 0}));
  EXPECT_FALSE(ray_hit(hull, {-1, 0.5, 0.5}, {1, 0, 0}, 0.5)); // too short
}

// Reference for polytopes: the shape S overlaps hull H by the distance from
// the origin to the boundary of the Minkowski difference H - S, along that
// facet's normal (Qhull over every vertex difference; no separating axes).
struct Penetration {
  double depth;
  Eigen::Vector3d normal;
  bool unique; // the nearest facet is clearly nearest (normal well defined)
};
std::optional<Penetration> minkowski_reference(const std::vector<Eigen::Vector3d>& hull,
                                               const std::vector<Eigen::Vector3d>& shape) {
  std::vector<Eigen::Vector3d> differences;
  for (const Eigen::Vector3d& h : hull)
    for (const Eigen::Vector3d& s : shape) differences.push_back(h - s);
  ConvexHullBuilder builder;
  const Result<ConvexPolytope> m = builder.build(differences);
  EXPECT_TRUE(m.ok());
  double best = INFINITY, second = INFINITY;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (const Plane& p : m.value().planes) {
    if (p.offset < 0.0) return std::nullopt; // the origin is outside: apart
    if (p.offset < best) {
      second = best;
      best = p.offset;
      normal = p.normal;
    } else if (p.offset < second && (p.normal - normal).norm() > 1e-9) {
      second = p.offset;
    }
  }
  return Penetration{best, normal, second - best > 1e-6};
}

std::vector<Eigen::Vector3d> random_points(std::mt19937& rng, const Eigen::Vector3d& centre, double size) {
  std::normal_distribution<double> g(0.0, size);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 12; ++i) points.push_back(centre + Eigen::Vector3d(g(rng), g(rng), g(rng)));
  return points;
}

TEST(BoxAndConvexContact, MatchTheMinkowskiReferenceAtRandomPoses) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int boxes = 0, convexes = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const OrientedBox world_box = random_box(rng);
    const RuntimeHull hull = trial % 2 ? hull_of(world_box) : [&] {
      ConvexHullBuilder b;
      return make_runtime_hull(b.build(random_points(rng, world_box.pose.translation(), 1.0)).value(), 0);
    }();
    // A box query near the hull.
    Eigen::Isometry3d pose = world_box.pose;
    pose.translation() += Eigen::Vector3d(u(rng), u(rng), u(rng)) * 1.5;
    pose.linear() = Eigen::Quaterniond(Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng)).normalized()).toRotationMatrix();
    const Eigen::Vector3d half(0.2 + std::abs(u(rng)), 0.2 + std::abs(u(rng)), 0.2 + std::abs(u(rng)));
    std::vector<Eigen::Vector3d> box_corners;
    for (int i = 0; i < 8; ++i)
      box_corners.push_back(pose * Eigen::Vector3d(i & 1 ? half.x() : -half.x(), i & 2 ? half.y() : -half.y(),
                                                   i & 4 ? half.z() : -half.z()));
    const auto expected = minkowski_reference(hull.shape.vertices, box_corners);
    const std::optional<Contact> got = box_contact(hull, pose, half);
    if (expected && expected->depth > 1e-9) {
      ASSERT_TRUE(got) << trial;
      EXPECT_NEAR(got->depth, expected->depth, 1e-9) << trial;
      if (expected->unique) {
        EXPECT_NEAR((got->normal - expected->normal).norm(), 0.0, 1e-6) << trial;
      }
      ++boxes;
    } else if (!expected) {
      EXPECT_FALSE(got) << trial;
    }
    // A convex query shape near the hull.
    ConvexHullBuilder builder;
    const RuntimeHull shape = make_runtime_hull(
        builder.build(random_points(rng, world_box.pose * Eigen::Vector3d(u(rng), u(rng), u(rng)), 0.5)).value(), 0);
    const auto expected_convex = minkowski_reference(hull.shape.vertices, shape.shape.vertices);
    const std::optional<Contact> got_convex = convex_contact(hull, shape);
    if (expected_convex && expected_convex->depth > 1e-9) {
      ASSERT_TRUE(got_convex) << trial;
      EXPECT_NEAR(got_convex->depth, expected_convex->depth, 1e-9) << trial;
      if (expected_convex->unique) {
        EXPECT_NEAR((got_convex->normal - expected_convex->normal).norm(), 0.0, 1e-6) << trial;
      }
      ++convexes;
    } else if (!expected_convex) {
      EXPECT_FALSE(got_convex) << trial;
    }
  }
  EXPECT_GT(boxes, 100);
  EXPECT_GT(convexes, 100);
}

// A unit cube whose top is two triangles in one plane, the one listed
// first not under the point: both are equally far below it, and the point
// is over the second's inside, so the closest hull point is its foot there,
// not on the diagonal between them (0.61 away instead of 0.5).
TEST(ClosestToPoint, AFootOverTheTwinOfTheFrontFacetIsFound) {
  ConvexPolytope cube;
  for (int i = 0; i < 8; ++i) cube.vertices.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  cube.facets = {{4, 5, 7}, {4, 7, 6}, {0, 2, 3, 1}, {0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}};
  const Eigen::Vector3d normals[] = {{0, 0, 1}, {0, 0, 1}, {0, 0, -1}, {-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}};
  const double offsets[] = {1, 1, 0, 0, 1, 0, 1};
  for (int f = 0; f < 7; ++f) cube.planes.push_back({normals[f], offsets[f]});
  const RuntimeHull hull = make_runtime_hull(cube, 0);
  const Eigen::Vector3d p(0.25, 0.75, 1.5), foot(0.25, 0.75, 1.0);
  const ClosestPoints c = closest_to_point(hull, p);
  EXPECT_DOUBLE_EQ(c.distance, 0.5);
  EXPECT_NEAR((c.on_hull - foot).norm(), 0.0, 1e-15);
  const std::optional<Contact> contact = sphere_contact(hull, p, 0.6);
  ASSERT_TRUE(contact);
  EXPECT_NEAR(contact->depth, 0.1, 1e-15);
  EXPECT_NEAR((contact->normal - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-15);
  EXPECT_FALSE(sphere_touches(hull, p, 0.45));
  EXPECT_TRUE(sphere_touches(hull, p, 0.55));
}

// The closest hull point to points all round random solid hulls and flat
// polygons, against the distance to the hull's facets fanned into
// triangles (geometry's own reference, computed triangle by triangle): the
// search skips facets whose foot cannot be the nearest and compares edges
// by squared distance, and must still find the nearest point everywhere.
TEST(ClosestToPoint, EqualsTheFacetFansDistanceRoundRandomHulls) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int solids = 0, flats = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Eigen::Vector3d centre(40 * u(rng), 40 * u(rng), 40 * u(rng));
    const std::vector<Eigen::Vector3d> points = random_points(rng, centre, 1.0);
    const bool flat = trial % 3 == 0;
    ConvexPolytope shape;
    if (flat) { // a polygon of the points projected onto a tilted plane
      std::vector<int> ids(points.size());
      for (size_t k = 0; k < ids.size(); ++k) ids[k] = static_cast<int>(k);
      shape = flat_polytope(make_flat_polygon(points, ids, Eigen::Vector3d(0.3, -0.5, 1.0).normalized(), 1e-9), true);
    } else {
      ConvexHullBuilder builder;
      const Result<ConvexPolytope> built = builder.build(points);
      ASSERT_TRUE(built.ok()) << trial;
      shape = built.value();
    }
    const RuntimeHull hull = make_runtime_hull(shape, 0);
    (flat ? flats : solids) += 1;
    for (int i = 0; i < 40; ++i) {
      const Eigen::Vector3d p = centre + Eigen::Vector3d(u(rng), u(rng), u(rng)) * 3.0;
      const ClosestPoints c = closest_to_point(hull, p);
      if (c.distance == 0.0) continue; // inside
      const double reference = distance_to_facet_fans(hull.shape, p);
      EXPECT_NEAR(c.distance, reference, kExact) << "trial " << trial << ", point " << i;
      EXPECT_NEAR((c.on_hull - p).norm(), c.distance, kExact) << "trial " << trial << ", point " << i;
      // The point found is on the hull: behind or on every plane.
      for (const Plane& plane : hull.shape.planes) EXPECT_LE(plane.signed_distance(c.on_hull), kExact);
      // Sphere tests agree with it on both sides of the radius.
      EXPECT_TRUE(sphere_touches(hull, p, reference + kExact)) << trial;
      EXPECT_FALSE(sphere_touches(hull, p, reference - kExact)) << trial;
    }
  }
  EXPECT_GT(solids, 150);
  EXPECT_GT(flats, 50);
}

} // namespace
} // namespace hullcover::bvh
