#pragma once
// The figures `hullcover info` prints about a prepared mesh, as text or JSON.

#include "hullcover/mesh/prepared_mesh.h"

#include <nlohmann/json.hpp>

#include <string>

namespace hullcover::app {

/// Counts and extents of a prepared mesh, the same ones for text and JSON.
struct MeshFigures {
  int triangles = 0;
  int vertices_before_weld = 0;
  int vertices_after_weld = 0;
  int unreferenced_vertices = 0;
  int components = 0;
  int boundary_edges = 0;
  int non_manifold_edges = 0;
  int orientation_conflicts = 0;
  int zero_area_faces = 0;
  int materials = 0;
  Aabb bounding_box;
  Tolerance tolerance;
};

MeshFigures measure_mesh(const PreparedMesh& prepared);

/// Several aligned lines "name  value", ending in a newline.
std::string format_mesh_figures(const MeshFigures& figures);

nlohmann::json mesh_figures_json(const MeshFigures& figures);

/// One line saying which tolerance is in force and why.
std::string describe_tolerance(const Tolerance& tolerance);

} // namespace hullcover::app
