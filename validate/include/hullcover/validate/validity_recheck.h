#pragma once
/// \file validity_recheck.h
/// An independent re-check of hulls against the paper's conditions 1-4 and
/// coverage. It shares no predicate with the decomposer: planes come from
/// the facet polygons (Newell's method), boundary edges and bars are found
/// again from the raw triangles, and candidates come from a uniform grid,
/// not the decomposer's trees. One bug cannot hide in both. The audit runs
/// it on hulls from any source; the tests run it on every covering.

#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/validate/hull_under_check.h"
#include "hullcover/covering/covering_types.h"
#include "hullcover/mesh/prepared_mesh.h"

#include <string>
#include <vector>

namespace hullcover::validate {

/// A covering's hulls, with the faces each covers.
std::vector<HullUnderCheck> hulls_under_check(const Covering& covering);
/// Hulls from any source (no claimed faces); flat when front and back
/// facets share their corners.
std::vector<HullUnderCheck> hulls_under_check(const std::vector<bvh::RuntimeHull>& hulls);

/// What the re-check found: counts per condition, and the first few findings.
struct CheckReport {
  long vertices_inside = 0;     ///< condition 1: mesh vertices strictly inside a solid hull
  long edges_inside = 0;        ///< condition 1: mesh edges with a part strictly inside a solid hull
  long faces_off_hull = 0;      ///< condition 2: claimed faces not on their hull with their normal out
  long bars_inside = 0;         ///< condition 3: the paper's bars entering a hull
  long faces_below_polygon = 0; ///< condition 4: faces reaching a flat hull's interior from below
  long faces_uncovered =
      0; ///< coverage: faces with area on no hull's boundary (nor, when inside_allowed, inside or on one)
  long faces_inside = 0;             ///< when inside_allowed: faces covered by lying inside a solid hull, not on it
  double uncovered_area = 0.0;       ///< their area, scene units squared
  double total_area = 0.0;           ///< the area of every face with a surface
  long hulls_not_convex = 0;         ///< hulls with a vertex in front of one of their own facets
  std::vector<std::string> examples; ///< the first few findings, for a failure message
  /// Checked for a covering made with an allowance (allowance_audit.h):
  /// faces may lie inside their hull (covered, any shape touching them
  /// touches it), so mesh vertices and edges inside hulls are reported, not
  /// violations (what the hulls take is judged by the allowance audit).
  bool inside_allowed = false;

  /// Every finding, the paper's bars included (what paper mode must pass).
  long total() const { return violations() + bars_inside; }
  /// What the audit's verdict counts: everything but the paper's bars, which
  /// stand in for openings at one point per edge; the probe measures the
  /// openings themselves (exact-mode hulls keep them without long bars).
  long violations() const {
    return (inside_allowed ? 0 : vertices_inside + edges_inside) + faces_off_hull + faces_below_polygon +
           faces_uncovered + hulls_not_convex;
  }
  /// The counts on one line, then the examples one per line.
  std::string summary() const;
};

/// Re-checks every hull against the whole of `prepared`, with bars of the
/// given half-length. Conditions 3 and 4 are skipped for a flat hull that
/// is one face (claims exactly one, or is a bare triangle claiming none):
/// whatever crosses it crosses the mesh. A face no hull claims counts as
/// covered when it lies on some hull's boundary with its normal out: every
/// corner within tol of the hull's facets (the distance to them, fanned into
/// triangles; a plane test can pass a point far past a thin hull's sharp
/// edge) and no hull vertex more than `kOnHullInTolerances` tolerances in
/// front of the face's plane (hullcover/geometry/tolerances.h). A face
/// thinner than tol (its height over its longest edge) has no reliable
/// normal: only its corners are checked. With `inside_allowed`, condition 2
/// gives way: a face (claimed or not) is also covered when its corners all
/// lie inside one solid hull, or on one flat hull, or within tol of it (the
/// hull's far vertices may rise above the face's own plane), and condition 1 is
/// reported without counting as a violation (CheckReport::inside_allowed).
/// Hulls, then faces, are checked on `threads` threads (0: every core;
/// negative: one), each into a part of its own added in hull and face
/// order: the report, examples included, is the same for any thread count.
CheckReport recheck_hulls(const PreparedMesh& prepared, const std::vector<HullUnderCheck>& hulls,
                          double bar_half_length, bool inside_allowed = false, int threads = 1);

/// Re-checks a covering (its faces claimed, its own bar length); with
/// `inside_allowed` as recheck_hulls does, for a covering made with an
/// allowance.
CheckReport check_covering_independently(const PreparedMesh& prepared, const Covering& covering,
                                         bool inside_allowed = false);

/// True when segment p-q passes through some hull: deeper than `tol`
/// inside a solid hull, or across the relative interior of a flat one.
bool segment_hits_covering(const Covering& covering, const Eigen::Vector3d& p, const Eigen::Vector3d& q, double tol);

/// True when `p` lies deeper than `tol` inside some solid hull.
bool point_inside_covering(const Covering& covering, const Eigen::Vector3d& p, double tol);

} // namespace hullcover::validate
