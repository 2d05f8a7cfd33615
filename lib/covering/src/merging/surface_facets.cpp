#include "merging/surface_facets.h"

#include "hullcover/geometry/planar_hull.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace hullcover::detail {
namespace {

// The strip beyond a flat polygon's rim edge, in its plane, this many tol
// wide: shrunk by tol it still holds 2 tol, so a face running on past the
// edge reaches it, while a face that only touches the edge does not.
constexpr double kRimStripInTolerances = 4.0;

// A face counts as lying in a plane when its part within tol of the plane
// reaches in and it runs within this angle of the plane (as a cosine): a
// large face tilted a little from a hull facet (merged within tol of
// neighbours) has corners far off the plane yet lies along it, while a wall
// standing on a floor crosses the floor's plane at a steep angle and does
// not.
const double kAlongPlaneCosine = std::cos(5.0 * M_PI / 180.0);

// Whether a mesh face lying in `polygon`'s plane reaches its interior
// shrunk by tol.
bool face_in_polygon(const SceneIndex& index, const FlatPolygon& polygon, std::vector<int>& scratch) {
  const double tol = index.tol();
  std::vector<Eigen::Vector3d> triangle(3);
  scratch.clear();
  index.face_tree.overlapping(grown(bounding_box_of(polygon.corners), tol), scratch);
  for (int g : scratch) {
    if (!(index.face_areas[g] > 0.0)) continue;
    if (std::abs(index.face_normals[g].dot(polygon.plane.normal)) < kAlongPlaneCosine) continue;
    triangle_corners(index.mesh(), g, triangle);
    if (meets_polygon_interior(polygon, triangle, tol)) return true;
  }
  return false;
}

FlatPolygon polygon_of(std::vector<Eigen::Vector3d> corners, const Plane& plane) {
  FlatPolygon polygon;
  polygon.corners = std::move(corners);
  polygon.plane = plane;
  polygon.sides = polygon_side_planes(polygon.corners, plane.normal);
  return polygon;
}

} // namespace

std::vector<bool> surface_planes(const SceneIndex& index, const ConvexPolytope& polytope, std::vector<int>& scratch) {
  const double tol = index.tol();
  const size_t facets = polytope.facets.size();
  std::vector<bool> on_surface(polytope.planes.size(), true);
  std::vector<bool> on_face(facets, false);
  std::vector<std::vector<Eigen::Vector3d>> corners(facets);
  for (size_t f = 0; f < facets; ++f) {
    for (int v : polytope.facets[f]) corners[f].push_back(polytope.vertices[v]);
    on_face[f] = face_in_polygon(index, polygon_of(corners[f], polytope.planes[f]), scratch);
  }
  // Whether the surface runs on, in `plane`, past the edge a-b of a polygon
  // lying on the side of it where `inside` is.
  const auto runs_on_past =
      [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Plane& plane, const Eigen::Vector3d& inside) {
    Eigen::Vector3d out = (b - a).cross(plane.normal);
    if (out.dot(inside - a) > 0.0) out = -out;
    if (!(out.norm() > 0.0)) return false;
    out *= kRimStripInTolerances * tol / out.norm();
    // Counter-clockwise about the plane's normal, as polygon_side_planes needs.
    std::vector<Eigen::Vector3d> strip = {a, b, b + out, a + out};
    if ((b - a).cross(out).dot(plane.normal) < 0.0) strip = {b, a, a + out, b + out};
    return face_in_polygon(index, polygon_of(strip, plane), scratch);
  };
  // A facet on no face is the surface's own (a contact keeps its normal)
  // unless, past an edge it shares with a facet on a face, the surface runs
  // on: then it is the side of a seam between hulls.
  for (size_t f = 0; f < facets; ++f) {
    if (on_face[f]) continue;
    const std::vector<int>& poly = polytope.facets[f];
    for (size_t i = 0; i < poly.size() && on_surface[f]; ++i) {
      const int u = poly[i], v = poly[(i + 1) % poly.size()];
      for (size_t g = 0; g < facets && on_surface[f]; ++g) {
        if (g == f || !on_face[g]) continue;
        const std::vector<int>& other = polytope.facets[g];
        const bool shares = std::find(other.begin(), other.end(), u) != other.end() &&
                            std::find(other.begin(), other.end(), v) != other.end();
        if (shares &&
            runs_on_past(polytope.vertices[u], polytope.vertices[v], polytope.planes[g], centroid_of(corners[g])))
          on_surface[f] = false;
      }
    }
  }
  // A flat polygon's side planes: the rim edge each holds, from the front
  // facet's corners.
  if (facets == 0) return on_surface;
  const std::vector<Eigen::Vector3d>& rim = corners[0];
  const Eigen::Vector3d middle = centroid_of(rim);
  for (size_t p = facets; p < polytope.planes.size(); ++p) {
    const Plane& side = polytope.planes[p];
    for (size_t i = 0; i < rim.size(); ++i) {
      const Eigen::Vector3d& a = rim[i];
      const Eigen::Vector3d& b = rim[(i + 1) % rim.size()];
      if (std::abs(side.signed_distance(a)) > tol || std::abs(side.signed_distance(b)) > tol) continue;
      on_surface[p] = !runs_on_past(a, b, polytope.planes[0], middle);
      break;
    }
  }
  return on_surface;
}

} // namespace hullcover::detail
