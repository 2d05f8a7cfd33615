#pragma once
// An independent re-check of a covering against the paper's conditions
// 1-4 and coverage. It shares no predicate with the decomposer: planes come
// from the facet polygons (Newell's method), boundary edges and bars are
// found again from the raw triangles, and candidates come from a uniform
// grid, not the decomposer's trees. One bug cannot hide in both.

#include "hullcover/lib/covering.h"
#include "hullcover/lib/prepared_mesh.h"

#include <string>
#include <vector>

namespace hullcover::test {

struct CheckReport {
  long vertices_inside = 0;       // condition 1
  long edges_inside = 0;          // condition 1
  long faces_off_hull = 0;        // condition 2 (a covered face whose plane does not support its hull)
  long bars_inside = 0;           // condition 3
  long faces_below_polygon = 0;   // condition 4
  long faces_uncovered = 0;       // coverage: a face with area in no hull
  long hulls_not_convex = 0;      // a hull vertex in front of one of its own facets
  std::vector<std::string> examples;  // the first few, for the failure message

  long total() const {
    return vertices_inside + edges_inside + faces_off_hull + bars_inside + faces_below_polygon + faces_uncovered +
           hulls_not_convex;
  }
  std::string summary() const;
};

/// Re-checks every hull of `covering` against the whole of `prepared`.
CheckReport check_covering_independently(const PreparedMesh& prepared, const Covering& covering);

/// True when segment p-q passes through some hull: deeper than `tol`
/// inside a solid hull, or across the relative interior of a flat one.
bool segment_hits_covering(const Covering& covering, const Eigen::Vector3d& p, const Eigen::Vector3d& q, double tol);

/// True when `p` lies deeper than `tol` inside some solid hull.
bool point_inside_covering(const Covering& covering, const Eigen::Vector3d& p, double tol);

} // namespace hullcover::test
