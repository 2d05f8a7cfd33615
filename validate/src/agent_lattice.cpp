#include "agent_lattice.h"

#include "hullcover/geometry/convex_polytope.h"
#include "hullcover/geometry/parallel_for.h"
#include "hullcover/geometry/triangle_distance.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hullcover::validate::detail {
namespace {

std::vector<Aabb> triangle_boxes(const Mesh& mesh, const std::vector<int>& faces) {
  std::vector<Aabb> boxes;
  for (int f : faces) {
    Aabb box;
    for (int k = 0; k < 3; ++k) box.extend(mesh.positions[mesh.triangles[f][k]]);
    boxes.push_back(box);
  }
  return boxes;
}

std::vector<int> all_faces(const Mesh& mesh) {
  std::vector<int> faces(mesh.triangles.size());
  for (size_t f = 0; f < faces.size(); ++f) faces[f] = static_cast<int>(f);
  return faces;
}

Eigen::Vector3d up_of(const AuditAgent& agent) {
  Eigen::Vector3d up = Eigen::Vector3d::Zero();
  up[agent.up_axis] = agent.up_sign;
  return up;
}

// The part of triangle `f` whose height, as up measures it, lies in
// [low, high]: where a walker standing at height `high` may rest.
std::vector<Eigen::Vector3d> face_in_slab(const Mesh& mesh, const AuditAgent& agent, int f, double low, double high) {
  std::vector<Eigen::Vector3d> polygon;
  for (int k = 0; k < 3; ++k) polygon.push_back(mesh.positions[mesh.triangles[f][k]]);
  const Eigen::Vector3d up = up_of(agent);
  polygon = clip_polygon(polygon, Plane{up, high}, 0.0);
  return clip_polygon(polygon, Plane{-up, -low}, 0.0);
}

// The 2D distance, across up, from p to convex `polygon` (face_in_slab);
// infinity when it is empty.
double across_distance(const AuditAgent& agent, const std::vector<Eigen::Vector3d>& polygon, const Eigen::Vector3d& p) {
  if (polygon.empty()) return std::numeric_limits<double>::infinity();
  const Eigen::Vector3d up = up_of(agent);
  // Flattened along up: the nearest point of a convex polygon.
  const auto flat = [&](Eigen::Vector3d q) {
    q[agent.up_axis] = 0.0;
    return q;
  };
  const Eigen::Vector3d target = flat(p);
  const size_t n = polygon.size();
  bool left = true, right = true;
  for (size_t i = 0; i < n; ++i) {
    const double side = (flat(polygon[(i + 1) % n]) - flat(polygon[i])).cross(target - flat(polygon[i])).dot(up);
    left &= side >= 0.0;
    right &= side <= 0.0;
  }
  if (left || right) return 0.0;
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < n; ++i)
    best = std::min(best,
                    (closest_point_on_segment(target, flat(polygon[i]), flat(polygon[(i + 1) % n])) - target).norm());
  return best;
}

// The lowest height, as up measures it, of the part of `polygon` (a face
// in its slab, face_in_slab) that lies within r across up of p: the lowest
// point a walker at p may rest on. Infinity when there is none.
// Height is linear across the face, so its least value on that convex part
// is at a corner of the polygon inside the circle, where a side of it
// crosses the circle, or at the circle's point straight downhill of p.
double lowest_rest_near(const AuditAgent& agent, const std::vector<Eigen::Vector3d>& polygon,
                        const Eigen::Vector3d& p) {
  const Eigen::Vector3d up = up_of(agent);
  const double infinity = std::numeric_limits<double>::infinity();
  if (polygon.size() < 3) return infinity;
  const auto across = [&](const Eigen::Vector3d& q) { return Eigen::Vector3d(q - up.dot(q) * up); };
  const double r = agent.radius, r2 = r * r;
  const Eigen::Vector3d centre = across(p);
  double lowest = infinity;
  const size_t n = polygon.size();
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& a = polygon[i];
    const Eigen::Vector3d& b = polygon[(i + 1) % n];
    if ((across(a) - centre).squaredNorm() <= r2) lowest = std::min(lowest, agent.height_of(a));
    // Where side a-b crosses the circle: |across(a) + t d - centre| = r.
    const Eigen::Vector3d d = across(b) - across(a), e = across(a) - centre;
    const double qa = d.squaredNorm(), qb = 2.0 * d.dot(e), qc = e.squaredNorm() - r2;
    const double disc = qb * qb - 4.0 * qa * qc;
    if (!(qa > 0.0) || disc < 0.0) continue;
    for (double sign : {-1.0, 1.0}) {
      const double t = (-qb + sign * std::sqrt(disc)) / (2.0 * qa);
      if (t >= 0.0 && t <= 1.0) lowest = std::min(lowest, agent.height_of(a + t * (b - a)));
    }
  }
  // Straight downhill of p on the circle, when the polygon holds it: the
  // face's plane falls fastest along its normal's part across up. A level
  // face falls nowhere: its point under p, when the polygon holds it.
  const Eigen::Vector3d normal = (polygon[1] - polygon[0]).cross(polygon[2] - polygon[0]);
  Eigen::Vector3d downhill = across(normal);
  if (std::abs(normal.dot(up)) > 0.0) {
    const double fall = downhill.norm();
    downhill =
        fall > 0.0 ? Eigen::Vector3d((normal.dot(up) > 0.0 ? 1.0 : -1.0) * downhill / fall) : Eigen::Vector3d::Zero();
    const Eigen::Vector3d foot = centre + r * downhill;
    // The face's point over `foot`, and whether it lies in the polygon.
    const double t = normal.dot(polygon[0] - foot) / normal.dot(up);
    const Eigen::Vector3d q = foot + t * up;
    bool left = true, right = true;
    for (size_t i = 0; i < n; ++i) {
      const double side = (polygon[(i + 1) % n] - polygon[i]).cross(q - polygon[i]).dot(normal);
      left &= side >= 0.0;
      right &= side <= 0.0;
    }
    if (left || right) lowest = std::min(lowest, agent.height_of(q));
  }
  return lowest;
}

} // namespace

TriangleDistances::TriangleDistances(const Mesh& m) : mesh(m), tree(triangle_boxes(m, all_faces(m))) {}

double TriangleDistances::clearance(const Eigen::Vector3d& p, double limit) const {
  return std::sqrt(tree.nearest_to_point(p, limit, [&](int f) {
    const Eigen::Vector3i& t = mesh.triangles[f];
    return (closest_point_on_triangle(p, mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]) - p)
        .squaredNorm();
  }));
}

bool audit_walkable(const Mesh& mesh, const AuditAgent& agent, int f) {
  const Eigen::Vector3i& t = mesh.triangles[f];
  const Eigen::Vector3d n =
      (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]);
  return n.norm() > 0.0 && agent.up_sign * n[agent.up_axis] / n.norm() >= agent.min_up_cosine;
}

bool AgentLattice::reachable_near(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d at = (p - origin) / spacing;
  for (int corner = 0; corner < 8; ++corner) {
    Eigen::Vector3i c;
    for (int a = 0; a < 3; ++a) c[a] = static_cast<int>(std::floor(at[a])) + ((corner >> a) & 1);
    if ((c.array() < 0).any() || (c.array() >= dims.array()).any()) continue;
    if (reachable(index(c.x(), c.y(), c.z()))) return true;
  }
  return false;
}

bool AgentLattice::reachable_nearest(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d at = ((p - origin) / spacing).array().round();
  if ((at.array() < 0.0).any() || (at.array() >= dims.cast<double>().array()).any()) return false;
  return reachable(index(static_cast<int>(at.x()), static_cast<int>(at.y()), static_cast<int>(at.z())));
}

AgentLattice reach_lattice(const TriangleDistances& distances, const AuditAgent& agent, const Aabb& box, double spacing,
                           const std::vector<Eigen::Vector3d>& seeds, int threads) {
  const Mesh& mesh = distances.mesh;
  AgentLattice lattice;
  lattice.origin = box.min;
  lattice.spacing = spacing;
  lattice.dims = (((box.max - box.min) / spacing).array().floor() + 1.0).cast<int>();
  const long long count = lattice.size();
  lattice.flags.assign(count, 0);
  std::vector<std::uint8_t>& flags = lattice.flags;
  constexpr std::uint8_t kPassable = 4; // an agent's centre may be here
  constexpr std::uint8_t kStanding = 8; // ... standing on a walkable face
  // The lattice samples the definition: a point passes when it is clear
  // itself, so every centre the flood reaches is one (two neighbours both
  // clear, less than 2 r apart, have no surface between them). Narrow
  // passages between samples may be missed: the audit's reach is at most
  // the definition's, and a violation it reports is a real pose.
  std::vector<int> walkable;
  for (int f = 0; f < static_cast<int>(mesh.triangles.size()); ++f)
    if (audit_walkable(mesh, agent, f)) walkable.push_back(f);
  const AabbTree walkable_tree(triangle_boxes(mesh, walkable));
  const double rise = agent.rise();
  parallel_for(lattice.dims.z(), threads, [&](int k) {
    for (int j = 0; j < lattice.dims.y(); ++j)
      for (int i = 0; i < lattice.dims.x(); ++i) {
        const long long at = lattice.index(i, j, k);
        const double d = distances.clearance(lattice.point(i, j, k), agent.radius);
        if (d >= agent.radius) flags[at] |= AgentLattice::kClearPoint;
        if (d >= agent.radius) flags[at] |= kPassable;
      }
  });
  // Standing, column by column (each column's points read and written by
  // one job): a walkable point within r across of it, at most `rise`
  // below it, and headroom: the capsule's axis (H - 2r long) holds at
  // least that length over a spacing of clear points in its column,
  // above the lowest such walkable point and below its face's highest
  // point plus `rise`.
  const int axis = agent.up_axis, a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
  const int fewest = static_cast<int>(std::floor((agent.height - 2.0 * agent.radius) / spacing));
  if (agent.walking)
    parallel_for(lattice.dims[a1], threads, [&](int u) {
      std::vector<int> found;
      Eigen::Vector3i c;
      c[a1] = u;
      const auto at = [&](int w) {
        c[axis] = w;
        return lattice.index(c.x(), c.y(), c.z());
      };
      for (int v = 0; v < lattice.dims[a2]; ++v) {
        c[a2] = v;
        for (int w = 0; w < lattice.dims[axis]; ++w) {
          if (!(flags[at(w)] & kPassable)) continue;
          const Eigen::Vector3d p = lattice.point(c.x(), c.y(), c.z());
          const double height = agent.height_of(p);
          Aabb query;
          query.extend(p);
          query = grown(query, agent.radius);
          if (agent.up_sign > 0)
            query.min[axis] -= rise;
          else
            query.max[axis] += rise;
          found.clear();
          walkable_tree.overlapping(query, found);
          for (int f : found) {
            // Heights as up measures them (the slab is clipped along up).
            const std::vector<Eigen::Vector3d> rest = face_in_slab(mesh, agent, walkable[f], height - rise, height);
            if (across_distance(agent, rest, p) > agent.radius) continue;
            // The axis stands on the face: above the lowest point of it a
            // walker at p rests on, below its highest plus `rise`.
            const double floor_low = lowest_rest_near(agent, rest, p);
            double floor_high = -std::numeric_limits<double>::infinity();
            for (int k = 0; k < 3; ++k)
              floor_high = std::max(floor_high, agent.height_of(mesh.positions[mesh.triangles[walkable[f]][k]]));
            // The run of passable points through this one, within the face's range.
            const auto in_range = [&](int x) {
              const double h = height + (x - w) * agent.up_sign * spacing;
              return (flags[at(x)] & kPassable) && h >= floor_low && h <= floor_high + rise;
            };
            int run = 1;
            for (int x = w + 1; x < lattice.dims[axis] && in_range(x); ++x) ++run;
            for (int x = w - 1; x >= 0 && in_range(x); --x) ++run;
            c[axis] = w;
            if (run >= fewest) {
              flags[at(w)] |= kStanding;
              break;
            }
          }
          c[axis] = w;
        }
      }
    });
  // Walking: standing points, and the passable points below one in its
  // column (an agent stepping off a ledge falls straight down).
  if (agent.walking) {
    const int down = agent.up_sign > 0 ? -1 : 1;
    for (int u = 0; u < lattice.dims[a1]; ++u)
      for (int v = 0; v < lattice.dims[a2]; ++v) {
        bool falling = false;
        for (int w = down < 0 ? lattice.dims[axis] - 1 : 0; w >= 0 && w < lattice.dims[axis]; w += down) {
          Eigen::Vector3i c;
          c[axis] = w;
          c[a1] = u;
          c[a2] = v;
          const long long at = lattice.index(c.x(), c.y(), c.z());
          if (!(flags[at] & kPassable))
            falling = false;
          else if (flags[at] & kStanding)
            falling = true;
          else if (!falling)
            flags[at] &= ~kPassable;
        }
      }
  }
  // Flood from the lattice points around each seed.
  std::vector<std::uint32_t> stack;
  for (const Eigen::Vector3d& seed : seeds) {
    const Eigen::Vector3d at = (seed - lattice.origin) / spacing;
    for (int corner = 0; corner < 8; ++corner) {
      Eigen::Vector3i c;
      for (int a = 0; a < 3; ++a) c[a] = static_cast<int>(std::floor(at[a])) + ((corner >> a) & 1);
      if ((c.array() < 0).any() || (c.array() >= lattice.dims.array()).any()) continue;
      const long long i = lattice.index(c.x(), c.y(), c.z());
      if ((flags[i] & kPassable) && !lattice.reachable(i)) {
        flags[i] |= AgentLattice::kReachablePoint;
        stack.push_back(static_cast<std::uint32_t>(i));
      }
    }
  }
  // Walking moves between standing points freely, off a ledge sideways or
  // down into a falling point, and from a falling point straight down only.
  const long long step[3] = {1, lattice.dims.x(), static_cast<long long>(lattice.dims.x()) * lattice.dims.y()};
  const int down = agent.up_sign > 0 ? -1 : 1;
  while (!stack.empty()) {
    const long long c = stack.back();
    stack.pop_back();
    const bool free_moving = !agent.walking || (flags[c] & kStanding);
    const long long at[3] = {c % lattice.dims.x(), (c / step[1]) % lattice.dims.y(), c / step[2]};
    for (int a = 0; a < 3; ++a)
      for (int s = -1; s <= 1; s += 2) {
        const bool downward = a == agent.up_axis && s == down;
        const bool upward = a == agent.up_axis && s != down;
        if (!free_moving && !downward) continue;
        if (at[a] + s < 0 || at[a] + s >= lattice.dims[a]) continue;
        const long long next = c + s * step[a];
        if (!(flags[next] & kPassable) || lattice.reachable(next)) continue;
        if (agent.walking && upward && !(flags[next] & kStanding)) continue;
        flags[next] |= AgentLattice::kReachablePoint;
        stack.push_back(static_cast<std::uint32_t>(next));
      }
  }
  return lattice;
}

} // namespace hullcover::validate::detail
