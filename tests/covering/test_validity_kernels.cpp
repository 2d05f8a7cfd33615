// The paper's four validity conditions (validity_conditions.h), each called
// directly on small seeded random scenes built in code, against a verdict
// worked out here from how the scene was built:
//  1. check_solid_hull on a randomly placed and rotated box hull and a closed
//     tetrahedron (no bars): vertex_inside, edge_inside or valid exactly as a
//     slab test in the box's own frame says, with "strictly inside" meaning
//     deeper than tol;
//  2. planes_support_points against a brute-force loop;
//  3. a boundary bar through a hull is bar_inside, through a flat polygon's
//     interior bar_crosses_polygon; a bar stopping short is valid;
//  4. a face below a flat polygon touching its interior is face_below_polygon;
//     one lowered by 2 tol, beside the polygon, above it or in the patch is not.
// These kernels decide what the decomposer may merge; a wrong verdict either
// swallows geometry or splits hulls needlessly.

#include "covering_fixture.h"
#include "indexed_scene.h"
#include "validity/validity_conditions.h"

#include "hullcover/covering/convex_hull_3d.h"
#include "hullcover/mesh/prepared_mesh.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <memory>
#include <random>

namespace hullcover {
namespace {

using V = Eigen::Vector3d;
constexpr double kTol = 1e-3;

std::unique_ptr<test::IndexedScene> indexed(const Mesh& m, double bar_half_length) {
  auto out = test::index_scene(m, kTol, {bar_half_length, false, ValidityMode::paper, 1.0});
  EXPECT_EQ(out->prepared.tolerance.length, kTol);
  return out;
}

using test::add_triangle;
using test::random_unit;

// A closed tetrahedron of size 0.1 at `where`, far from the rest: a scene
// of one small triangle has a tiny diagonal, and bars are indexed in pieces
// of diagonal / 64.
void add_anchor(Mesh& m, const V& where) {
  const int base = static_cast<int>(m.positions.size());
  m.positions.insert(m.positions.end(), {where, where + V(0.1, 0, 0), where + V(0, 0.1, 0), where + V(0, 0, 0.1)});
  for (const Eigen::Vector3i& t :
       {Eigen::Vector3i(0, 2, 1), Eigen::Vector3i(0, 1, 3), Eigen::Vector3i(1, 2, 3), Eigen::Vector3i(0, 3, 2)}) {
    m.triangles.push_back(t + Eigen::Vector3i::Constant(base));
    m.material_ids.push_back(0);
  }
}

// The triangle whose edge mid -/+ l across has its midpoint at `mid` and
// whose third corner is mid + 2 l w; its corners are listed starting from
// `first`, so that edge's bar gets any index among the triangle's.
void add_triangle_on_edge(Mesh& m, const V& mid, const V& across, const V& w, double l, int first) {
  const V c[3] = {mid - l * across, mid + l * across, mid + 2.0 * l * w};
  add_triangle(m, c[first % 3], c[(first + 1) % 3], c[(first + 2) % 3]);
}

// A closed tetrahedron, faces wound outward: every edge manifold, no bars.
Mesh tetrahedron(V a, V b, V c, const V& d) {
  if ((b - a).cross(c - a).dot(d - a) > 0.0) std::swap(b, c); // d behind a-b-c
  Mesh m;
  m.positions = {a, b, c, d};
  m.triangles = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {0, 2, 3}};
  m.material_ids = {0, 0, 0, 0};
  return m;
}

// A box of half-sizes `half` at `centre`, rotated by `rotation`, as Qhull builds it.
struct BoxHull {
  Eigen::Matrix3d rotation;
  V centre, half;
  ConvexPolytope hull;
  V local(const V& p) const { return rotation.transpose() * (p - centre); }
  V world(const V& q) const { return centre + rotation * q; }
};

BoxHull random_box_hull(std::mt19937& rng, ConvexHullBuilder& qhull) {
  std::uniform_real_distribution<double> size(0.3, 1.0), u(-0.5, 0.5);
  std::normal_distribution<double> g(0.0, 1.0);
  BoxHull b;
  b.rotation = Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
  b.centre = V(u(rng), u(rng), u(rng));
  b.half = V(size(rng), size(rng), size(rng));
  std::vector<V> corners;
  for (int i = 0; i < 8; ++i)
    corners.push_back(b.world(V((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1).cwiseProduct(b.half)));
  b.hull = qhull.build(corners).value();
  return b;
}

// Reference for condition 1, in the box's frame: a point is strictly inside
// when deeper than tol behind every face; a segment enters when its clipped
// parameter interval against the box shrunk by tol is not empty.
bool strictly_inside(const BoxHull& b, const V& p) { return ((b.local(p).cwiseAbs() - b.half).array() < -kTol).all(); }
bool segment_enters(const BoxHull& b, const V& p, const V& q) {
  const V a = b.local(p), d = b.local(q) - a, inner = b.half - V::Constant(kTol);
  double enter = 0.0, leave = 1.0;
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0.0) {
      if (std::abs(a[k]) >= inner[k]) return false;
      continue;
    }
    const double s0 = (-inner[k] - a[k]) / d[k], s1 = (inner[k] - a[k]) / d[k];
    enter = std::max(enter, std::min(s0, s1));
    leave = std::min(leave, std::max(s0, s1));
  }
  return enter < leave;
}

Validity reference_condition_1(const BoxHull& b, const Mesh& m) {
  for (const V& p : m.positions)
    if (strictly_inside(b, p)) return Validity::vertex_inside;
  for (const Eigen::Vector3i& t : m.triangles)
    for (int k = 0; k < 3; ++k)
      if (segment_enters(b, m.positions[t[k]], m.positions[t[(k + 1) % 3]])) return Validity::edge_inside;
  return Validity::valid;
}

TEST(ValidityKernels, Condition1MatchesASlabTestOnRandomTetrahedra) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  ConvexHullBuilder qhull;
  std::vector<int> scratch;
  int seen[3] = {0, 0, 0};
  for (int trial = 0; trial < 300; ++trial) {
    const BoxHull b = random_box_hull(rng, qhull);
    const Mesh m = tetrahedron(V(u(rng), u(rng), u(rng)), V(u(rng), u(rng), u(rng)), V(u(rng), u(rng), u(rng)),
                               V(u(rng), u(rng), u(rng)));
    const auto s = indexed(m, 0.1);
    ASSERT_TRUE(s->index.bars.empty());
    const Validity expected = reference_condition_1(b, m);
    ++seen[expected == Validity::valid ? 0 : expected == Validity::vertex_inside ? 1 : 2];
    ASSERT_EQ(check_solid_hull(s->index, b.hull, scratch), expected) << "trial " << trial;
  }
  for (int count : seen) EXPECT_GE(count, 30) << "each verdict should be exercised";
}

TEST(ValidityKernels, Condition1TargetedPlacements) {
  std::mt19937 rng(32);
  std::uniform_real_distribution<double> unit(0.0, 1.0), sym(-1.0, 1.0);
  ConvexHullBuilder qhull;
  std::vector<int> scratch;
  for (int trial = 0; trial < 40; ++trial) {
    const BoxHull b = random_box_hull(rng, qhull);
    const double far = 4.0 * b.half.norm();
    // A vertex strictly inside (the rest far out): vertex_inside.
    const V inside = b.world(b.half.cwiseProduct(V(sym(rng), sym(rng), sym(rng))) * 0.95);
    const Mesh poking = tetrahedron(inside, b.world(V(far, 0, 0)), b.world(V(0, far, 0)), b.world(V(0, 0, far)));
    EXPECT_EQ(check_solid_hull(indexed(poking, 0.1)->index, b.hull, scratch), Validity::vertex_inside);

    // Only an edge through: its ends beyond the box on a line through two
    // interior points; the other corners far out on one side.
    const V p = b.world(b.half.cwiseProduct(V(sym(rng), sym(rng), sym(rng))) * 0.9);
    const V q = b.world(b.half.cwiseProduct(V(sym(rng), sym(rng), sym(rng))) * 0.9);
    const V dir = (q - p).normalized();
    const V side = b.world(V(0, 0, far)) - b.centre;
    const Mesh through = tetrahedron(p - far * dir, q + far * dir, b.centre + side + 0.3 * far * dir,
                                     b.centre + side - 0.2 * far * dir + 0.3 * side.cross(dir));
    for (const V& v : through.positions) ASSERT_FALSE(strictly_inside(b, v));
    EXPECT_EQ(check_solid_hull(indexed(through, 0.1)->index, b.hull, scratch), Validity::edge_inside);

    // A corner on a random face at depth `depth`, the rest beyond that face:
    // inside only when deeper than tol.
    const int axis = trial % 3;
    const double sign = unit(rng) < 0.5 ? -1.0 : 1.0;
    for (double depth : {-3.0 * kTol, 0.0, 0.5 * kTol, 2.0 * kTol}) {
      V on_face = b.half.cwiseProduct(V(sym(rng), sym(rng), sym(rng))) * 0.8;
      on_face[axis] = sign * (b.half[axis] - depth);
      std::vector<V> beyond;
      for (int k = 0; k < 3; ++k) {
        V c = b.half.cwiseProduct(V(sym(rng), sym(rng), sym(rng))) * 2.0;
        c[axis] = sign * (b.half[axis] + 0.1 + unit(rng));
        beyond.push_back(b.world(c));
      }
      const Mesh m = tetrahedron(b.world(on_face), beyond[0], beyond[1], beyond[2]);
      EXPECT_EQ(check_solid_hull(indexed(m, 0.1)->index, b.hull, scratch),
                depth > kTol ? Validity::vertex_inside : Validity::valid)
          << "depth " << depth;
    }
  }
}

TEST(ValidityKernels, Condition2PlanesSupportPointsMatchesBruteForce) {
  std::mt19937 rng(33);
  std::uniform_real_distribution<double> off(-1.0, 1.2), lateral(-0.3, 0.3);
  std::uniform_int_distribution<int> count(1, 6);
  int supported = 0;
  const int trials = 600;
  for (int trial = 0; trial < trials; ++trial) {
    // Tangent planes of the unit sphere; points near their tangent points,
    // off the plane by a fraction of tol on either side of it.
    std::vector<Plane> planes;
    for (int i = count(rng); i > 0; --i) planes.push_back({random_unit(rng), 1.0});
    std::vector<V> points;
    for (int i = count(rng); i > 0; --i) {
      const Plane& near = planes[std::uniform_int_distribution<size_t>(0, planes.size() - 1)(rng)];
      const V tangent = near.normal.cross(random_unit(rng)).normalized();
      points.push_back(near.normal * (1.0 + off(rng) * kTol) + lateral(rng) * tangent);
    }
    bool expected = true;
    for (const Plane& plane : planes)
      for (const V& p : points) expected = expected && plane.normal.dot(p) - plane.offset <= kTol;
    supported += expected;
    ASSERT_EQ(planes_support_points(planes, points, kTol), expected) << "trial " << trial;
  }
  EXPECT_GT(supported, trials / 5);
  EXPECT_LT(supported, trials * 4 / 5);

  // A patch's faces on its hull and the hull's vertices: supported, until
  // a vertex of a facet leaves its plane by more than tol.
  ConvexHullBuilder qhull;
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 30; ++trial) {
    std::vector<V> cloud;
    for (int i = 0; i < 20; ++i) cloud.push_back(V(u(rng), u(rng), u(rng)));
    const ConvexPolytope hull = qhull.build(cloud).value();
    EXPECT_TRUE(planes_support_points(hull.planes, hull.vertices, kTol));
    const size_t f = std::uniform_int_distribution<size_t>(0, hull.facets.size() - 1)(rng);
    for (double out : {0.5 * kTol, 2.0 * kTol}) {
      std::vector<V> moved = hull.vertices;
      moved[hull.facets[f][0]] += out * hull.planes[f].normal;
      EXPECT_EQ(planes_support_points(hull.planes, moved, kTol), out <= kTol) << "moved out by " << out;
    }
  }
}

TEST(ValidityKernels, Condition3BarThroughASolidHull) {
  std::mt19937 rng(34);
  std::uniform_real_distribution<double> unit(0.0, 1.0), sym(-1.0, 1.0);
  ConvexHullBuilder qhull;
  std::vector<int> scratch;
  for (int trial = 0; trial < 40; ++trial) {
    const BoxHull b = random_box_hull(rng, qhull);
    const double diag = b.half.norm(); // every box point is within 2 diag of an inner one
    const V inner = b.world(b.half.cwiseProduct(V(sym(rng), sym(rng), sym(rng))) * 0.9);
    const V n = random_unit(rng), across = n.cross(random_unit(rng)).normalized();
    const double s = diag * (4.0 + unit(rng));
    const V mid = inner + s * n; // an open edge's midpoint, far from the box
    // One triangle normal to n: the bar of its edge at `mid` runs along n
    // through `inner`; the other edges' bars pass over 2 diag to the side.
    Mesh m;
    add_triangle_on_edge(m, mid, across, n.cross(across), 2.0 * diag, trial);
    add_anchor(m, inner + 20.0 * n + across);
    EXPECT_EQ(check_solid_hull(indexed(m, s + diag)->index, b.hull, scratch), Validity::bar_inside);
    // The same bars stopping 3 diag short of `inner`: outside the box.
    EXPECT_EQ(check_solid_hull(indexed(m, s - 3.0 * diag)->index, b.hull, scratch), Validity::valid);
  }
}

// A convex polygon of 3 to 8 corners on a circle (angles jittered) in a
// random plane, its corners the first points of `points`.
FlatPolygon random_polygon(std::mt19937& rng, std::vector<V>& points) {
  std::uniform_real_distribution<double> unit(0.0, 1.0), sym(-1.0, 1.0);
  const int corners = std::uniform_int_distribution<int>(3, 8)(rng);
  const PlaneFrame frame = PlaneFrame::from_normal(V(sym(rng), sym(rng), sym(rng)), random_unit(rng));
  const double radius = 0.6 + 0.4 * unit(rng);
  std::vector<int> ids;
  for (int i = 0; i < corners; ++i) {
    const double angle = 2.0 * M_PI * (i + 0.3 * sym(rng)) / corners;
    points.push_back(frame.origin + radius * (std::cos(angle) * frame.u + std::sin(angle) * frame.v));
    ids.push_back(static_cast<int>(points.size()) - 1);
  }
  return make_flat_polygon(points, ids, frame.normal, kTol);
}

// A point of the polygon at least `margin` inside every side.
V interior_point(std::mt19937& rng, const FlatPolygon& polygon, double margin) {
  std::exponential_distribution<double> weight(1.0);
  for (;;) {
    V p = V::Zero();
    double total = 0.0;
    for (const V& c : polygon.corners) {
      const double w = weight(rng);
      p += w * c;
      total += w;
    }
    p /= total;
    if (deepest_signed_distance(polygon.sides, p) < -margin) return p;
  }
}

// A point of the polygon's plane 0.08 to 0.38 outside one of its edges.
V beside(std::mt19937& rng, const FlatPolygon& polygon) {
  const size_t i = std::uniform_int_distribution<size_t>(0, polygon.corners.size() - 1)(rng);
  const V mid = 0.5 * (polygon.corners[i] + polygon.corners[(i + 1) % polygon.corners.size()]);
  return mid + (0.08 + 0.3 * std::uniform_real_distribution<double>(0.0, 1.0)(rng)) * polygon.sides[i].normal;
}

const auto kNoPatch = [](int) { return false; };

TEST(ValidityKernels, Condition3BarThroughAFlatPolygon) {
  std::mt19937 rng(35);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<int> scratch;
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<V> points;
    const FlatPolygon polygon = random_polygon(rng, points);
    ASSERT_GE(polygon.corners.size(), 3u);
    const V& np = polygon.plane.normal;
    // Through the interior, or through the plane beside the polygon.
    const bool through = trial % 2 == 0;
    const V target = through ? interior_point(rng, polygon, 10 * kTol) : beside(rng, polygon);
    V nt;
    do nt = random_unit(rng);
    while (nt.dot(np) < 0.7);
    const V across = nt.cross(random_unit(rng)).normalized();
    const double s = 6.0 + unit(rng);
    const V mid = target + s * nt; // in front of the polygon by >= 4.2
    // A triangle normal to nt, wholly in front (its corners within 5 of
    // `mid`, less than 3.6 nearer the polygon's plane). Only the bar of the
    // edge at `mid` can cross: the others run 2.7 or more to its side,
    // beyond the polygon (diameter <= 2).
    Mesh m;
    add_triangle_on_edge(m, mid, across, nt.cross(across), 2.5, trial / 2);
    add_anchor(m, mid + 10.0 * nt);
    EXPECT_EQ(check_flat_polygon(indexed(m, s + 0.5)->index, polygon, kNoPatch, scratch),
              through ? Validity::bar_crosses_polygon : Validity::valid)
        << "trial " << trial;
    EXPECT_EQ(check_flat_polygon(indexed(m, 0.4 * s)->index, polygon, kNoPatch, scratch), Validity::valid);
  }
}

TEST(ValidityKernels, Condition4FaceBelowTouchingThePolygonInterior) {
  std::mt19937 rng(36);
  std::uniform_real_distribution<double> unit(0.0, 1.0), sym(-1.0, 1.0);
  std::vector<int> scratch;
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<V> points;
    const FlatPolygon polygon = random_polygon(rng, points);
    ASSERT_GE(polygon.corners.size(), 3u);
    const V& n = polygon.plane.normal;
    const V q = interior_point(rng, polygon, 10 * kTol);
    // A closed tetrahedron (no bars) with its apex at q, within tol/2 of the
    // plane, and its base below (or, mirrored, above) the polygon.
    const auto below = [&](const V& apex, double up) {
      std::vector<V> base;
      for (int k = 0; k < 3; ++k) {
        const V lateral = V(sym(rng), sym(rng), sym(rng)) * 0.5;
        base.push_back(apex + up * (0.1 + 0.4 * unit(rng)) * n + (lateral - lateral.dot(n) * n));
      }
      return tetrahedron(apex, base[0], base[1], base[2]);
    };
    const V apex = q + 0.5 * kTol * sym(rng) * n;
    EXPECT_EQ(check_flat_polygon(indexed(below(apex, -1.0), 0.1)->index, polygon, kNoPatch, scratch),
              Validity::face_below_polygon)
        << "trial " << trial;
    EXPECT_EQ(check_flat_polygon(indexed(below(q - 2.0 * kTol * n, -1.0), 0.1)->index, polygon, kNoPatch, scratch),
              Validity::valid)
        << "lowered by 2 tol";
    EXPECT_EQ(check_flat_polygon(indexed(below(apex, 1.0), 0.1)->index, polygon, kNoPatch, scratch), Validity::valid)
        << "above";
    EXPECT_EQ(check_flat_polygon(
                  indexed(below(apex, -1.0), 0.1)->index, polygon, [](int) { return true; }, scratch),
              Validity::valid)
        << "in the patch";
    EXPECT_EQ(check_flat_polygon(indexed(below(beside(rng, polygon), -1.0), 0.1)->index, polygon, kNoPatch, scratch),
              Validity::valid)
        << "beside";
    // Only a vertex deeper than tol counts as below: a base at depth 2 tol
    // is, one at 0.5 tol (touching the polygon all over) is not.
    for (double depth : {0.5 * kTol, 2.0 * kTol}) {
      const V base = q - depth * n, a = (polygon.corners[0] - q).normalized(), b = n.cross(a);
      const Mesh m = tetrahedron(q + 0.2 * n, base + 0.2 * a, base + 0.2 * b, base - 0.2 * a - 0.2 * b);
      EXPECT_EQ(check_flat_polygon(indexed(m, 0.1)->index, polygon, kNoPatch, scratch),
                depth > kTol ? Validity::face_below_polygon : Validity::valid)
          << "base at depth " << depth;
    }
  }
}

} // namespace
} // namespace hullcover
