#include "hullcover/covering/validity.h"

namespace hullcover {

const char* validity_name(Validity v) {
  switch (v) {
    case Validity::valid: return "valid";
    case Validity::vertex_inside: return "vertex_inside";
    case Validity::edge_inside: return "edge_inside";
    case Validity::face_not_on_hull: return "face_not_on_hull";
    case Validity::bar_inside: return "bar_inside";
    case Validity::bar_crosses_polygon: return "bar_crosses_polygon";
    case Validity::face_below_polygon: return "face_below_polygon";
    case Validity::too_many_vertices: return "too_many_vertices";
    case Validity::materials_differ: return "materials_differ";
    case Validity::hull_failed: return "hull_failed";
    case Validity::front_space_inside: return "front_space_inside";
    case Validity::opening_inside: return "opening_inside";
    case Validity::face_crosses_hull: return "face_crosses_hull";
    case Validity::polygon_spans_gap: return "polygon_spans_gap";
    case Validity::too_many_triangles: return "too_many_triangles";
  }
  return "unknown";
}

} // namespace hullcover
