#include "agent_lattice.h"
#include "walker_rest.h"

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

} // namespace

TriangleDistances::TriangleDistances(const Mesh& m) : mesh(m), tree(triangle_boxes(m, all_faces(m))) {}

double TriangleDistances::nearest(const Eigen::Vector3d& p, double limit, Eigen::Vector3d& foot) const {
  double best = limit * limit;
  return std::sqrt(tree.nearest_to_point(p, limit, [&](int f) {
    const Eigen::Vector3i& t = mesh.triangles[f];
    const Eigen::Vector3d on =
        closest_point_on_triangle(p, mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
    const double d2 = (on - p).squaredNorm();
    if (d2 < best) {
      best = d2;
      foot = on;
    }
    return d2;
  }));
}

double TriangleDistances::clearance(const Eigen::Vector3d& p, double limit) const {
  Eigen::Vector3d foot;
  return nearest(p, limit, foot);
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
    if (reachable(c.x(), c.y(), c.z())) return true;
  }
  return false;
}

bool AgentLattice::holds(const Eigen::Vector3d& at) const {
  // Written so that a NaN coordinate lies off the lattice.
  return (at.array() >= 0.0).all() && (at.array() < dims.cast<double>().array()).all();
}

bool AgentLattice::nearest_reachable(const Eigen::Vector3d& p, Eigen::Vector3d& nearest) const {
  const Eigen::Vector3d at = ((p - origin) / spacing).array().round();
  if (!holds(at)) return false;
  const Eigen::Vector3i g = at.cast<int>();
  nearest = point(g.x(), g.y(), g.z());
  return reachable(g.x(), g.y(), g.z());
}

bool AgentLattice::reachable_for_walker(const Eigen::Vector3d& p, int up_axis, double up_sign) const {
  Eigen::Vector3d nearest;
  if (nearest_reachable(p, nearest)) return true;
  const Eigen::Vector3d at = (p - origin) / spacing;
  const auto reachable_at = [&](const Eigen::Vector3d& c) {
    return holds(c) && reachable(static_cast<int>(c.x()), static_cast<int>(c.y()), static_cast<int>(c.z()));
  };
  const int across_a = (up_axis + 1) % 3, across_b = (up_axis + 2) % 3;
  Eigen::Vector3d above;
  above[up_axis] = up_sign > 0 ? std::ceil(at[up_axis]) : std::floor(at[up_axis]);
  for (int corner = 0; corner < 4; ++corner) {
    above[across_a] = std::floor(at[across_a]) + (corner & 1);
    above[across_b] = std::floor(at[across_b]) + ((corner >> 1) & 1);
    if (reachable_at(above)) return true;
  }
  return false;
}

namespace {

constexpr std::uint8_t kPassable = 4; // an agent's centre may be here (clear)
constexpr std::uint8_t kStanding = 8; // ... standing on a walkable face
constexpr std::uint8_t kFalling = 16; // ... falling straight down from a standing point

// Judges the points of block `b` by their clearance: the whole block at
// once when the clearance at its middle, less or plus the distance to its
// farthest point, clears r or stays below it by tol, else point by point.
void examine_block(const TriangleDistances& distances, const AuditAgent& agent, double tol, AgentLattice& lattice,
                   long long b) {
  BlockBytes& flags = lattice.flags;
  const Eigen::Vector3i lo = flags.block_at(b) * BlockBytes::kSide;
  const Eigen::Vector3i hi = (lo.array() + BlockBytes::kSide).min(lattice.dims.array()) - 1;
  const Eigen::Vector3d middle = 0.5 * (lattice.point(lo.x(), lo.y(), lo.z()) + lattice.point(hi.x(), hi.y(), hi.z()));
  const double spread = 0.5 * (hi - lo).cast<double>().norm() * lattice.spacing;
  const double r = agent.radius;
  const double d = distances.clearance(middle, r + spread + 2.0 * tol);
  if (d - spread >= r + tol) {
    flags.set_uniform(b, AgentLattice::kClearPoint | kPassable);
    return;
  }
  if (d + spread < r - tol) {
    flags.set_uniform(b, 0);
    return;
  }
  std::uint8_t* held = flags.hold(b, 0);
  for (int k = lo.z(); k <= hi.z(); ++k)
    for (int j = lo.y(); j <= hi.y(); ++j)
      for (int i = lo.x(); i <= hi.x(); ++i)
        if (distances.clearance(lattice.point(i, j, k), r) >= r)
          held[BlockBytes::in_block(i, j, k)] = AgentLattice::kClearPoint | kPassable;
}

// A walker's centre may be at a point when it is standing, or falling from
// a standing point straight down.
bool walker_may_be(std::uint8_t m) { return (m & kPassable) && (m & (kStanding | kFalling)); }

} // namespace

Result<AgentLattice> reach_lattice(const TriangleDistances& distances, const AuditAgent& agent, const Aabb& box,
                                   double spacing, const std::vector<Eigen::Vector3d>& seeds, double tol,
                                   long long most_held, int threads) {
  const Mesh& mesh = distances.mesh;
  AgentLattice lattice;
  lattice.origin = box.min;
  lattice.spacing = spacing;
  lattice.dims = (((box.max - box.min) / spacing).array().floor() + 1.0).cast<int>();
  lattice.flags = BlockBytes(lattice.dims);
  BlockBytes& flags = lattice.flags;
  const auto too_many = [&] {
    return Status{StatusCode::limit_exceeded, "the movement audit's lattice needs more than " +
                                                  std::to_string(most_held) +
                                                  " points held one by one (those near the scene's surfaces): a wider "
                                                  "--lattice-spacing, or a part of the scene"};
  };
  // The lattice samples the definition: a point passes when it is clear
  // itself, so every centre the flood reaches is one (two neighbours both
  // clear, less than 2 r apart, have no surface between them). Narrow
  // passages between samples may be missed: the lattice's reach is at most
  // the definition's, and a centre sinking that it reports is a real pose.
  // (A walker's touching pose is judged a spacing wider:
  // AgentLattice::reachable_for_walker.)
  std::vector<int> walkable;
  for (int f = 0; f < static_cast<int>(mesh.triangles.size()); ++f)
    if (audit_walkable(mesh, agent, f)) walkable.push_back(f);
  const AabbTree walkable_tree(triangle_boxes(mesh, walkable));
  const double rise = agent.rise();
  const int axis = agent.up_axis, a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;

  // The blocks to examine: all (flying), or those a walker may stand in:
  // a point standing on a face lies within r of its box, and at most
  // `rise` above it (the rest are examined when a fall enters them).
  std::vector<std::uint8_t> wanted; // walking: a byte a block; flying: empty, every block
  if (agent.walking) {
    wanted.assign(static_cast<size_t>(flags.block_count()), 0);
    for (int f : walkable) {
      Aabb near;
      for (int k = 0; k < 3; ++k) near.extend(mesh.positions[mesh.triangles[f][k]]);
      near = grown(near, agent.radius);
      if (agent.up_sign > 0)
        near.max[axis] += rise;
      else
        near.min[axis] -= rise;
      Eigen::Vector3i lo, hi;
      for (int a = 0; a < 3; ++a) {
        lo[a] =
            static_cast<int>(std::clamp(std::floor((near.min[a] - box.min[a]) / spacing), 0.0, lattice.dims[a] - 1.0));
        hi[a] =
            static_cast<int>(std::clamp(std::ceil((near.max[a] - box.min[a]) / spacing), 0.0, lattice.dims[a] - 1.0));
      }
      const Eigen::Vector3i blo = BlockBytes::block_of(lo), bhi = BlockBytes::block_of(hi);
      for (int k = blo.z(); k <= bhi.z(); ++k)
        for (int j = blo.y(); j <= bhi.y(); ++j)
          for (int i = blo.x(); i <= bhi.x(); ++i) wanted[flags.block_index({i, j, k})] = 1;
    }
  }
  parallel_for(static_cast<int>(flags.block_count()), threads, [&](int b) {
    if ((wanted.empty() || wanted[b]) && flags.cells_held() <= most_held)
      examine_block(distances, agent, tol, lattice, b);
  });
  if (flags.cells_held() > most_held) return too_many();

  // Standing (walking), column by column (each column's points read and
  // written by one job; every block that may hold a standing point is held
  // first, so no job holds one): a walkable point within r across of it, at
  // most `rise` below it, and headroom: the capsule's axis (H - 2r long)
  // holds at least that length over a spacing of clear points in its
  // column, above the lowest such walkable point and below its face's
  // highest point plus `rise`.
  const int fewest = static_cast<int>(std::floor((agent.height - 2.0 * agent.radius) / spacing));
  if (agent.walking) {
    for (long long b = 0; b < flags.block_count(); ++b) {
      if (!flags.uniform(b) || !flags.uniform_byte(b)) continue;
      if (flags.cells_held() > most_held) return too_many();
      flags.hold(b, flags.uniform_byte(b));
    }
    const Eigen::Vector3i& blocks = flags.block_dims();
    parallel_for(blocks[a1] * blocks[a2], threads, [&](int column) {
      const int bu = column / blocks[a2], bv = column % blocks[a2];
      std::vector<int> found;
      Eigen::Vector3i c;
      const auto at = [&](int w) -> std::uint8_t& {
        c[axis] = w;
        return flags.at(c.x(), c.y(), c.z());
      };
      const auto passable = [&](int w) {
        c[axis] = w;
        return (flags.get(c.x(), c.y(), c.z()) & kPassable) != 0;
      };
      const int u_end = std::min(lattice.dims[a1], (bu + 1) * BlockBytes::kSide);
      const int v_end = std::min(lattice.dims[a2], (bv + 1) * BlockBytes::kSide);
      for (int u = bu * BlockBytes::kSide; u < u_end; ++u)
        for (int v = bv * BlockBytes::kSide; v < v_end; ++v) {
          c[a1] = u;
          c[a2] = v;
          for (int w = 0; w < lattice.dims[axis]; ++w) {
            if (!passable(w)) continue;
            c[axis] = w;
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
                return passable(x) && h >= floor_low && h <= floor_high + rise;
              };
              int run = 1;
              for (int x = w + 1; x < lattice.dims[axis] && in_range(x); ++x) ++run;
              for (int x = w - 1; x >= 0 && in_range(x); --x) ++run;
              if (run >= fewest) {
                at(w) |= kStanding;
                break;
              }
            }
            c[axis] = w;
          }
        }
    });
  }
  // Walking: the passable points below a standing one in its column fall
  // (an agent stepping off a ledge falls straight down). Only columns of
  // held blocks hold standing points; a block a fall enters is examined
  // then.
  if (agent.walking) {
    const int down = agent.up_sign > 0 ? -1 : 1;
    const Eigen::Vector3i& blocks = flags.block_dims();
    Eigen::Vector3i block;
    for (int bu = 0; bu < blocks[a1]; ++bu)
      for (int bv = 0; bv < blocks[a2]; ++bv) {
        block[a1] = bu;
        block[a2] = bv;
        bool any_held = false;
        for (int bw = 0; bw < blocks[axis] && !any_held; ++bw) {
          block[axis] = bw;
          any_held = flags.held(flags.block_index(block)) != nullptr;
        }
        if (!any_held) continue;
        const int u_end = std::min(lattice.dims[a1], (bu + 1) * BlockBytes::kSide);
        const int v_end = std::min(lattice.dims[a2], (bv + 1) * BlockBytes::kSide);
        for (int u = bu * BlockBytes::kSide; u < u_end; ++u)
          for (int v = bv * BlockBytes::kSide; v < v_end; ++v) {
            bool falling = false;
            Eigen::Vector3i c;
            c[a1] = u;
            c[a2] = v;
            for (int w = down < 0 ? lattice.dims[axis] - 1 : 0; w >= 0 && w < lattice.dims[axis]; w += down) {
              c[axis] = w;
              const long long b = flags.block_index(BlockBytes::block_of(c));
              if (!falling && !flags.held(b)) continue;
              if (!flags.classified(b)) {
                examine_block(distances, agent, tol, lattice, b);
                if (flags.cells_held() > most_held) return too_many();
              }
              const std::uint8_t m = flags.get(c.x(), c.y(), c.z());
              if (!(m & kPassable))
                falling = false;
              else if (m & kStanding)
                falling = true;
              else if (falling) {
                if (flags.cells_held() > most_held) return too_many();
                flags.at(c.x(), c.y(), c.z()) |= kFalling;
              }
            }
          }
      }
  }
  // Flood from the lattice points around each seed.
  std::vector<CellKey> starts;
  for (const Eigen::Vector3d& seed : seeds) {
    const Eigen::Vector3d at = (seed - lattice.origin) / spacing;
    for (int corner = 0; corner < 8; ++corner) {
      Eigen::Vector3i c;
      for (int a = 0; a < 3; ++a) c[a] = static_cast<int>(std::floor(at[a])) + ((corner >> a) & 1);
      if ((c.array() < 0).any() || (c.array() >= lattice.dims.array()).any()) continue;
      starts.push_back(cell_key(c.x(), c.y(), c.z()));
    }
  }
  if (!agent.walking) {
    flood_through(flags, starts, {}, kPassable, AgentLattice::kReachablePoint);
    return lattice;
  }
  // Walking moves between standing points freely, off a ledge sideways or
  // down into a falling point, and from a falling point straight down only.
  // Every point a walker may be at is in a held block.
  std::vector<CellKey> stack;
  for (CellKey key : starts) {
    const Eigen::Vector3i c = cell_of(key);
    const std::uint8_t m = flags.get(c.x(), c.y(), c.z());
    if (!walker_may_be(m) || (m & AgentLattice::kReachablePoint)) continue;
    flags.at(c.x(), c.y(), c.z()) |= AgentLattice::kReachablePoint;
    stack.push_back(key);
  }
  const int down = agent.up_sign > 0 ? -1 : 1;
  while (!stack.empty()) {
    const Eigen::Vector3i c = cell_of(stack.back());
    stack.pop_back();
    const bool free_moving = (flags.get(c.x(), c.y(), c.z()) & kStanding) != 0;
    for (int a = 0; a < 3; ++a)
      for (int s = -1; s <= 1; s += 2) {
        const bool downward = a == agent.up_axis && s == down;
        const bool upward = a == agent.up_axis && s != down;
        if (!free_moving && !downward) continue;
        Eigen::Vector3i n = c;
        n[a] += s;
        if (n[a] < 0 || n[a] >= lattice.dims[a]) continue;
        const std::uint8_t m = flags.get(n.x(), n.y(), n.z());
        if (!walker_may_be(m) || (m & AgentLattice::kReachablePoint)) continue;
        if (upward && !(m & kStanding)) continue;
        flags.at(n.x(), n.y(), n.z()) |= AgentLattice::kReachablePoint;
        stack.push_back(cell_key(n.x(), n.y(), n.z()));
      }
  }
  return lattice;
}

} // namespace hullcover::validate::detail
