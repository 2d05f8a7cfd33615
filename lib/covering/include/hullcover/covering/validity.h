#pragma once
/// \file validity.h
/// Which validity conditions a covering keeps, and which one a rejected
/// candidate hull broke (counted in CoveringStatistics::rejections).

#include <cstdint>

namespace hullcover {

/// Which validity conditions a covering keeps (docs/definitions-and-proofs.md, "Exact mode:
/// no free space lost").
enum class ValidityMode {
  paper, ///< the paper's conditions 1-4 alone (bars at edge midpoints)
  exact, ///< the paper's plus lib/covering/src/validity/exact_conditions.h: no free space lost
};

/// Which condition a candidate broke first (or `valid`).
enum class Validity : std::uint8_t {
  valid,               ///< every condition holds
  vertex_inside,       ///< condition 1
  edge_inside,         ///< condition 1
  face_not_on_hull,    ///< condition 2
  bar_inside,          ///< condition 3, solid hull
  bar_crosses_polygon, ///< condition 3, flat polygon
  face_below_polygon,  ///< condition 4
  too_many_vertices,   ///< the option max_hull_vertices
  materials_differ,    ///< materials are kept apart
  hull_failed,         ///< Qhull rejected the points (treated as invalid)
  front_space_inside,  ///< exact E1: a face's front space enters the hull
  opening_inside,      ///< exact E2: the opening beyond an open edge enters the hull
  face_crosses_hull,   ///< exact E3: a face's interior deeper than tol inside
  polygon_spans_gap,   ///< a flat polygon spans area of its plane that none of its faces covers
  too_many_triangles,  ///< the option max_hull_triangles
};
/// How many Validity values there are (rejection counters per value).
inline constexpr int kValidityCount = static_cast<int>(Validity::too_many_triangles) + 1;

/// Stable snake_case name, for reports.
const char* validity_name(Validity v);

} // namespace hullcover
