#include "mesh_report.h"

#include "help_numbers.h"
#include "hullcover/geometry/tolerances.h"

#include <cstdio>

namespace hullcover::app {

MeshFigures measure_mesh(const PreparedMesh& prepared) {
  MeshFigures f;
  const MeshConnectivity& c = prepared.connectivity;
  f.triangles = static_cast<int>(prepared.mesh.triangles.size());
  f.vertices_before_weld = prepared.vertices_before_weld;
  f.vertices_after_weld = static_cast<int>(prepared.mesh.positions.size());
  f.unreferenced_vertices = prepared.unreferenced_dropped;
  f.components = c.component_count;
  f.boundary_edges = count_edges(c, EdgeKind::boundary);
  f.non_manifold_edges = count_edges(c, EdgeKind::non_manifold);
  f.orientation_conflicts = count_edges(c, EdgeKind::orientation_conflict);
  f.zero_area_faces = count_zero_area_faces(c);
  f.materials = static_cast<int>(prepared.mesh.material_names.size());
  f.bounding_box = referenced_bounding_box(prepared.mesh);
  f.tolerance = prepared.tolerance;
  return f;
}

std::string describe_tolerance(const Tolerance& t) {
  const std::string relative = number_text(kDefaultRelativeTolerance);
  char line[320];
  char lengths[96];
  if (t.largest_length() > t.length)
    std::snprintf(lengths, sizeof lengths, "%.6g to %.6g (each of %d places its own)", t.length, t.largest_length(),
                  t.places);
  else
    std::snprintf(lengths, sizeof lengths, "%.6g", t.length);
  if (t.raised_to_floor)
    std::snprintf(line, sizeof line, "%s (raised to the data's rounding floor; %s was below it%s)", lengths,
                  t.user_given ? "the given value" : "the default", t.places > 1 ? " in some place" : "");
  else if (t.user_given)
    std::snprintf(line, sizeof line, "%s (given)", lengths);
  else if (t.islands <= 1)
    std::snprintf(line, sizeof line, "%s (default: %s x the diagonal %.6g)", lengths, relative.c_str(), t.local_extent);
  else if (t.places <= 1)
    std::snprintf(line, sizeof line, "%s (default: %s x the diagonal of the box of its %d islands)", lengths,
                  relative.c_str(), t.islands);
  else
    std::snprintf(line, sizeof line,
                  "%s (default: %s x each place's diagonal; %d places, each islands whose boxes meet)", lengths,
                  relative.c_str(), t.places);
  return line;
}

std::string format_mesh_figures(const MeshFigures& f) {
  std::string out;
  char line[256];
  const auto row = [&](const char* name, long long value) {
    std::snprintf(line, sizeof line, "  %-24s %lld\n", name, value);
    out += line;
  };
  row("triangles", f.triangles);
  row("vertices (as imported)", f.vertices_before_weld);
  row("vertices (welded)", f.vertices_after_weld);
  if (f.unreferenced_vertices > 0) row("unreferenced (dropped)", f.unreferenced_vertices);
  row("components", f.components);
  row("boundary edges", f.boundary_edges);
  row("non-manifold edges", f.non_manifold_edges);
  row("orientation conflicts", f.orientation_conflicts);
  row("zero-area faces", f.zero_area_faces);
  row("materials", f.materials);
  const Eigen::Vector3d& lo = f.bounding_box.min;
  const Eigen::Vector3d& hi = f.bounding_box.max;
  std::snprintf(line, sizeof line, "  %-24s (%.6g, %.6g, %.6g) .. (%.6g, %.6g, %.6g)\n", "bounding box", lo.x(), lo.y(),
                lo.z(), hi.x(), hi.y(), hi.z());
  out += line;
  out += "  tolerance                " + describe_tolerance(f.tolerance) + "\n";
  return out;
}

nlohmann::json mesh_figures_json(const MeshFigures& f) {
  const Eigen::Vector3d& lo = f.bounding_box.min;
  const Eigen::Vector3d& hi = f.bounding_box.max;
  return {
      {"triangles", f.triangles},
      {"vertices_before_weld", f.vertices_before_weld},
      {"vertices_after_weld", f.vertices_after_weld},
      {"unreferenced_vertices", f.unreferenced_vertices},
      {"components", f.components},
      {"boundary_edges", f.boundary_edges},
      {"non_manifold_edges", f.non_manifold_edges},
      {"orientation_conflicts", f.orientation_conflicts},
      {"zero_area_faces", f.zero_area_faces},
      {"materials", f.materials},
      {"bounding_box", {{"min", {lo.x(), lo.y(), lo.z()}}, {"max", {hi.x(), hi.y(), hi.z()}}}},
      {"tolerance",
       {{"length", f.tolerance.length},
        {"floor", f.tolerance.floor},
        {"diagonal", f.tolerance.diagonal},
        {"local_extent", f.tolerance.local_extent},
        {"islands", f.tolerance.islands},
        {"per_island", f.tolerance.island_lengths},
        {"user_given", f.tolerance.user_given},
        {"raised_to_floor", f.tolerance.raised_to_floor}}},
  };
}

} // namespace hullcover::app
