#include "hullcover/covering/convex_hull_3d.h"

#include "hullcover/geometry/tolerances.h"

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace hullcover {

// The error sink is opened by the first hull asked for: a builder that
// makes none (a merger of one triangle's island) holds no stream, and a world
// of many such islands keeps no list of open streams for every close to walk.
ConvexHullBuilder::ConvexHullBuilder() = default;

ConvexHullBuilder::~ConvexHullBuilder() {
  if (error_sink_ != nullptr) std::fclose(error_sink_);
}

namespace {

// Orders a facet's vertices counter-clockwise around its outward normal.
void order_around(std::vector<int>& facet, const std::vector<Eigen::Vector3d>& vertices, const Eigen::Vector3d& n) {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int v : facet) centre += vertices[v];
  centre /= static_cast<double>(facet.size());
  Eigen::Index axis = 0;
  n.cwiseAbs().minCoeff(&axis);
  const Eigen::Vector3d u = n.cross(Eigen::Vector3d::Unit(axis)).normalized();
  const Eigen::Vector3d w = n.cross(u);
  std::vector<std::pair<double, int>> by_angle;
  for (int v : facet) {
    const Eigen::Vector3d d = vertices[v] - centre;
    by_angle.emplace_back(std::atan2(d.dot(w), d.dot(u)), v);
  }
  std::sort(by_angle.begin(), by_angle.end());
  for (size_t i = 0; i < facet.size(); ++i) facet[i] = by_angle[i].second;
}

// The diagonal of the points' bounding box.
double extent_of(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d low = points.front(), high = points.front();
  for (const Eigen::Vector3d& p : points) low = low.cwiseMin(p), high = high.cwiseMax(p);
  return (high - low).norm();
}

} // namespace

Result<ConvexPolytope> ConvexHullBuilder::build(const std::vector<Eigen::Vector3d>& points,
                                                const std::vector<int>& ids) {
  ++calls_;
  if (points.size() < 4) return Status{StatusCode::degenerate_scene, "a 3D hull needs at least 4 points"};
  if (error_sink_ == nullptr) error_sink_ = std::fopen("/dev/null", "w");
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) centre += p;
  centre /= static_cast<double>(points.size());
  std::vector<coordT> coordinates;
  coordinates.reserve(points.size() * 3);
  for (const Eigen::Vector3d& p : points)
    for (int k = 0; k < 3; ++k) coordinates.push_back(p[k] - centre[k]);

  qhT qh_storage;
  qhT* qh = &qh_storage;
  qh_zero(qh, error_sink_);
  char flags[] = "qhull";
  const int exit_code =
      qh_new_qhull(qh, 3, static_cast<int>(points.size()), coordinates.data(), False, flags, nullptr, error_sink_);
  Result<ConvexPolytope> result = Status{StatusCode::degenerate_scene, "Qhull error " + std::to_string(exit_code)};
  if (exit_code == 0) {
    ConvexPolytope hull;
    std::vector<int> compact(points.size(), -1);
    vertexT* vertex;
    FORALLvertices {
      const int id = qh_pointid(qh, vertex->point);
      if (id >= 0 && id < static_cast<int>(points.size())) compact[id] = 0;
    }
    for (size_t i = 0; i < points.size(); ++i)
      if (compact[i] == 0) {
        compact[i] = static_cast<int>(hull.vertices.size());
        hull.vertices.push_back(points[i]);
        if (!ids.empty()) hull.vertex_ids.push_back(ids[i]);
      }
    facetT* facet;
    FORALLfacets {
      Plane plane;
      plane.normal = Eigen::Vector3d(facet->normal[0], facet->normal[1], facet->normal[2]);
      // Qhull's hyperplane is normal . (x - centre) + offset = 0.
      plane.offset = -facet->offset + plane.normal.dot(centre);
      std::vector<int> corners;
      vertexT** vertexp;
      FOREACHvertex_(facet->vertices) corners.push_back(compact[qh_pointid(qh, vertex->point)]);
      order_around(corners, hull.vertices, plane.normal);
      hull.facets.push_back(std::move(corners));
      hull.planes.push_back(plane);
    }
    if (thinnest_width(hull) <= kFlatHullRelativeWidth * extent_of(points))
      result = Status{StatusCode::degenerate_scene, "the points lie within rounding of a plane"};
    else
      result = std::move(hull);
  }
  qh_freeqhull(qh, !qh_ALL);
  int still_long = 0, total_long = 0;
  qh_memfreeshort(qh, &still_long, &total_long);
  return result;
}

} // namespace hullcover
