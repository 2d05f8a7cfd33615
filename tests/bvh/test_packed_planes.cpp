// The packed plane store (bvh/src/packed_planes.h): a settled float
// verdict is never the opposite of the exact test's, and the store's exact
// ray hit is ray_hit's, on boxes,
// turned boxes and flat polygons, near the origin and far from it, with
// shapes placed at knife-edge gaps as well as at random.

#include "box_hulls.h"
#include "hullcover/bvh/hull_contact.h"

#include "float4.h" // private to bvh
#include "packed_planes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace hullcover::bvh {
namespace {

using V = Eigen::Vector3d;
using detail::FloatVerdict;

// Hulls of the kinds a covering holds, all about `offset`: a box, a turned
// box, and a flat triangle (front, back and side planes).
std::vector<RuntimeHull> hulls_about(const V& offset) {
  std::vector<RuntimeHull> hulls;
  hulls.push_back(test::box_hull(offset + V(0, 0, 0), offset + V(2, 1, 3)));
  Eigen::Isometry3d turned = Eigen::Isometry3d::Identity();
  turned.translation() = offset + V(5, 0, 0);
  turned.linear() = Eigen::AngleAxisd(0.7, V(1, 2, 3).normalized()).toRotationMatrix();
  hulls.push_back(placed_box(turned, V(1.0, 0.5, 0.25)));
  hulls.push_back(flat_triangle_hull(offset + V(0, 4, 0), offset + V(3, 4, 0.5), offset + V(1, 4.5, 2)));
  return hulls;
}

// Points at random around a hull, and at knife-edge gaps from its surface
// along a facet's normal (a sphere of `radius` then just touches or just
// misses).
std::vector<V> points_near(const RuntimeHull& hull, double radius, std::mt19937& rng) {
  std::vector<V> points;
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const V mid = 0.5 * (hull.box.min + hull.box.max);
  const double size = (hull.box.max - hull.box.min).norm();
  for (int i = 0; i < 300; ++i) points.push_back(mid + V(u(rng), u(rng), u(rng)) * (size + 2.0 * radius));
  const double gaps[] = {0.0, 1e-12, -1e-12, 1e-9, -1e-9, 1e-6, -1e-6, 1e-3, -1e-3};
  for (size_t f = 0; f < hull.shape.facets.size(); ++f) {
    const V& n = hull.shape.planes[f].normal;
    for (int corner : hull.shape.facets[f]) {
      const V on = 0.7 * hull.shape.vertices[corner] + 0.3 * mid;
      const V foot = on - hull.shape.planes[f].signed_distance(on) * n;
      for (double gap : gaps) points.push_back(foot + (radius + gap * (1.0 + size)) * n);
    }
  }
  return points;
}

TEST(PackedPlanes, SettledVerdictsAreTheExactTests) {
  std::mt19937 rng(31);
  int settled_apart = 0, settled_meets = 0, unsure = 0, rays_hit = 0;
  for (const double far : {0.0, 1e5, 1e7}) {
    const std::vector<RuntimeHull> hulls = hulls_about(V::Constant(far));
    const detail::PackedPlanes planes(hulls);
    for (size_t h = 0; h < hulls.size(); ++h)
      for (const double radius : {0.0, 0.05, 0.5, 2.0}) {
        const std::vector<V> points = points_near(hulls[h], radius, rng);
        for (size_t i = 0; i < points.size(); ++i) {
          const V& p = points[i];
          const FloatVerdict sphere = planes.sphere(static_cast<int>(h), p, radius);
          if (sphere != FloatVerdict::unsure) {
            EXPECT_EQ(sphere == FloatVerdict::meets, sphere_touches(hulls[h], p, radius))
                << "sphere, hull " << h << " at " << far << ", radius " << radius << ", point " << i;
          }
          settled_apart += sphere == FloatVerdict::apart;
          settled_meets += sphere == FloatVerdict::meets;
          unsure += sphere == FloatVerdict::unsure;
          const V b = points[(i * 7 + 3) % points.size()];
          const FloatVerdict capsule = planes.segment(static_cast<int>(h), p, b, radius);
          if (capsule != FloatVerdict::unsure) {
            EXPECT_EQ(capsule == FloatVerdict::meets, capsule_touches(hulls[h], p, b, radius))
                << "capsule, hull " << h << " at " << far << ", radius " << radius << ", point " << i;
          }
          // Rays from the point towards another: the store's exact hit, on
          // its own copy of the planes, is ray_hit's, bit for bit.
          if ((b - p).norm() == 0.0) continue;
          const V dir = (b - p).normalized();
          const double reach = 3.0 * (b - p).norm();
          const std::optional<RayHit> packed = planes.ray_hit(static_cast<int>(h), p, dir, reach);
          const std::optional<RayHit> hit = ray_hit(hulls[h], p, dir, reach);
          ASSERT_EQ(packed.has_value(), hit.has_value()) << "ray, hull " << h << " at " << far << ", point " << i;
          rays_hit += hit.has_value();
          if (hit) {
            EXPECT_EQ(packed->t, hit->t);
            EXPECT_EQ(packed->point, hit->point);
            EXPECT_EQ(packed->normal, hit->normal);
          }
        }
      }
  }
  // The tests settle most cases, so they are tested, and leave some near
  // ones to the exact test.
  EXPECT_GT(settled_apart, 1000);
  EXPECT_GT(settled_meets, 500);
  EXPECT_GT(unsure, 100);
  EXPECT_GT(rays_hit, 500);
}

// A hull whose planes are stored with normals of another length (the same
// half-spaces) gets no float test: the bounds and the foot of a point on a
// plane take normals as unit.
TEST(PackedPlanes, NonUnitNormalsAreLeftToTheExactTests) {
  RuntimeHull hull = test::box_hull(V(0, 0, 0), V(10, 10, 10));
  for (Plane& plane : hull.shape.planes) {
    plane.normal *= 1.5;
    plane.offset *= 1.5;
  }
  const detail::PackedPlanes planes({hull});
  std::mt19937 rng(43);
  for (const V& p : points_near(hull, 1.0, rng)) {
    EXPECT_EQ(planes.sphere(0, p, 1.0), FloatVerdict::unsure);
    EXPECT_EQ(planes.segment(0, p, p + V(1, 2, 3), 1.0), FloatVerdict::unsure);
  }
}

// The outward rounding every float box and bound rests on: the float at or
// below (above) x, and the next one up (down) is beyond x.
TEST(FloatRounding, AtOrBelowAndAboveAreTheNearestFloatsOutward) {
  using detail::float_at_or_above;
  using detail::float_at_or_below;
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-140, 127);
  std::vector<double> xs = {0.0,
                            -0.0,
                            1.0,
                            -1.0,
                            1e7 + 0.5,
                            -(1e7 + 0.5),
                            1e-45,
                            -1e-45,
                            1e-300,
                            -1e-300,
                            static_cast<double>(std::numeric_limits<float>::max()),
                            -static_cast<double>(std::numeric_limits<float>::max())};
  for (int i = 0; i < 20000; ++i) xs.push_back(std::ldexp(mantissa(rng), exponent(rng)));
  constexpr float kInf = std::numeric_limits<float>::infinity();
  for (const double x : xs) {
    const float below = float_at_or_below(x), above = float_at_or_above(x);
    EXPECT_LE(static_cast<double>(below), x) << x;
    EXPECT_GE(static_cast<double>(above), x) << x;
    EXPECT_GT(static_cast<double>(std::nextafter(below, kInf)), x) << x;
    EXPECT_LT(static_cast<double>(std::nextafter(above, -kInf)), x) << x;
  }
  EXPECT_EQ(float_at_or_below(1e7 + 0.5), 1e7f);
  EXPECT_EQ(float_at_or_above(1e7 + 0.5), 1e7f + 1.0f);
  EXPECT_EQ(float_at_or_below(1e300), std::numeric_limits<float>::max());
  EXPECT_EQ(float_at_or_below(-1e300), -kInf);
}

} // namespace
} // namespace hullcover::bvh
