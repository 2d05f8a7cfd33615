// The covering's OBJ (covering_export.h): every hull an object, its
// vertices and facets numbered across the file, coordinates to 17
// significant digits, a flat hull by its one face; the same text for any
// thread count, across the blocks of hulls the writer formats apart.

#include "covering_fixture.h"

#include "hullcover/covering/covering_export.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace hullcover {
namespace {

// Hulls enough for several of the writer's blocks: tetrahedra, every
// seventh a flat triangle (planar, no thickness).
Covering many_small_hulls(int count) {
  Covering covering;
  covering.statistics.faces = count;
  covering.tolerance.length = 1.0 / 3.0e5;
  for (int i = 0; i < count; ++i) {
    CoveringHull hull;
    const Eigen::Vector3d at(i / 3.0, -i * 0.1, 1e6 + i);
    hull.polytope.vertices = {at, at + Eigen::Vector3d(1, 0, 0), at + Eigen::Vector3d(0, 1, 0),
                              at + Eigen::Vector3d(0, 0, 1)};
    hull.polytope.facets = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    hull.planar = i % 7 == 0;
    if (hull.planar) {
      hull.polytope.vertices.pop_back();
      hull.polytope.facets = {{0, 2, 1}, {0, 1, 2}};
    }
    hull.faces = {i};
    covering.hulls.push_back(std::move(hull));
  }
  return covering;
}

// The OBJ the covering stands for, written out line by line here.
std::string expected_obj(const Covering& covering) {
  std::string text;
  char line[256];
  std::snprintf(line, sizeof line, "# hullcover covering: %zu hulls of %d faces, tolerance %.17g\n",
                covering.hulls.size(), covering.statistics.faces, covering.tolerance.length);
  text += line;
  long first = 1;
  for (size_t h = 0; h < covering.hulls.size(); ++h) {
    const CoveringHull& hull = covering.hulls[h];
    text += "o hull_" + std::to_string(h) + "\n";
    for (const Eigen::Vector3d& p : hull.polytope.vertices) {
      std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", p.x(), p.y(), p.z());
      text += line;
    }
    const size_t facets = hull.planar && hull.thickness == 0.0 ? 1 : hull.polytope.facets.size();
    for (size_t f = 0; f < facets; ++f) {
      text += "f";
      for (int v : hull.polytope.facets[f]) text += " " + std::to_string(first + v);
      text += "\n";
    }
    first += static_cast<long>(hull.polytope.vertices.size());
  }
  return text;
}

TEST(CoveringExport, ObjTextIsTheSameForAnyThreadCount) {
  Covering covering = many_small_hulls(20000);
  const std::string expected = expected_obj(covering);
  for (int threads : {1, 2, 5}) {
    covering.options.threads = threads;
    EXPECT_EQ(test::covering_obj_bytes(covering), expected) << threads << " threads";
  }
}

TEST(CoveringExport, AnEmptyCoveringIsItsHeaderAlone) {
  Covering covering;
  covering.options.threads = 3;
  EXPECT_EQ(test::covering_obj_bytes(covering), expected_obj(covering));
  EXPECT_EQ(expected_obj(covering).find("o "), std::string::npos);
}

} // namespace
} // namespace hullcover
