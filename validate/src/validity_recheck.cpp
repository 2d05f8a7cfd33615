#include "hullcover/validate/validity_recheck.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <unordered_map>

namespace hullcover::validate {
namespace {

struct HalfSpace {
  Eigen::Vector3d n;  // unit, outward
  double d;           // inside: n.x <= d
};

// A hull as this checker sees it.
struct CheckedHull {
  std::vector<HalfSpace> facets;  // solid: one per facet; flat: front, back and sides
  bool flat = false;
  HalfSpace front;                // flat: the polygon's plane
  std::vector<HalfSpace> sides;   // flat: in-plane edge half-spaces
  Eigen::Vector3d lo, hi;
};

HalfSpace newell_plane(const std::vector<Eigen::Vector3d>& poly) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero(), centre = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector3d& a = poly[i];
    const Eigen::Vector3d& b = poly[(i + 1) % poly.size()];
    n += Eigen::Vector3d((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()),
                         (a.x() - b.x()) * (a.y() + b.y()));
    centre += a;
  }
  centre /= static_cast<double>(poly.size());
  n.normalize();
  return {n, n.dot(centre)};
}

CheckedHull make_checked(const HullUnderCheck& hull) {
  CheckedHull c;
  const auto& V = hull.shape->vertices;
  c.lo = c.hi = V.front();
  for (const auto& p : V) {
    c.lo = c.lo.cwiseMin(p);
    c.hi = c.hi.cwiseMax(p);
  }
  std::vector<Eigen::Vector3d> poly;
  for (const auto& facet : hull.shape->facets) {
    poly.clear();
    for (int v : facet) poly.push_back(V[v]);
    c.facets.push_back(newell_plane(poly));
  }
  c.flat = hull.flat;
  if (c.flat) {
    c.front = c.facets.front();
    poly.clear();
    for (int v : hull.shape->facets.front()) poly.push_back(V[v]);
    for (size_t i = 0; i < poly.size(); ++i) {
      const Eigen::Vector3d e = poly[(i + 1) % poly.size()] - poly[i];
      const Eigen::Vector3d out = e.cross(c.front.n).normalized();
      c.sides.push_back({out, out.dot(poly[i])});
    }
    // A point is on a flat hull when it is on its plane AND within its sides.
    c.facets.insert(c.facets.end(), c.sides.begin(), c.sides.end());
  }
  return c;
}

double depth_inside(const std::vector<HalfSpace>& hs, const Eigen::Vector3d& p) {
  double worst = INFINITY;
  for (const HalfSpace& h : hs) worst = std::min(worst, h.d - h.n.dot(p));
  return worst;  // > tol: strictly inside
}

// Longest sub-interval of segment p-q deeper than tol inside all half-spaces.
bool segment_deeper_than(const std::vector<HalfSpace>& hs, const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                         double tol) {
  double lo = 0.0, hi = 1.0;
  const Eigen::Vector3d d = q - p;
  for (const HalfSpace& h : hs) {
    // need h.n.(p + t d) <= h.d - tol
    const double slope = h.n.dot(d);
    const double room = h.d - tol - h.n.dot(p);
    if (std::abs(slope) < 1e-300) {
      if (room <= 0.0) return false;
      continue;
    }
    const double t = room / slope;
    if (slope > 0.0)
      hi = std::min(hi, t);
    else
      lo = std::max(lo, t);
    if (lo >= hi) return false;
  }
  return lo < hi;
}

// Does segment p-q cross the flat polygon's relative interior?
bool segment_crosses_flat(const CheckedHull& c, const Eigen::Vector3d& p, const Eigen::Vector3d& q, double tol) {
  const double dp = c.front.n.dot(p) - c.front.d, dq = c.front.n.dot(q) - c.front.d;
  if (std::abs(dp - dq) <= tol) return false;  // runs along the plane
  if ((dp > tol && dq > tol) || (dp < -tol && dq < -tol)) return false;
  const Eigen::Vector3d x = p + (q - p) * (dp / (dp - dq));
  return depth_inside(c.sides, x) > tol;
}

struct Grid {
  double cell;
  Eigen::Vector3d origin;
  std::unordered_map<long long, std::vector<int>> cells;
  long long key(long long i, long long j, long long k) const { return (i * 73856093LL) ^ (j * 19349663LL) ^ (k * 83492791LL); }
  Eigen::Vector3i at(const Eigen::Vector3d& p) const {
    return ((p - origin) / cell).array().floor().cast<int>();
  }
  void insert(int id, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
    const Eigen::Vector3i a = at(lo), b = at(hi);
    for (int i = a.x(); i <= b.x(); ++i)
      for (int j = a.y(); j <= b.y(); ++j)
        for (int k = a.z(); k <= b.z(); ++k) cells[key(i, j, k)].push_back(id);
  }
  std::vector<int> query(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) const {
    std::vector<int> out;
    const Eigen::Vector3i a = at(lo), b = at(hi);
    for (int i = a.x(); i <= b.x(); ++i)
      for (int j = a.y(); j <= b.y(); ++j)
        for (int k = a.z(); k <= b.z(); ++k) {
          const auto it = cells.find(key(i, j, k));
          if (it != cells.end()) out.insert(out.end(), it->second.begin(), it->second.end());
        }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }
};

}  // namespace

std::string CheckReport::summary() const {
  std::ostringstream s;
  s << "vertices_inside " << vertices_inside << ", edges_inside " << edges_inside << ", faces_off_hull "
    << faces_off_hull << ", bars_inside " << bars_inside << ", faces_below_polygon " << faces_below_polygon
    << ", faces_uncovered " << faces_uncovered << ", hulls_not_convex " << hulls_not_convex;
  for (const std::string& e : examples) s << "\n  " << e;
  return s.str();
}

namespace {

// Flat: two facets on the same corners in opposite order (front and back),
// whatever the decomposer calls the hull.
bool has_flat_facets(const std::vector<std::vector<int>>& f) {
  bool flat = f.size() == 2 && f[0].size() == f[1].size();
  for (size_t i = 0; flat && i < f[0].size(); ++i) flat = f[0][i] == f[1][f[1].size() - 1 - i];
  return flat;
}

} // namespace

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

CheckReport check_covering_independently(const PreparedMesh& prepared, const Covering& covering) {
  return recheck_hulls(prepared, hulls_under_check(covering), covering.bar_half_length);
}

CheckReport recheck_hulls(const PreparedMesh& prepared, const std::vector<HullUnderCheck>& hulls,
                          double bar_half_length) {
  CheckReport report;
  const Mesh& mesh = prepared.mesh;
  const double tol = prepared.tolerance.length;
  const auto note = [&](const std::string& what) {
    if (report.examples.size() < 8) report.examples.push_back(what);
  };

  // Faces with a surface, their unit normals, and their edges counted again.
  const int F = static_cast<int>(mesh.triangles.size());
  std::vector<Eigen::Vector3d> normal(F, Eigen::Vector3d::Zero());
  std::vector<char> has_surface(F, 0);
  std::map<std::pair<int, int>, std::vector<int>> edge_faces;
  double longest_edge = 0;
  for (int f = 0; f < F; ++f) {
    const Eigen::Vector3i& t = mesh.triangles[f];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
    for (int k = 0; k < 3; ++k) {
      edge_faces[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}].push_back(f);
      longest_edge = std::max(longest_edge, (mesh.positions[t[k]] - mesh.positions[t[(k + 1) % 3]]).norm());
    }
    const Eigen::Vector3d a = mesh.positions[t[0]];
    const Eigen::Vector3d cr = (mesh.positions[t[1]] - a).cross(mesh.positions[t[2]] - a);
    double longest = 0;
    for (int k = 0; k < 3; ++k) longest = std::max(longest, (mesh.positions[t[(k + 1) % 3]] - mesh.positions[t[k]]).norm());
    if (cr.norm() > tol * longest) {
      has_surface[f] = 1;
      normal[f] = cr.normalized();
    }
  }
  struct Bar { Eigen::Vector3d a, b; };
  std::vector<Bar> bars;
  std::vector<std::pair<int, int>> edges;
  for (const auto& [e, faces] : edge_faces) {
    edges.push_back(e);
    if (faces.size() == 1 && has_surface[faces[0]]) {
      const Eigen::Vector3d mid = 0.5 * (mesh.positions[e.first] + mesh.positions[e.second]);
      bars.push_back({mid - bar_half_length * normal[faces[0]], mid + bar_half_length * normal[faces[0]]});
    }
  }

  // Uniform grids over vertices, edges, bars and faces.
  const Aabb scene = referenced_bounding_box(mesh);
  const double cell = std::max(longest_edge, scene.diagonal() / 200.0);
  Grid vgrid{cell, scene.min, {}}, egrid{cell, scene.min, {}}, bgrid{cell, scene.min, {}}, fgrid{cell, scene.min, {}};
  for (int v = 0; v < static_cast<int>(mesh.positions.size()); ++v) vgrid.insert(v, mesh.positions[v], mesh.positions[v]);
  for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
    const auto& p = mesh.positions[edges[e].first];
    const auto& q = mesh.positions[edges[e].second];
    egrid.insert(e, p.cwiseMin(q), p.cwiseMax(q));
  }
  for (int b = 0; b < static_cast<int>(bars.size()); ++b)
    bgrid.insert(b, bars[b].a.cwiseMin(bars[b].b), bars[b].a.cwiseMax(bars[b].b));
  for (int f = 0; f < F; ++f) {
    const Eigen::Vector3i& t = mesh.triangles[f];
    const Eigen::Vector3d lo = mesh.positions[t[0]].cwiseMin(mesh.positions[t[1]]).cwiseMin(mesh.positions[t[2]]);
    const Eigen::Vector3d hi = mesh.positions[t[0]].cwiseMax(mesh.positions[t[1]]).cwiseMax(mesh.positions[t[2]]);
    fgrid.insert(f, lo, hi);
  }

  std::vector<char> covered(F, 0);
  std::vector<CheckedHull> checked;
  Grid hgrid{cell, scene.min, {}};
  for (size_t h = 0; h < hulls.size(); ++h) {
    const HullUnderCheck& hull = hulls[h];
    const CheckedHull c = make_checked(hull);
    const Eigen::Vector3d lo = c.lo.array() - 2 * tol, hi = c.hi.array() + 2 * tol;
    checked.push_back(c);
    hgrid.insert(static_cast<int>(h), c.lo, c.hi);
    const std::string where = "hull " + std::to_string(h) + " (" + std::to_string(hull.faces.size()) + " faces" +
                              (hull.flat ? ", flat" : "") + "): ";
    for (const auto& p : hull.shape->vertices)
      for (size_t fi = 0; fi < hull.shape->facets.size(); ++fi)
        if (const HalfSpace& plane = c.facets[fi]; plane.n.dot(p) - plane.d > tol) {
          std::ostringstream detail;
          detail << "facet " << fi << " of size " << hull.shape->facets[fi].size() << " n " << plane.n.transpose()
                 << " p " << p.transpose();
          note(detail.str());
          ++report.hulls_not_convex;
          note(where + "not convex: a vertex " + std::to_string(plane.n.dot(p) - plane.d) + " in front of a facet of " +
               std::to_string(hull.shape->facets.size()));
          goto convex_checked;
        }
  convex_checked:
    // Condition 2 and coverage: each covered face's plane supports the hull
    // (every hull vertex behind it) and its corners lie on the hull.
    for (int f : hull.faces) {
      covered[f] = 1;
      const Eigen::Vector3i& t = mesh.triangles[f];
      const Eigen::Vector3d& a = mesh.positions[t[0]];
      double in_front = 0.0, corner_off = 0.0;
      for (const auto& p : hull.shape->vertices) in_front = std::max(in_front, normal[f].dot(p - a));
      // Off the surface either way: deep inside, or outside the hull.
      for (int k = 0; k < 3; ++k)
        corner_off = std::max(corner_off, std::abs(depth_inside(c.facets, mesh.positions[t[k]])));
      // A flat hull has a facet either way: faces of either side lie on it.
      if (in_front > 2 * tol || corner_off > 2 * tol) {
        ++report.faces_off_hull;
        note(where + "face " + std::to_string(f) + " not on the hull with its normal out (" +
             std::to_string(in_front) + " in front, a corner " + std::to_string(corner_off) + " off its surface)");
      }
    }
    // A flat hull that is one face (claimed, or a bare triangle from another
    // tool): whatever crosses it crosses the mesh itself.
    if (c.flat && (hull.faces.size() == 1 || (hull.faces.empty() && hull.shape->vertices.size() == 3))) continue;
    if (c.flat) {
      // Condition 3 (flat): no bar crosses the relative interior.
      for (int b : bgrid.query(lo, hi))
        if (segment_crosses_flat(c, bars[b].a, bars[b].b, tol)) {
          ++report.bars_inside;
          note(where + "bar " + std::to_string(b) + " crosses the polygon");
        }
      // Condition 4: faces outside the hull's patch touching the interior from below.
      for (int f : fgrid.query(lo, hi)) {
        if (std::binary_search(hull.faces.begin(), hull.faces.end(), f)) continue;
        const Eigen::Vector3i& t = mesh.triangles[f];
        // A hull read from a file claims no faces: those lying on it (within
        // 2 tol, as coverage counts them) are its own.
        bool on_polygon = hull.faces.empty();
        for (int k = 0; k < 3; ++k)
          on_polygon &= std::abs(c.front.n.dot(mesh.positions[t[k]]) - c.front.d) <= 2 * tol;
        if (on_polygon) continue;
        bool below = false;
        for (int k = 0; k < 3; ++k) below |= c.front.n.dot(mesh.positions[t[k]]) - c.front.d < -tol;
        if (!below) continue;
        // Sample the triangle's crossing with the plane: its edges' crossing points and vertices on it.
        std::vector<Eigen::Vector3d> on_plane;
        for (int k = 0; k < 3; ++k) {
          const Eigen::Vector3d p = mesh.positions[t[k]], q = mesh.positions[t[(k + 1) % 3]];
          const double dp = c.front.n.dot(p) - c.front.d, dq = c.front.n.dot(q) - c.front.d;
          if (std::abs(dp) <= tol) on_plane.push_back(p);
          if ((dp < -tol && dq > tol) || (dp > tol && dq < -tol)) on_plane.push_back(p + (q - p) * (dp / (dp - dq)));
        }
        bool touches = false;
        for (size_t i = 0; i < on_plane.size() && !touches; ++i)
          for (size_t j = i; j < on_plane.size() && !touches; ++j)
            for (int s = 0; s <= 16 && !touches; ++s) {
              const Eigen::Vector3d x = on_plane[i] + (on_plane[j] - on_plane[i]) * (s / 16.0);
              touches = depth_inside(c.sides, x) > 2 * tol;
            }
        if (touches) {
          ++report.faces_below_polygon;
          note(where + "face " + std::to_string(f) + " reaches below the polygon's interior");
        }
      }
      continue;
    }
    // Condition 1: no mesh vertex or edge part strictly inside.
    for (int v : vgrid.query(lo, hi))
      if (depth_inside(c.facets, mesh.positions[v]) > tol) {
        ++report.vertices_inside;
        note(where + "vertex " + std::to_string(v) + " inside");
      }
    for (int e : egrid.query(lo, hi))
      if (segment_deeper_than(c.facets, mesh.positions[edges[e].first], mesh.positions[edges[e].second], tol)) {
        ++report.edges_inside;
        note(where + "edge " + std::to_string(edges[e].first) + "-" + std::to_string(edges[e].second) + " inside");
      }
    // Condition 3: no bar enters the interior.
    for (int b : bgrid.query(lo, hi))
      if (segment_deeper_than(c.facets, bars[b].a, bars[b].b, tol)) {
        ++report.bars_inside;
        note(where + "bar " + std::to_string(b) + " inside");
      }
  }
  // Faces no hull claims: covered when on some hull's boundary, normal out.
  for (int f = 0; f < F; ++f) {
    if (!has_surface[f]) continue;
    const Eigen::Vector3i& t = mesh.triangles[f];
    const Eigen::Vector3d &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
    const double area = 0.5 * (b - a).cross(c - a).norm();
    report.total_area += area;
    if (covered[f]) continue;
    const Eigen::Vector3d lo = a.cwiseMin(b).cwiseMin(c).array() - 2 * tol, hi = a.cwiseMax(b).cwiseMax(c).array() + 2 * tol;
    for (int h : hgrid.query(lo, hi)) {
      const HullUnderCheck& hull = hulls[h];
      double in_front = 0.0, off = 0.0;
      for (const auto& p : hull.shape->vertices) in_front = std::max(in_front, normal[f].dot(p - a));
      for (const Eigen::Vector3d* corner : {&a, &b, &c}) off = std::max(off, std::abs(depth_inside(checked[h].facets, *corner)));
      // A flat hull has a facet either way: a face on it is on its boundary
      // whichever way it faces (a double-sided sheet's two faces).
      if (in_front <= 2 * tol && off <= 2 * tol) {
        covered[f] = 1;
        break;
      }
    }
    if (!covered[f]) {
      ++report.faces_uncovered;
      report.uncovered_area += area;
      note("face " + std::to_string(f) + " is on no hull");
    }
  }
  return report;
}

bool segment_hits_covering(const Covering& covering, const Eigen::Vector3d& p, const Eigen::Vector3d& q, double tol) {
  for (const HullUnderCheck& hull : hulls_under_check(covering)) {
    const CheckedHull c = make_checked(hull);
    if (c.flat ? segment_crosses_flat(c, p, q, tol) : segment_deeper_than(c.facets, p, q, tol)) return true;
  }
  return false;
}

bool point_inside_covering(const Covering& covering, const Eigen::Vector3d& p, double tol) {
  for (const HullUnderCheck& hull : hulls_under_check(covering)) {
    const CheckedHull c = make_checked(hull);
    if (!c.flat && depth_inside(c.facets, p) > tol) return true;
  }
  return false;
}

} // namespace hullcover::validate
