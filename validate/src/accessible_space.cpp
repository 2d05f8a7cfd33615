#include "hullcover/validate/accessible_space.h"

#include "hullcover/geometry/tolerances.h"

#include <octomap/OcTree.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace hullcover::validate {
namespace {

// OctoMap keys have 16 bits per axis: 32768 cells either side of its origin.
constexpr double kMaxCellsPerAxis = 32768.0;

// Closest point of triangle abc to p (Ericson, Real-Time Collision
// Detection, 5.1.5).
Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                    const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + ab * (d1 / (d1 - d3));
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

class Prober {
public:
  Prober(const PreparedMesh& prepared, const bvh::TriangleWorld& triangles, const bvh::HullWorld& hulls,
         ProbeReport& report)
      : prepared_(prepared), triangles_(triangles), hulls_(hulls), report_(report),
        tol_(prepared.tolerance.length), tree_(report.resolution) {
    const Aabb box = referenced_bounding_box(prepared.mesh);
    centre_ = 0.5 * (box.min + box.max);
    report.octree_origin = centre_;
  }

  // The octree is centred on the scene (its keys reach 32768 cells either
  // way from its origin), and holds float coordinates.
  octomap::point3d to_octomap(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d local = p - centre_;
    return {static_cast<float>(local.x()), static_cast<float>(local.y()), static_cast<float>(local.z())};
  }

  // How deep p lies inside the hulls (<= 0 when outside every one), and which.
  double depth_in_hulls(const Eigen::Vector3d& p, int& hull) const {
    bvh::ContactResult contacts;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = p;
    hull = -1;
    if (!hulls_.contacts({bvh::QueryShape::sphere(tol_), pose, 1}, contacts).ok() || contacts.contacts.empty())
      return 0.0;
    hull = contacts.contacts[0].hull;
    return contacts.contacts[0].depth - tol_;  // a sphere of radius tol: its centre's depth
  }

  // Walks the ray from `origin` along unit `dir` to R or the first mesh
  // hit; every `resolution` a free point, tested against the hulls.
  void walk(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, int face, bool opening) {
    // Off the surface it leaves, and as far short of the one it hits: the
    // surfaces themselves are not free (the decomposer's witness rays too).
    const double stand_off = kRayStandOffInTolerances * tol_;
    const Eigen::Vector3d start = origin + dir * stand_off;
    // The first face along the whole ray (not only within R) tells whether
    // the space is enclosed: met from behind, the ray runs inside something
    // (a solid the face is resting against, the space under a table top).
    bvh::RayResult hit;
    double reach = report_.probe_distance;
    bool enclosed = false;
    if (triangles_.ray_cast({start, dir, prepared_.tolerance.diagonal}, hit).ok() && hit.hit) {
      reach = std::min(reach, hit.first.t - stand_off);
      // Enclosed only when every face at the first hit (coincident ones
      // included) is met from behind: one met from the front there (a
      // ceiling coincident with the floor above) ends the ray on a front,
      // which is open space (DESIGN.md). Opening rays are never enclosed
      // here, as the decomposer's E2 still has it.
      std::vector<bvh::RayHit> at_hit;
      if (!opening && triangles_.ray_hits({start, dir, hit.first.t + stand_off}, at_hit).ok() && !at_hit.empty()) {
        enclosed = true;
        for (const bvh::RayHit& h : at_hit)
          enclosed &= triangle_area_vector(prepared_.mesh, h.hull).dot(dir) > 0.0;
      }
    }
    for (double t = std::min(report_.resolution, reach); t <= reach && reach > 0.0; t += report_.resolution) {
      const Eigen::Vector3d q = start + t * dir;
      if (!enclosed) tree_.updateNode(to_octomap(q), false, true);  // the octree holds accessible space only
      int hull = -1;
      const double depth = depth_in_hulls(q, hull);
      const bool lost = depth > tol_;
      if (opening) {
        ++report_.opening_points;
        report_.opening_lost += lost;
      } else if (enclosed) {
        ++report_.enclosed_points;
        report_.enclosed_in_hulls += lost;
      } else {
        ++report_.front_points;
        report_.front_lost += lost;
      }
      if (lost && !enclosed) {
        note({q, face, hull, depth, opening});
        lost_keys_.insert(tree_.coordToKey(to_octomap(q)));
      }
    }
  }

  void note(const LostPlace& place) {
    report_.max_lost_depth = std::max(report_.max_lost_depth, place.depth);
    report_.worst.push_back(place);
    std::sort(report_.worst.begin(), report_.worst.end(),
              [](const LostPlace& a, const LostPlace& b) { return a.depth > b.depth; });
    if (report_.worst.size() > kWorstPlaces) report_.worst.pop_back();
  }

  void probe_faces() {
    const Mesh& mesh = prepared_.mesh;
    for (int f = 0; f < static_cast<int>(mesh.triangles.size()); ++f) {
      if (prepared_.connectivity.zero_area[f]) continue;
      const Eigen::Vector3d n = triangle_area_vector(mesh, f).normalized();
      const Eigen::Vector3i& t = mesh.triangles[f];
      const Eigen::Vector3d &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
      const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
      const int m = std::max(1, static_cast<int>(std::ceil(longest / report_.resolution)));
      // A triangular grid of m(m+1)/2 points inside the face.
      for (int i = 0; i < m; ++i)
        for (int j = 0; i + j < m; ++j) {
          const double u = (i + 1.0 / 3.0) / m, v = (j + 1.0 / 3.0) / m;
          const Eigen::Vector3d p = a + u * (b - a) + v * (c - a);
          walk(p, n, f, false);
        }
    }
  }

  void probe_openings() {
    const Mesh& mesh = prepared_.mesh;
    const MeshConnectivity& con = prepared_.connectivity;
    for (const MeshEdge& e : con.edges) {
      if (e.kind != EdgeKind::boundary) continue;
      const EdgeUse& use = con.edge_uses[e.first_use];
      if (con.zero_area[use.face]) continue;
      const Eigen::Vector3i& t = mesh.triangles[use.face];
      const Eigen::Vector3d& p0 = mesh.positions[t[use.corner]];
      const Eigen::Vector3d& p1 = mesh.positions[t[(use.corner + 1) % 3]];
      const Eigen::Vector3d& other = mesh.positions[t[(use.corner + 2) % 3]];
      const Eigen::Vector3d n = triangle_area_vector(mesh, use.face).normalized();
      Eigen::Vector3d out = (p1 - p0).cross(n).normalized();
      if (out.dot(other - p0) > 0.0) out = -out;
      const int m = std::max(1, static_cast<int>(std::ceil((p1 - p0).norm() / report_.resolution)));
      for (int k = 0; k < m; ++k) walk(p0 + (p1 - p0) * ((k + 0.5) / m), out, use.face, true);
    }
  }

  // Every cell a face passes within half a cell diagonal of its centre
  // becomes occupied (conservative: point samples would miss corners).
  void mark_surface_cells() {
    const Mesh& mesh = prepared_.mesh;
    const double half_diagonal = 0.5 * std::sqrt(3.0) * report_.resolution;
    const float occupied = tree_.getClampingThresMaxLog();
    for (int f = 0; f < static_cast<int>(mesh.triangles.size()); ++f) {
      const Eigen::Vector3i& t = mesh.triangles[f];
      const Eigen::Vector3d &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
      const Eigen::Vector3d lo = a.cwiseMin(b).cwiseMin(c).array() - half_diagonal;
      const Eigen::Vector3d hi = a.cwiseMax(b).cwiseMax(c).array() + half_diagonal;
      const octomap::OcTreeKey k0 = tree_.coordToKey(to_octomap(lo)), k1 = tree_.coordToKey(to_octomap(hi));
      for (unsigned x = k0[0]; x <= k1[0]; ++x)
        for (unsigned y = k0[1]; y <= k1[1]; ++y)
          for (unsigned z = k0[2]; z <= k1[2]; ++z) {
            const octomap::OcTreeKey key(static_cast<octomap::key_type>(x), static_cast<octomap::key_type>(y),
                                         static_cast<octomap::key_type>(z));
            const octomap::point3d centre = tree_.keyToCoord(key);
            const Eigen::Vector3d p = centre_ + Eigen::Vector3d(centre.x(), centre.y(), centre.z());
            if ((closest_on_triangle(p, a, b, c) - p).squaredNorm() <= half_diagonal * half_diagonal)
              tree_.setNodeValue(key, occupied, true);
          }
    }
  }

  void fill_octree_and_count_cells() {
    mark_surface_cells();
    tree_.updateInnerOccupancy();
    for (auto leaf = tree_.begin_leafs(), end = tree_.end_leafs(); leaf != end; ++leaf) {
      if (tree_.isNodeOccupied(*leaf)) continue;
      const double size = leaf.getSize();
      const octomap::point3d c = leaf.getCoordinate();
      ++report_.free_cells;
      report_.free_volume += size * size * size;
      // A cell is lost when a free sample in it is, or when it lies wholly
      // inside a hull. One whose centre alone is inside straddles a hull's
      // surface: its free sample lies outside, so only part of it may be
      // lost; counted apart.
      int hull = -1;
      const double depth = depth_in_hulls(centre_ + Eigen::Vector3d(c.x(), c.y(), c.z()), hull);
      const bool sample_lost = leaf.getDepth() == tree_.getTreeDepth() && lost_keys_.count(leaf.getKey()) > 0;
      if (sample_lost || depth > tol_ + 0.5 * std::sqrt(3.0) * size) {
        ++report_.lost_cells;
        report_.lost_volume += size * size * size;
      } else if (depth > tol_) {
        ++report_.straddling_cells;
      }
    }
  }

  octomap::OcTree& tree() { return tree_; }

private:
  const PreparedMesh& prepared_;
  const bvh::TriangleWorld& triangles_;
  const bvh::HullWorld& hulls_;
  ProbeReport& report_;
  double tol_;
  octomap::OcTree tree_;
  Eigen::Vector3d centre_;
  std::unordered_set<octomap::OcTreeKey, octomap::OcTreeKey::KeyHash> lost_keys_;  // cells of lost free samples
};

} // namespace

Result<ProbeReport> probe_accessible_space(const PreparedMesh& prepared, const bvh::TriangleWorld& triangles,
                                           const bvh::HullWorld& hulls, const ProbeOptions& options) {
  ProbeReport report;
  const double diagonal = prepared.tolerance.diagonal;
  report.probe_distance = options.probe_distance.value_or(kDefaultProbeRelative * diagonal);
  report.resolution = options.resolution.value_or(report.probe_distance / kDefaultCellsPerProbe);
  if (!(report.probe_distance > 0.0) || !(report.resolution > 0.0) || !std::isfinite(report.probe_distance) ||
      !std::isfinite(report.resolution))
    return Status{StatusCode::invalid_argument, "probe distance and resolution must be positive lengths"};
  if ((0.5 * diagonal + report.probe_distance) / report.resolution > kMaxCellsPerAxis)
    return Status{StatusCode::invalid_argument, "resolution too fine: the octree has 16 levels (32768 cells a side)"};
  try {
    Prober prober(prepared, triangles, hulls, report);
    prober.probe_faces();
    prober.probe_openings();
    prober.fill_octree_and_count_cells();
    if (!options.octree_path.empty() && !prober.tree().writeBinary(options.octree_path))
      return Status{StatusCode::unwritable_file, options.octree_path + ": cannot write the octree"};
    return report;
  } catch (const std::exception& e) {
    return Status{StatusCode::internal_error, std::string("accessible-space probe failed: ") + e.what()};
  }
}

} // namespace hullcover::validate
