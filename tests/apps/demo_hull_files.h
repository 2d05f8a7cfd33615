#pragma once
// The demo scene and its hulls (`hullcover demo`, generated in code), and
// hull OBJ files made from them: a subset of the hulls, or the hulls plus
// one more box placed in free space.

#include "command_run.h"
#include "temp_dir.h"

#include <Eigen/Core>

#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace hullcover::test {

/// One `o` group of a hull OBJ: its corner points and faces (indices into them).
struct ObjHull {
  std::string name;
  std::vector<Eigen::Vector3d> points;
  std::vector<std::vector<int>> faces;
};

/// The groups of a hull OBJ as `hullcover decompose` writes it (global
/// 1-based vertex indices, one `o` per hull).
inline std::vector<ObjHull> read_obj_hulls(const std::string& text) {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<ObjHull> hulls;
  std::vector<std::vector<int>> global_faces;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag == "v") {
      Eigen::Vector3d v;
      words >> v.x() >> v.y() >> v.z();
      vertices.push_back(v);
    } else if (tag == "o" || tag == "g") {
      hulls.push_back({});
      words >> hulls.back().name;
    } else if (tag == "f" && !hulls.empty()) {
      std::vector<int> face;
      for (std::string corner; words >> corner;) face.push_back(std::stoi(corner.substr(0, corner.find('/'))) - 1);
      hulls.back().faces.push_back(face);
    }
  }
  for (ObjHull& hull : hulls) { // local indices, each hull its own points
    std::vector<int> local(vertices.size(), -1);
    for (std::vector<int>& face : hull.faces)
      for (int& index : face) {
        if (local[index] < 0) {
          local[index] = static_cast<int>(hull.points.size());
          hull.points.push_back(vertices[index]);
        }
        index = local[index];
      }
  }
  return hulls;
}

/// A hull OBJ of `hulls`.
inline std::string write_obj_hulls(const std::vector<ObjHull>& hulls) {
  std::ostringstream out;
  out.precision(17);
  int base = 1;
  for (const ObjHull& hull : hulls) {
    out << "o " << hull.name << '\n';
    for (const Eigen::Vector3d& p : hull.points) out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    for (const std::vector<int>& face : hull.faces) {
      out << 'f';
      for (int index : face) out << ' ' << base + index;
      out << '\n';
    }
    base += static_cast<int>(hull.points.size());
  }
  return out.str();
}

/// An axis-aligned box as a hull, faces wound outward.
inline ObjHull box_hull(const std::string& name, const Eigen::Vector3d& low, const Eigen::Vector3d& high) {
  ObjHull box{name, {}, {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}}};
  for (int corner = 0; corner < 8; ++corner)
    box.points.emplace_back((corner & 4) ? high.x() : low.x(), (corner & 2) ? high.y() : low.y(),
                            (corner & 1) ? high.z() : low.z());
  return box;
}

/// Runs `hullcover demo` into `dir`/demo: demo/demo-scene.obj and
/// demo/demo-hulls.obj. False when it failed.
inline bool write_demo(const TempDir& dir) { return run_hullcover(dir, "demo --out " + dir.path("demo")).status == 0; }

} // namespace hullcover::test
