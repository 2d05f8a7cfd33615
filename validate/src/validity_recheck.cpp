#include "hullcover/validate/validity_recheck.h"

#include "recheck_geometry.h"
#include "recheck_mesh.h"

#include "hullcover/geometry/parallel_for.h"
#include "hullcover/geometry/tolerances.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hullcover::validate {
namespace {

using recheck::CandidateGrid;
using recheck::CheckedHull;
using recheck::depth_inside;
using recheck::HalfSpace;

// Findings kept as examples: enough to start debugging from.
constexpr size_t kExamplesKept = 8;
// Hulls or faces checked between two additions to the report: their parts
// are kept until then, so memory stays bounded on million-face scenes, and
// a batch is long enough that its threads seldom wait for one another.
constexpr int kPartsPerBatch = 4096;
// Condition 4 samples each chord between two points where a face meets a
// flat hull's plane at this many intervals.
constexpr int kChordSamples = 16;

// Flat: two facets on the same corners in opposite order (front and back),
// whatever the decomposer calls the hull.
bool has_flat_facets(const std::vector<std::vector<int>>& f) {
  bool flat = f.size() == 2 && f[0].size() == f[1].size();
  for (size_t i = 0; flat && i < f[0].size(); ++i) flat = f[0][i] == f[1][f[1].size() - 1 - i];
  return flat;
}

// A flat hull that is one face (claimed, or a bare triangle from another
// tool): whatever crosses it crosses the mesh itself.
bool is_single_face(const HullUnderCheck& hull) {
  return hull.flat && (hull.faces.size() == 1 || (hull.faces.empty() && hull.shape->vertices.size() == 3));
}

// How far a face is from lying on a hull's boundary with its normal out.
struct FaceOffHull {
  double in_front = 0.0; // the farthest hull vertex in front of the face's plane (0 for a thin face: no plane)
  // The face's farthest corner from the hull's surface, inside or outside;
  // and from the hull itself (0 for a corner in it).
  double corner_off = 0.0;
  double corner_outside = 0.0;
  // Condition 2 within `front_limit`, coverage within tol: every corner,
  // and so (the hull being convex) every point of the face, within tol of
  // the hull.
  bool on_hull(double front_limit, double tol) const { return in_front <= front_limit && corner_off <= tol; }
  // Covered with an allowance, which lifts condition 2 (the face's plane
  // need not support the hull): every corner, and so every point of the
  // face, in the hull or within tol of it. A flat hull has no inside: there
  // it is the face lying on the polygon, however far the polygon rises
  // beyond the face's own plane. A planar patch of faces within a slab of
  // tol but not coplanar (a sloped triangle beside level strips,
  // recast-dungeon) rises more than 2 tol above a small face's plane a few
  // metres away, and the face is on it all the same.
  bool on_or_inside(double tol) const { return corner_outside <= tol; }
};

// How far corner `p` is from the hull's surface. At a hull vertex (most
// corners are), no farther than from it. Else the distance to the hull's
// facets, fanned into triangles (never below the true distance for a point
// outside, convex_polytope.h): not the planes alone, which past a thin
// hull's sharp edge can all lie within tol of a point far from the hull
// (recast-dungeon: a stair rail's corner 140 tol from its hull, within
// 0.06 tol of every plane). A point more than kOnHullInTolerances tol from
// a plane's side (outside, or inside) is at least that far less the
// planes' fitting error (under tol): its plane distance is returned, which
// fails any test within tol.
double corner_off_surface(const HullUnderCheck& hull, const CheckedHull& c, const Eigen::Vector3d& p, double depth) {
  for (const Eigen::Vector3d& v : hull.shape->vertices)
    if ((v - p).squaredNorm() <= c.tol * c.tol) return (v - p).norm();
  if (std::abs(depth) > kOnHullInTolerances * c.tol) return std::abs(depth);
  return distance_to_facet_fans(*hull.shape, p);
}

FaceOffHull face_off_hull(const Mesh& mesh, const Eigen::Vector3d& normal, const Eigen::Vector3i& t,
                          const HullUnderCheck& hull, const CheckedHull& c) {
  FaceOffHull off;
  const Eigen::Vector3d& a = mesh.positions[t[0]];
  for (const auto& p : hull.shape->vertices) off.in_front = std::max(off.in_front, normal.dot(p - a));
  // A flat hull has a facet either way: faces of either side lie on it.
  for (int k = 0; k < 3; ++k) {
    const double depth = depth_inside(c.facets, mesh.positions[t[k]]);
    const double off_surface = corner_off_surface(hull, c, mesh.positions[t[k]], depth);
    off.corner_off = std::max(off.corner_off, off_surface);
    if (depth < 0.0) off.corner_outside = std::max(off.corner_outside, off_surface);
  }
  return off;
}

// Where triangle `t` meets `plane`: its corners on the plane and its
// edges' crossing points.
std::vector<Eigen::Vector3d> meeting_with_plane(const Mesh& mesh, const Eigen::Vector3i& t, const HalfSpace& plane,
                                                double tol) {
  std::vector<Eigen::Vector3d> on_plane;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d p = mesh.positions[t[k]], q = mesh.positions[t[(k + 1) % 3]];
    const double dp = plane.n.dot(p) - plane.d, dq = plane.n.dot(q) - plane.d;
    if (std::abs(dp) <= tol) on_plane.push_back(p);
    if ((dp < -tol && dq > tol) || (dp > tol && dq < -tol)) on_plane.push_back(p + (q - p) * (dp / (dp - dq)));
  }
  return on_plane;
}

// Condition 4 for one face: does triangle `t`, reaching below flat hull
// `c`, touch its polygon's interior (deeper inside the sides than the rim)?
bool reaches_below_polygon(const Mesh& mesh, const Eigen::Vector3i& t, const CheckedHull& c, double tol,
                           double on_hull) {
  bool below = false;
  for (int k = 0; k < 3; ++k) below |= c.front.n.dot(mesh.positions[t[k]]) - c.front.d < -tol;
  if (!below) return false;
  // Sampled along the chords between the points where it meets the plane.
  const std::vector<Eigen::Vector3d> on_plane = meeting_with_plane(mesh, t, c.front, tol);
  for (size_t i = 0; i < on_plane.size(); ++i)
    for (size_t j = i; j < on_plane.size(); ++j)
      for (int s = 0; s <= kChordSamples; ++s) {
        const double u = s / static_cast<double>(kChordSamples);
        if (depth_inside(c.sides, on_plane[i] + (on_plane[j] - on_plane[i]) * u) > on_hull) return true;
      }
  return false;
}

// Adds `part` (one hull's or one face's findings) to `total`: counts
// summed, examples appended while there is room. Parts are added in hull,
// then face order, so the report is the same whichever thread found what.
void add_findings(CheckReport& total, const CheckReport& part) {
  total.vertices_inside += part.vertices_inside;
  total.edges_inside += part.edges_inside;
  total.faces_off_hull += part.faces_off_hull;
  total.bars_inside += part.bars_inside;
  total.faces_below_polygon += part.faces_below_polygon;
  total.faces_uncovered += part.faces_uncovered;
  total.faces_inside += part.faces_inside;
  total.uncovered_area += part.uncovered_area;
  total.total_area += part.total_area;
  total.hulls_not_convex += part.hulls_not_convex;
  for (const std::string& e : part.examples)
    if (total.examples.size() < kExamplesKept) total.examples.push_back(e);
}

// Re-checks hulls one by one against the mesh, then the faces no hull
// claims. Every check is const and writes only the part it is given: hulls
// and faces are checked on many threads, each into its own part.
class Rechecker {
public:
  Rechecker(const PreparedMesh& prepared, double bar_half_length, bool inside_allowed)
      : inside_allowed_(inside_allowed), mesh_(prepared.mesh),
        largest_on_hull_(kOnHullInTolerances * prepared.tolerance.largest_length()),
        facts_(recheck::read_mesh_facts(prepared, bar_half_length)), scene_(referenced_bounding_box(mesh_)),
        cell_(std::max(facts_.longest_edge, scene_.diagonal() / recheck::kMaxCellsAlongDiagonal)),
        grids_(recheck::build_candidate_grids(mesh_, facts_, cell_, scene_.min)) {}

  // An empty grid on the same cells as the mesh's.
  CandidateGrid empty_grid() const { return {cell_, scene_.min, {}}; }

  int face_count() const { return static_cast<int>(mesh_.triangles.size()); }

  // Hull h's findings, into `out`.
  void check_hull(size_t h, const HullUnderCheck& hull, const CheckedHull& c, CheckReport& out) const {
    const std::string where = "hull " + std::to_string(h) + " (" + std::to_string(hull.faces.size()) + " faces" +
                              (hull.flat ? ", flat" : "") + "): ";
    check_convex(where, hull, c, out);
    check_claimed_faces(where, hull, c, out);
    if (is_single_face(hull)) return;
    // Candidates: whatever lies on the hull or in it is in its box grown by
    // the on-hull distance.
    const Eigen::Vector3d lo = c.lo.array() - on_hull(c), hi = c.hi.array() + on_hull(c);
    if (c.flat) {
      check_bars_across_flat(where, c, lo, hi, out);
      check_faces_below_flat(where, hull, c, lo, hi, out);
    } else {
      check_solid(where, c, lo, hi, out);
    }
  }

  // Coverage of face f (its area counted into `out`; every face with three
  // distinct corners, those thinner than tol too): claimed by some hull
  // (`claimed`), or, claimed by none, lying on some hull's boundary with its
  // normal out (a thin face: within tol of it, face_covered).
  void check_face_coverage(int f, bool claimed, const std::vector<HullUnderCheck>& hulls,
                           const std::vector<CheckedHull>& checked, const CandidateGrid& hull_grid,
                           CheckReport& out) const {
    const Eigen::Vector3i& t = mesh_.triangles[f];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return;
    const Eigen::Vector3d &a = mesh_.positions[t[0]], &b = mesh_.positions[t[1]], &c = mesh_.positions[t[2]];
    const double area = 0.5 * (b - a).cross(c - a).norm();
    out.total_area += area;
    if (claimed) return;
    // Candidates: hulls within the largest on-hull distance; each judged at
    // its own.
    const Eigen::Vector3d lo = a.cwiseMin(b).cwiseMin(c).array() - largest_on_hull_;
    const Eigen::Vector3d hi = a.cwiseMax(b).cwiseMax(c).array() + largest_on_hull_;
    // A flat hull has a facet either way: a face on it is on its boundary
    // whichever way it faces (a double-sided sheet's two faces).
    for (int h : hull_grid.query(lo, hi))
      if (face_covered(facts_.normal[f], t, hulls[h], checked[h], out)) return;
    ++out.faces_uncovered;
    out.uncovered_area += area;
    note(out, "face " + std::to_string(f) + " is on no hull");
  }

private:
  static void note(CheckReport& out, const std::string& what) {
    if (out.examples.size() < kExamplesKept) out.examples.push_back(what);
  }

  // On the hull; with an allowance, or inside a solid one (counted apart),
  // or on a flat one that condition 2 would refuse. A face thinner than tol
  // (no surface, read_mesh_facts) has no reliable normal, so condition 2
  // means nothing for it; its coverage still does.
  bool face_covered(const Eigen::Vector3d& normal, const Eigen::Vector3i& t, const HullUnderCheck& hull,
                    const CheckedHull& c, CheckReport& out) const {
    const FaceOffHull off = face_off_hull(mesh_, normal, t, hull, c);
    if (off.on_hull(on_hull(c), c.tol)) return true;
    if (!inside_allowed_ || !off.on_or_inside(c.tol)) return false;
    if (!c.flat) ++out.faces_inside;
    return true;
  }

  // A hull vertex in front of one of the hull's own facets; one finding per hull.
  void check_convex(const std::string& where, const HullUnderCheck& hull, const CheckedHull& c,
                    CheckReport& out) const {
    for (const auto& p : hull.shape->vertices)
      for (size_t fi = 0; fi < hull.shape->facets.size(); ++fi)
        if (const HalfSpace& plane = c.facets[fi]; plane.n.dot(p) - plane.d > c.tol) {
          ++out.hulls_not_convex;
          note(out, where + "not convex: a vertex " + std::to_string(plane.n.dot(p) - plane.d) +
                        " in front of a facet of " + std::to_string(hull.shape->facets.size()));
          return;
        }
  }

  // Condition 2 and coverage: each claimed face's plane supports the hull
  // (every hull vertex behind it) and its corners lie on the hull.
  void check_claimed_faces(const std::string& where, const HullUnderCheck& hull, const CheckedHull& c,
                           CheckReport& out) const {
    for (int f : hull.faces) {
      if (!face_covered(facts_.normal[f], mesh_.triangles[f], hull, c, out)) {
        const FaceOffHull off = face_off_hull(mesh_, facts_.normal[f], mesh_.triangles[f], hull, c);
        ++out.faces_off_hull;
        note(out, where + "face " + std::to_string(f) + " not on the hull with its normal out (" +
                      std::to_string(off.in_front) + " in front, a corner " + std::to_string(off.corner_off) +
                      " off its surface)");
      }
    }
  }

  // Condition 3 (flat): no bar crosses the polygon's relative interior.
  void check_bars_across_flat(const std::string& where, const CheckedHull& c, const Eigen::Vector3d& lo,
                              const Eigen::Vector3d& hi, CheckReport& out) const {
    for (int b : grids_.bars.query(lo, hi))
      if (recheck::segment_crosses_flat(c, facts_.bars[b].a, facts_.bars[b].b, c.tol)) {
        ++out.bars_inside;
        note(out, where + "bar " + std::to_string(b) + " crosses the polygon");
      }
  }

  // Condition 4: no face outside the hull's patch touches the polygon's
  // interior from below.
  void check_faces_below_flat(const std::string& where, const HullUnderCheck& hull, const CheckedHull& c,
                              const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, CheckReport& out) const {
    for (int f : grids_.faces.query(lo, hi)) {
      if (std::binary_search(hull.faces.begin(), hull.faces.end(), f)) continue;
      const Eigen::Vector3i& t = mesh_.triangles[f];
      // A hull read from a file claims no faces: those lying on it (within
      // the on-hull distance, as coverage counts them) are its own.
      bool on_polygon = hull.faces.empty();
      for (int k = 0; k < 3; ++k)
        on_polygon &= std::abs(c.front.n.dot(mesh_.positions[t[k]]) - c.front.d) <= on_hull(c);
      if (on_polygon) continue;
      if (reaches_below_polygon(mesh_, t, c, c.tol, on_hull(c))) {
        ++out.faces_below_polygon;
        note(out, where + "face " + std::to_string(f) + " reaches below the polygon's interior");
      }
    }
  }

  // Conditions 1 and 3 (solid): no mesh vertex, edge part or bar strictly inside.
  void check_solid(const std::string& where, const CheckedHull& c, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                   CheckReport& out) const {
    for (int v : grids_.vertices.query(lo, hi))
      if (depth_inside(c.facets, mesh_.positions[v]) > c.tol) {
        ++out.vertices_inside;
        note(out, where + "vertex " + std::to_string(v) + " inside");
      }
    for (int e : grids_.edges.query(lo, hi)) {
      const auto& [p, q] = facts_.edges[e];
      if (recheck::segment_deeper_than(c.facets, mesh_.positions[p], mesh_.positions[q], c.tol)) {
        ++out.edges_inside;
        note(out, where + "edge " + std::to_string(p) + "-" + std::to_string(q) + " inside");
      }
    }
    for (int b : grids_.bars.query(lo, hi))
      if (recheck::segment_deeper_than(c.facets, facts_.bars[b].a, facts_.bars[b].b, c.tol)) {
        ++out.bars_inside;
        note(out, where + "bar " + std::to_string(b) + " inside");
      }
  }

  const bool inside_allowed_;
  const Mesh& mesh_;
  const double largest_on_hull_; // the largest island's on-hull distance
  // A point this close to hull c's surface is on it.
  static double on_hull(const CheckedHull& c) { return kOnHullInTolerances * c.tol; }
  const recheck::MeshFacts facts_;
  const Aabb scene_;
  const double cell_;
  const recheck::CandidateGrids grids_;
};

} // namespace

std::string CheckReport::summary() const {
  std::ostringstream s;
  s << "vertices_inside " << vertices_inside << ", edges_inside " << edges_inside << ", faces_off_hull "
    << faces_off_hull << ", bars_inside " << bars_inside << ", faces_below_polygon " << faces_below_polygon
    << ", faces_uncovered " << faces_uncovered << ", hulls_not_convex " << hulls_not_convex;
  if (inside_allowed) s << " (faces may lie inside hulls: " << faces_inside << " do)";
  for (const std::string& e : examples) s << "\n  " << e;
  return s.str();
}

std::vector<HullUnderCheck> hulls_under_check(const Covering& covering) {
  std::vector<HullUnderCheck> out;
  for (const CoveringHull& h : covering.hulls)
    out.push_back({&h.polytope, (h.planar && h.thickness == 0.0) || has_flat_facets(h.polytope.facets), h.faces});
  return out;
}

std::vector<HullUnderCheck> hulls_under_check(const std::vector<bvh::RuntimeHull>& hulls) {
  std::vector<HullUnderCheck> out;
  for (const bvh::RuntimeHull& h : hulls) out.push_back({&h.shape, has_flat_facets(h.shape.facets), {}});
  return out;
}

CheckReport check_covering_independently(const PreparedMesh& prepared, const Covering& covering, bool inside_allowed) {
  return recheck_hulls(prepared, hulls_under_check(covering), covering.bar_half_length, inside_allowed);
}

CheckReport recheck_hulls(const PreparedMesh& prepared, const std::vector<HullUnderCheck>& hulls,
                          double bar_half_length, bool inside_allowed, int threads) {
  CheckReport report;
  report.inside_allowed = inside_allowed;
  threads = threads < 0 ? 1 : threads_to_use(threads);
  const Rechecker rechecker(prepared, bar_half_length, inside_allowed);
  const int hull_count = static_cast<int>(hulls.size());
  std::vector<CheckedHull> checked(hulls.size());
  const PlaceTolerance place_tolerance(prepared.tolerance);
  parallel_for(hull_count, threads, [&](int h) {
    checked[h] = recheck::make_checked(hulls[h]);
    Aabb box;
    box.extend(checked[h].lo);
    box.extend(checked[h].hi);
    checked[h].tol = place_tolerance.at(box);
  });
  CandidateGrid hull_grid = rechecker.empty_grid();
  for (int h = 0; h < hull_count; ++h) hull_grid.insert(h, checked[h].lo, checked[h].hi);
  // Each hull's findings, then each face's, each in a part of its own (a
  // batch's worth at a time), added to the report in hull and face order.
  std::vector<CheckReport> parts(kPartsPerBatch);
  const auto add_part = [&](int i) {
    CheckReport& part = parts[i % kPartsPerBatch];
    add_findings(report, part);
    part = CheckReport{};
  };
  parallel_for_ordered(
      hull_count, threads, kPartsPerBatch,
      [&](int h) { rechecker.check_hull(h, hulls[h], checked[h], parts[h % kPartsPerBatch]); }, add_part);
  std::vector<char> claimed(rechecker.face_count(), 0);
  for (const HullUnderCheck& hull : hulls)
    for (int f : hull.faces) claimed[f] = 1;
  parallel_for_ordered(
      rechecker.face_count(), threads, kPartsPerBatch,
      [&](int f) {
    rechecker.check_face_coverage(f, claimed[f] != 0, hulls, checked, hull_grid, parts[f % kPartsPerBatch]);
      },
      add_part);
  return report;
}

bool segment_hits_covering(const Covering& covering, const Eigen::Vector3d& p, const Eigen::Vector3d& q, double tol) {
  for (const HullUnderCheck& hull : hulls_under_check(covering)) {
    const CheckedHull c = recheck::make_checked(hull);
    if (c.flat ? recheck::segment_crosses_flat(c, p, q, tol) : recheck::segment_deeper_than(c.facets, p, q, tol))
      return true;
  }
  return false;
}

bool point_inside_covering(const Covering& covering, const Eigen::Vector3d& p, double tol) {
  for (const HullUnderCheck& hull : hulls_under_check(covering)) {
    const CheckedHull c = recheck::make_checked(hull);
    if (!c.flat && depth_inside(c.facets, p) > tol) return true;
  }
  return false;
}

} // namespace hullcover::validate
