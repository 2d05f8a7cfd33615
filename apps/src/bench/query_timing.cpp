#include "query_timing.h"

#include <chrono>
#include <random>

namespace hullcover::app::bench {
namespace {

using Clock = std::chrono::steady_clock;

// A point drawn uniformly on a random face with an area, and its unit
// normal. Faces are drawn by area, so big floors get most poses.
struct FacePoint {
  Eigen::Vector3d point, normal;
};

class FaceSampler {
public:
  explicit FaceSampler(const Mesh& mesh) : mesh_(mesh) {
    std::vector<double> areas;
    for (int f = 0; f < static_cast<int>(mesh.triangles.size()); ++f) {
      const double a = triangle_area_vector(mesh, f).norm();
      if (a > 0.0) faces_.push_back(f), areas.push_back(a);
    }
    pick_ = std::discrete_distribution<size_t>(areas.begin(), areas.end());
  }
  bool empty() const { return faces_.empty(); }
  FacePoint draw(std::mt19937& rng) {
    const int f = faces_[pick_(rng)];
    std::uniform_real_distribution<double> u(0.0, 1.0);
    double a = u(rng), b = u(rng);
    if (a + b > 1.0) a = 1.0 - a, b = 1.0 - b;
    const Eigen::Vector3i& t = mesh_.triangles[f];
    const std::vector<Eigen::Vector3d>& x = mesh_.positions;
    return {x[t[0]] + a * (x[t[1]] - x[t[0]]) + b * (x[t[2]] - x[t[0]]), triangle_area_vector(mesh_, f).normalized()};
  }

private:
  const Mesh& mesh_;
  std::vector<int> faces_;
  std::discrete_distribution<size_t> pick_;
};

// Runs one kind of query on every pose, rounds alternating between the two
// worlds, and gives microseconds per query on each.
template <typename HullQuery, typename TriangleQuery>
Result<QueryTiming> time_side_by_side(int count, double min_seconds, HullQuery hull_query,
                                      TriangleQuery triangle_query) {
  QueryTiming timing;
  if (count == 0) return timing;
  double hull_seconds = 0.0, triangle_seconds = 0.0;
  long rounds = 0;
  while (rounds < 2 || hull_seconds < min_seconds || triangle_seconds < min_seconds) {
    Clock::time_point start = Clock::now();
    for (int i = 0; i < count; ++i)
      if (Status s = hull_query(i); !s.ok()) return s;
    hull_seconds += std::chrono::duration<double>(Clock::now() - start).count();
    start = Clock::now();
    for (int i = 0; i < count; ++i)
      if (Status s = triangle_query(i); !s.ok()) return s;
    triangle_seconds += std::chrono::duration<double>(Clock::now() - start).count();
    ++rounds;
  }
  const double queries = static_cast<double>(rounds) * count;
  timing.hull_us = 1e6 * hull_seconds / queries;
  timing.triangle_us = 1e6 * triangle_seconds / queries;
  return timing;
}

} // namespace

QueryPoses surface_poses(const Mesh& mesh, double radius, double half_height, int count, unsigned seed) {
  QueryPoses out;
  out.radius = radius;
  out.half_height = half_height;
  out.ray_length = 4.0 * radius;
  FaceSampler faces(mesh);
  if (faces.empty()) return out;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.5, 0.5), offset(-0.5, 1.5);
  for (int i = 0; i < count; ++i) {
    const FacePoint on = faces.draw(rng);
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = on.point + on.normal * (offset(rng) * radius);
    const Eigen::Vector4d q(u(rng), u(rng), u(rng), u(rng));
    pose.linear() = Eigen::Quaterniond(q.norm() > 0.0 ? q.normalized() : Eigen::Vector4d::UnitW()).toRotationMatrix();
    out.poses.push_back(pose);
    const Eigen::Vector3d towards = -on.normal + 0.3 * Eigen::Vector3d(u(rng), u(rng), u(rng));
    out.rays.push_back({pose.translation(), towards, out.ray_length});
  }
  return out;
}

Result<QueryTimings> time_queries(const bvh::HullWorld& hulls, const bvh::TriangleWorld& triangles,
                                  const QueryPoses& poses, double min_seconds) {
  const int n = static_cast<int>(poses.poses.size());
  const bvh::QueryShape capsule = bvh::QueryShape::capsule(poses.radius, poses.half_height);
  bvh::TouchResult touch;
  Result<QueryTiming> touches = time_side_by_side(
      n, min_seconds,
      [&](int i) {
    return hulls.touches({capsule, poses.poses[i]}, touch);
      },
      [&](int i) {
    return triangles.touches({capsule, poses.poses[i]}, touch);
  });
  if (!touches.ok()) return touches.status();
  bvh::ContactResult contact;
  Result<QueryTiming> contacts = time_side_by_side(
      n, min_seconds,
      [&](int i) {
    return hulls.contacts({capsule, poses.poses[i], 8}, contact);
      },
      [&](int i) {
    return triangles.contacts({capsule, poses.poses[i], 8}, contact);
  });
  if (!contacts.ok()) return contacts.status();
  bvh::RayResult hit;
  Result<QueryTiming> rays = time_side_by_side(
      n, min_seconds, [&](int i) { return hulls.ray_cast(poses.rays[i], hit); },
      [&](int i) { return triangles.ray_cast(poses.rays[i], hit); });
  if (!rays.ok()) return rays.status();
  return QueryTimings{touches.value(), contacts.value(), rays.value()};
}

} // namespace hullcover::app::bench
