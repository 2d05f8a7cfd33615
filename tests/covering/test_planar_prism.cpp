// The prism a planar patch becomes (planar_prism.h): beveled_side_planes,
// allowed_prism_thickness and prism_polytope on seeded random scenes built
// in code: a convex polygon (a triangle fan, the patch) in a random plane,
// with random faces around and behind it, a face leaving one of its edges
// downward (what bevels are for) and a face parallel behind it.
//
// The prism replaces the polygon as a solid, so it must swallow nothing:
// its thickness stays within the cap, and no point of a face outside the
// patch (vertices and points sampled over each face) nor of a bar lies
// deeper than tol inside it, checked by brute force over the scene. Its top
// facet is the polygon itself; it stays within the polygon's column. A face
// right behind the polygon at depth d limits the thickness to d, and one
// coincident with the polygon facing into it (back-to-back walls) to 0.

#include "covering_fixture.h"
#include "validity/planar_prism.h"
#include "indexed_scene.h"

#include "hullcover/mesh/prepared_mesh.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>

namespace hullcover {
namespace {

using V = Eigen::Vector3d;
constexpr double kPrismTol = 1e-3;
// A prism thinner than this is made flat (planar_prism.cpp).
constexpr double kMinThickness = kMinPrismThicknessInTolerances * kPrismTol;

using test::add_triangle;
using test::random_unit;

// The patch: a fan over `corners` corners on a circle (angles jittered) in
// the plane of `frame`, counter-clockwise seen from its normal. Its faces
// are the mesh's first corners - 2.
struct Scene {
  Mesh mesh;
  PlaneFrame frame;
  int patch_faces = 0;
  V world(double x, double y, double depth) const {
    return frame.origin + x * frame.u + y * frame.v - depth * frame.normal;
  }
};

Scene patch_scene(std::mt19937& rng) {
  std::uniform_real_distribution<double> sym(-1.0, 1.0), unit(0.0, 1.0);
  Scene s;
  s.frame = PlaneFrame::from_normal(V(sym(rng), sym(rng), sym(rng)), random_unit(rng));
  const int corners = std::uniform_int_distribution<int>(3, 8)(rng);
  const double radius = 0.6 + 0.4 * unit(rng);
  for (int i = 0; i < corners; ++i) {
    const double angle = 2.0 * M_PI * (i + 0.3 * sym(rng)) / corners;
    s.mesh.positions.push_back(s.world(radius * std::cos(angle), radius * std::sin(angle), 0.0));
  }
  for (int i = 1; i + 1 < corners; ++i) {
    s.mesh.triangles.emplace_back(0, i, i + 1);
    s.mesh.material_ids.push_back(0);
  }
  s.patch_faces = corners - 2;
  return s;
}

// A triangle at depth `depth` behind the polygon, parallel to it and so
// much wider that its edges and their bars stay out of the polygon's column,
// facing towards the polygon or away.
void add_parallel_face(Scene& s, double depth, bool facing_polygon) {
  const V a = s.world(-5, -5, depth), b = s.world(10, -5, depth), c = s.world(-5, 10, depth);
  if (facing_polygon)
    add_triangle(s.mesh, a, b, c); // counter-clockwise from the normal
  else
    add_triangle(s.mesh, a, c, b);
}

struct Prism {
  std::unique_ptr<test::IndexedScene> scene;
  FlatPolygon polygon;
  std::vector<Plane> sides;
  double allowed = 0.0; // allowed_prism_thickness
  double used = 0.0;    // what prism_polytope used
  ConvexPolytope polytope;
};

Prism build_prism(const Scene& s, double cap, ValidityMode mode = ValidityMode::paper, double bar_half_length = 0.2) {
  Prism p;
  p.scene = std::make_unique<test::IndexedScene>(prepare_mesh(s.mesh, kPrismTol).value(),
                                                 BarOptions{bar_half_length, false, mode, 0.5});
  std::vector<int> patch_vertices;
  for (int f = 0; f < s.patch_faces; ++f)
    for (int k = 0; k < 3; ++k) patch_vertices.push_back(p.scene->prepared.mesh.triangles[f][k]);
  p.polygon = make_flat_polygon(p.scene->prepared.mesh.positions, patch_vertices, s.frame.normal, kPrismTol);
  const int patch_faces = s.patch_faces;
  const auto in_patch = [patch_faces](int f) { return f < patch_faces; };
  std::vector<int> scratch;
  p.sides = beveled_side_planes(p.scene->index, p.polygon, in_patch, scratch);
  p.allowed = allowed_prism_thickness(p.scene->index, p.polygon, p.sides, in_patch, cap, scratch);
  p.used = p.allowed;
  ConvexHullBuilder hulls;
  p.polytope = prism_polytope(p.polygon, p.sides, p.used, kPrismTol, hulls);
  return p;
}

double depth_inside(const ConvexPolytope& prism, const V& x) {
  double outside = -std::numeric_limits<double>::infinity();
  for (const Plane& plane : prism.planes) outside = std::max(outside, plane.normal.dot(x) - plane.offset);
  return -outside;
}

// The prism's top facet is the polygon: its plane, and its corners (with
// their mesh vertex ids), counter-clockwise from the front.
void expect_top_is_polygon(const Prism& p) {
  const FlatPolygon& polygon = p.polygon;
  int tops = 0;
  for (size_t f = 0; f < p.polytope.facets.size(); ++f) {
    const Plane& plane = p.polytope.planes[f];
    if (plane.normal.dot(polygon.plane.normal) < 1.0 - 1e-9) continue;
    ++tops;
    EXPECT_NEAR(plane.offset, polygon.plane.offset, 1e-9);
    const std::vector<int>& facet = p.polytope.facets[f];
    ASSERT_EQ(facet.size(), polygon.corners.size());
    V newell = V::Zero();
    for (size_t i = 0; i < facet.size(); ++i) {
      newell += p.polytope.vertices[facet[i]].cross(p.polytope.vertices[facet[(i + 1) % facet.size()]]);
      size_t match = 0;
      while (match < polygon.corners.size() && (polygon.corners[match] - p.polytope.vertices[facet[i]]).norm() > 1e-9)
        ++match;
      ASSERT_LT(match, polygon.corners.size()) << "top vertex not a polygon corner";
      EXPECT_EQ(p.polytope.vertex_ids[facet[i]], polygon.corner_vertices[match]);
    }
    EXPECT_GT(newell.dot(polygon.plane.normal), 0.0);
  }
  EXPECT_EQ(tops, 1);
}

TEST(PlanarPrism, SwallowsNothingOnRandomScenes) {
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> sym(-1.0, 1.0), unit(0.0, 1.0);
  int solid = 0, beveled = 0, limited = 0;
  const int trials = 80;
  for (int trial = 0; trial < trials; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    Scene s = patch_scene(rng);
    const int corners = s.patch_faces + 2;
    // Clutter: random triangles around and behind the polygon.
    for (int i = std::uniform_int_distribution<int>(0, 4)(rng); i > 0; --i) {
      std::vector<V> t;
      for (int k = 0; k < 3; ++k) t.push_back(s.world(1.4 * sym(rng), 1.4 * sym(rng), 0.4 - 1.6 * unit(rng)));
      add_triangle(s.mesh, t[0], t[1], t[2]);
    }
    // A face leaving a patch edge downward (sharing it, wound against it).
    if (unit(rng) < 0.7) {
      const int i = std::uniform_int_distribution<int>(0, corners - 1)(rng);
      const V& a = s.mesh.positions[i];
      const V& b = s.mesh.positions[(i + 1) % corners];
      const V outward = (b - a).cross(s.frame.normal).normalized();
      const double depth = 0.05 + 0.5 * unit(rng);
      const V c = 0.5 * (a + b) - depth * s.frame.normal + depth * (1.5 * unit(rng) - 0.5) * -outward;
      s.mesh.positions.push_back(c);
      s.mesh.triangles.emplace_back((i + 1) % corners, i, static_cast<int>(s.mesh.positions.size()) - 1);
      s.mesh.material_ids.push_back(0);
    }
    if (unit(rng) < 0.5) add_parallel_face(s, 1.2 * unit(rng), unit(rng) < 0.5);
    const double cap = 0.1 + 0.7 * unit(rng);
    const ValidityMode mode = trial % 2 == 0 ? ValidityMode::paper : ValidityMode::exact;
    const Prism p = build_prism(s, cap, mode);
    ASSERT_EQ(p.polygon.corners.size(), static_cast<size_t>(corners));

    EXPECT_GE(p.allowed, 0.0);
    EXPECT_LE(p.allowed, cap);
    EXPECT_TRUE(p.allowed == 0.0 || p.allowed >= kMinThickness) << p.allowed;
    EXPECT_GE(p.used, 0.0);
    EXPECT_LE(p.used, p.allowed);
    solid += p.used > 0.0;
    limited += p.allowed < cap;
    for (size_t i = 0; i < p.sides.size(); ++i)
      beveled += p.sides[i].normal.dot(p.polygon.sides[i].normal) < 1.0 - 1e-12;
    if (p.used == 0.0) {
      EXPECT_EQ(p.polytope.facets.size(), 2u);
      continue;
    }
    expect_top_is_polygon(p);
    // Within the polygon's column and between its plane and the bottom.
    for (const V& v : p.polytope.vertices) {
      EXPECT_LE(deepest_signed_distance(p.polygon.sides, v), 1e-9);
      EXPECT_LE(p.polygon.plane.signed_distance(v), 1e-9);
      EXPECT_GE(p.polygon.plane.signed_distance(v), -p.used - 1e-9);
    }
    // Brute force: nothing outside the patch deeper than tol inside.
    const Mesh& mesh = p.scene->prepared.mesh;
    for (int f = s.patch_faces; f < static_cast<int>(mesh.triangles.size()); ++f) {
      const V& a = mesh.positions[mesh.triangles[f][0]];
      const V& b = mesh.positions[mesh.triangles[f][1]];
      const V& c = mesh.positions[mesh.triangles[f][2]];
      for (int i = 0; i <= 12; ++i)
        for (int j = 0; i + j <= 12; ++j) {
          const V x = a + (b - a) * (i / 12.0) + (c - a) * (j / 12.0);
          ASSERT_LE(depth_inside(p.polytope, x), kPrismTol) << "face " << f << " at " << i << "," << j;
        }
    }
    for (const BoundaryBar& bar : p.scene->index.bars)
      for (int i = 0; i <= 40; ++i)
        for (int j = 0; j <= (bar.is_sheet() ? 10 : 0); ++j) {
          const V x = bar.a + (bar.b - bar.a) * (i / 40.0) + bar.along * (j / 10.0);
          ASSERT_LE(depth_inside(p.polytope, x), kPrismTol) << "bar of edge " << bar.edge;
        }
  }
  // The scenes should exercise every branch.
  EXPECT_GT(solid, trials / 4);
  EXPECT_GT(beveled, trials / 5);
  EXPECT_GT(limited, trials / 4);
}

TEST(PlanarPrism, NothingNearGivesTheCapWithVerticalSides) {
  std::mt19937 rng(42);
  for (int trial = 0; trial < 20; ++trial) {
    const Scene s = patch_scene(rng);
    const double cap = 0.05 + 0.5 * std::uniform_real_distribution<double>(0.0, 1.0)(rng);
    const Prism p = build_prism(s, cap);
    EXPECT_EQ(p.allowed, cap);
    EXPECT_EQ(p.used, cap);
    expect_top_is_polygon(p);
    double area = 0.0;
    const std::vector<V>& c = p.polygon.corners;
    for (size_t i = 1; i + 1 < c.size(); ++i) area += 0.5 * (c[i] - c[0]).cross(c[i + 1] - c[0]).norm();
    EXPECT_NEAR(polytope_volume(p.polytope), area * cap, 1e-9);
  }
}

// A face leaving a polygon edge downward and inward, less steeply than the
// bevel cap allows: the side is tilted past it, so it does not limit the
// prism, and stays outside it.
TEST(PlanarPrism, BevelKeepsTheCapBesideAFaceLeavingAnEdgeInward) {
  std::mt19937 rng(45);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double cap = 0.3;
  for (int trial = 0; trial < 30; ++trial) {
    Scene s = patch_scene(rng);
    const int corners = s.patch_faces + 2;
    const int i = trial % corners;
    const V a = s.mesh.positions[i];
    const V b = s.mesh.positions[(i + 1) % corners];
    const V inward = s.frame.normal.cross(b - a).normalized();
    // Run per depth under 10 / 1.05; deep enough that the bars of its
    // other (open) edges stay below the prism.
    const double depth = 0.8 + 0.7 * unit(rng), slope = 0.05 + 0.25 * unit(rng);
    const V c = 0.5 * (a + b) - depth * s.frame.normal + slope * depth * inward;
    s.mesh.positions.push_back(c);
    s.mesh.triangles.emplace_back((i + 1) % corners, i, static_cast<int>(s.mesh.positions.size()) - 1);
    s.mesh.material_ids.push_back(0);
    const Prism p = build_prism(s, cap, ValidityMode::paper, 0.05);
    EXPECT_EQ(p.allowed, cap) << "trial " << trial;
    size_t j = 0; // the polygon's edge from a (its corners start elsewhere)
    while (j < p.polygon.corners.size() && (p.polygon.corners[j] - a).norm() > 1e-9) ++j;
    ASSERT_LT(j, p.polygon.corners.size());
    EXPECT_LT(p.sides[j].normal.dot(p.polygon.sides[j].normal), 1.0 - 1e-6) << "edge " << j << " not beveled";
    for (int k = 0; k <= 20; ++k) EXPECT_LE(depth_inside(p.polytope, a + (c - a) * (k / 20.0)), kPrismTol);
  }
}

TEST(PlanarPrism, FaceBehindAtDepthDLimitsTheThicknessToD) {
  std::mt19937 rng(43);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double cap = 0.5;
  for (int trial = 0; trial < 30; ++trial) {
    Scene s = patch_scene(rng);
    const double d = 3.0 * kPrismTol + (cap - 3.0 * kPrismTol) * unit(rng);
    add_parallel_face(s, d, trial % 2 == 0);
    const Prism p = build_prism(s, cap);
    EXPECT_NEAR(p.allowed, d, 1e-9) << "trial " << trial;
    EXPECT_LE(p.used, d + 1e-9);
    expect_top_is_polygon(p);
  }
  // Thinner than kMinThickness: flat.
  Scene s = patch_scene(rng);
  add_parallel_face(s, 0.75 * kMinThickness, true);
  EXPECT_EQ(build_prism(s, cap).allowed, 0.0);
}

TEST(PlanarPrism, BackToBackCoincidentFaceGivesThicknessZero) {
  std::mt19937 rng(44);
  std::uniform_real_distribution<double> sym(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    for (bool facing_polygon : {false, true}) {
      Scene s = patch_scene(rng);
      add_parallel_face(s, 0.5 * kPrismTol * sym(rng), facing_polygon); // within tol of the polygon's plane
      const Prism p = build_prism(s, 0.4);
      if (facing_polygon) {
        // Its normal points away from the prism: a second copy of the
        // patch's side, harmless.
        EXPECT_EQ(p.allowed, 0.4);
        continue;
      }
      // Its front faces into where the prism would be: flat.
      EXPECT_EQ(p.allowed, 0.0) << "trial " << trial;
      EXPECT_EQ(p.used, 0.0);
      ASSERT_EQ(p.polytope.facets.size(), 2u);
      EXPECT_EQ(p.polytope.vertices, p.polygon.corners);
      EXPECT_EQ(p.polytope.planes[0].normal, p.polygon.plane.normal);
    }
  }
}

// How deep a prism may reach before its box meets another island's zone
// (a prism stops short of a zone of a smaller tolerance, patch_hulls.cpp):
// where the last axis's interval of the growing box reaches the zone's.
TEST(PlanarPrism, DepthBeforeABoxIsWhereThePrismsBoxFirstMeetsIt) {
  const auto polygon = [](const std::vector<V>& corners, const V& normal) {
    FlatPolygon p;
    p.corners = corners;
    p.plane = Plane{normal.normalized(), normal.normalized().dot(corners[0])};
    return p;
  };
  const Aabb behind{V(-3, 0.2, 0.2), V(-2, 0.8, 0.8)}, beside{V(-3, 2, 0), V(-2, 3, 1)};
  const Aabb touching{V(-0.5, 0.5, 0.5), V(0.5, 2, 2)};
  const FlatPolygon facing_x = polygon({V(0, 0, 0), V(0, 1, 0), V(0, 1, 1), V(0, 0, 1)}, V(1, 0, 0));
  EXPECT_DOUBLE_EQ(depth_before_box(facing_x, behind), 2.0);
  EXPECT_EQ(depth_before_box(facing_x, beside), std::numeric_limits<double>::infinity());
  EXPECT_EQ(depth_before_box(facing_x, touching), 0.0);
  // Tilted, the box of the prism grows along x and y at once: a zone beside
  // the column (y below it) is met once both axes reach it.
  const FlatPolygon tilted = polygon({V(0, 0, 0), V(-1, 1, 0), V(-1, 1, 1), V(0, 0, 1)}, V(1, 1, 0));
  const Aabb below{V(-5, -0.5, 0), V(-4, -0.2, 1)};
  EXPECT_NEAR(depth_before_box(tilted, below), 3.0 * std::sqrt(2.0), 1e-12);
}

} // namespace
} // namespace hullcover
