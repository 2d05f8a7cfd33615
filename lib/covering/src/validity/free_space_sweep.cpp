#include "validity/free_space_sweep.h"

#include "hullcover/geometry/aabb.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace hullcover {
namespace {

Plane plane_through(const Eigen::Vector3d& normal, const Eigen::Vector3d& point) { return {normal, normal.dot(point)}; }

} // namespace

FreeSpaceSweep front_space_sweep(const std::vector<Eigen::Vector3d>& corners, const Eigen::Vector3d& normal,
                                 double reach, double tol) {
  FreeSpaceSweep sweep;
  front_space_sweep(corners, normal, reach, tol, sweep);
  return sweep;
}

void front_space_sweep(const std::vector<Eigen::Vector3d>& corners, const Eigen::Vector3d& normal, double reach,
                       double tol, FreeSpaceSweep& sweep) {
  sweep.planes.clear();
  sweep.insets.clear();
  sweep.corners.clear();
  sweep.direction = normal;
  // The probe's rays start a stand-off from the face and run the reach
  // from there.
  reach += kRayStandOffInTolerances * tol;
  sweep.reach = reach;
  const Eigen::Vector3d centre = (corners[0] + corners[1] + corners[2]) / 3.0;
  // Built for every sweep a hull check meets: sized once.
  sweep.planes.reserve(5);
  sweep.insets.reserve(5);
  sweep.corners.reserve(6);
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d& a = corners[k];
    const Eigen::Vector3d& b = corners[(k + 1) % 3];
    Eigen::Vector3d out = (b - a).cross(normal).normalized();
    if (out.dot(centre - a) > 0.0) out = -out;
    sweep.planes.push_back(plane_through(out, a));
    sweep.insets.push_back(0.0);
  }
  sweep.start = plane_through(-normal, corners[0]);
  sweep.planes.push_back(sweep.start);
  sweep.insets.push_back(-tol);
  sweep.planes.push_back(plane_through(normal, corners[0] + reach * normal));
  sweep.insets.push_back(0.0);
  sweep.base.assign(corners.begin(), corners.end());
  for (const Eigen::Vector3d& c : corners) {
    sweep.corners.push_back(c);
    sweep.corners.push_back(c + reach * normal);
  }
}

void opening_sweep(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& inner,
                   const Eigen::Vector3d& face_normal, double reach, double tol, FreeSpaceSweep& sweep) {
  const Eigen::Vector3d along = (p1 - p0).normalized();
  Eigen::Vector3d out = along.cross(face_normal).normalized();
  if (out.dot(inner - p0) > 0.0) out = -out;
  sweep.direction = out;
  reach += kRayStandOffInTolerances * tol;
  sweep.reach = reach;
  sweep.start = plane_through(-out, p0);
  // A strip in the face's plane, kept within tol of it either side, from
  // the start to the reach.
  sweep.planes = {plane_through(face_normal, p0),
                  plane_through(-face_normal, p0),
                  plane_through(along, p1),
                  plane_through(-along, p0),
                  sweep.start,
                  plane_through(out, p0 + reach * out)};
  sweep.insets = {-tol, -tol, 0.0, 0.0, -tol, 0.0};
  sweep.base = {p0, p1};
  sweep.corners = {p0, p1, p1 + reach * out, p0 + reach * out};
}

FreeSpaceSweep opening_sweep(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& inner,
                             const Eigen::Vector3d& face_normal, double reach, double tol) {
  FreeSpaceSweep sweep;
  opening_sweep(p0, p1, inner, face_normal, reach, tol, sweep);
  return sweep;
}

void opening_fan(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& inner,
                 const Eigen::Vector3d& face_normal, int fan, double reach, double tol, FreeSpaceSweep& sweep) {
  if (fan == 0) return opening_sweep(p0, p1, inner, face_normal, reach, tol, sweep);
  // Turning the plane about the edge turns its normal with it: a fan
  // tilted by s toward the front runs along c out + s n, in the plane whose
  // normal is c n - s out.
  Eigen::Vector3d out = (p1 - p0).cross(face_normal).normalized();
  if (out.dot(inner - p0) > 0.0) out = -out;
  const double s = fan == 1 ? kOpeningTiltSine : -kOpeningTiltSine;
  const double c = std::sqrt(1.0 - s * s);
  opening_sweep(p0, p1, inner, c * face_normal - s * out, reach, tol, sweep);
}

FreeSpaceSweep opening_fan(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& inner,
                           const Eigen::Vector3d& face_normal, int fan, double reach, double tol) {
  FreeSpaceSweep sweep;
  opening_fan(p0, p1, inner, face_normal, fan, reach, tol, sweep);
  return sweep;
}

} // namespace hullcover
