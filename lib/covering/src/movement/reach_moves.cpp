#include "movement/reach_moves.h"

#include "hullcover/geometry/convex_polytope.h"

#include <algorithm>
#include <cmath>

namespace hullcover::detail {

Aabb standing_box(const Mesh& mesh, const AgentShape& agent, int face) {
  Aabb box;
  for (int k = 0; k < 3; ++k) box.extend(mesh.positions[mesh.triangles[face][k]]);
  for (int a = 0; a < 3; ++a)
    if (a != agent.up_axis) {
      box.min[a] -= agent.radius;
      box.max[a] += agent.radius;
    }
  const double rise = agent.climb + agent.height - agent.radius;
  if (agent.up_sign > 0)
    box.max[agent.up_axis] += rise;
  else
    box.min[agent.up_axis] -= rise;
  return box;
}

// Cell range [lo, hi] (inclusive) of the cells meeting `box`, clamped to the grid.
void cell_range(const ReachGrid& grid, const Aabb& box, Eigen::Vector3i& lo, Eigen::Vector3i& hi) {
  // Clamped as doubles first: a box far beyond the grid (a huge height)
  // must not overflow the casts.
  const auto index_of = [&](double x, int a) {
    return static_cast<int>(std::clamp(std::floor((x - grid.origin[a]) / grid.cell), -1.0, double(grid.dims[a])));
  };
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::max(0, index_of(box.min[a], a));
    hi[a] = std::min(grid.dims[a] - 1, index_of(box.max[a], a));
  }
}

// Marks kStanding in the clear cells where an agent standing on walkable
// face `face` may have a point of its axis: within r across of a point w of
// the face and above it (a standing agent rests on w), up to the face's
// highest point plus climb + H - r, in a run of clear cells within that
// range long enough for the axis (H - 2r long, it crosses at least that
// length over a cell side of cells, each holding one of its clear points,
// all in one column): no upright capsule stands where its head would be in
// a ceiling. Cells under the face's lowest point within r across of their
// column are left out: an agent under a surface does not stand on it (and
// walkers would otherwise walk the envelopes under sloping ground).
bool mark_standing(const ReachGrid& grid, const Mesh& mesh, const AgentShape& agent, int face, long long most_held,
                   ReachMarks& marks) {
  const Aabb box = standing_box(mesh, agent, face);
  std::vector<Eigen::Vector3d> triangle;
  for (int k = 0; k < 3; ++k) triangle.push_back(mesh.positions[mesh.triangles[face][k]]);
  Eigen::Vector3i lo, hi;
  cell_range(grid, box, lo, hi);
  const int axis = agent.up_axis;
  const int fewest = static_cast<int>(
      std::min(std::floor((agent.height - 2.0 * agent.radius) / grid.cell), double(grid.dims[agent.up_axis] + 1)));
  Eigen::Vector3i c;
  const auto cell = [&](int w) {
    c[axis] = w;
    return c;
  };
  const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
  std::vector<Eigen::Vector3d> part, clipped;
  for (int u = lo[a1]; u <= hi[a1]; ++u)
    for (int v = lo[a2]; v <= hi[a2]; ++v) {
      c[a1] = u;
      c[a2] = v;
      // The part of the face within r across of the column (its square
      // grown by r: a superset of the disc), and its lowest coordinate
      // along up: a plane's extremes over a polygon lie at its corners.
      part = triangle;
      for (const auto& [a, index] : {std::pair{a1, u}, std::pair{a2, v}}) {
        Eigen::Vector3d n = Eigen::Vector3d::Zero();
        n[a] = 1.0;
        const double low = grid.origin[a] + index * grid.cell - agent.radius;
        const double high = grid.origin[a] + (index + 1) * grid.cell + agent.radius;
        clip_polygon_into(part, Plane{n, high}, 0.0, clipped);
        clip_polygon_into(clipped, Plane{-n, -low}, 0.0, part);
      }
      if (part.empty()) continue;
      int first = lo[axis], last = hi[axis];
      // One cell more than the cell of w's height: rounding in the floor
      // never leaves out the cell holding w itself.
      if (agent.up_sign > 0) {
        double lowest = part[0][axis];
        for (const Eigen::Vector3d& q : part) lowest = std::min(lowest, q[axis]);
        first = std::max(first, static_cast<int>(std::floor((lowest - grid.origin[axis]) / grid.cell)) - 1);
      } else {
        // Up is -axis: the face's lowest point has the largest coordinate.
        double bottom = part[0][axis];
        for (const Eigen::Vector3d& q : part) bottom = std::max(bottom, q[axis]);
        last = std::min(last, static_cast<int>(std::floor((bottom - grid.origin[axis]) / grid.cell)) + 1);
      }
      int run_start = first;
      for (int w = first; w <= last + 1; ++w) {
        if (w <= last) {
          const Eigen::Vector3i& q = cell(w);
          if (marks.get(q.x(), q.y(), q.z()) & kClear) continue;
        }
        if (w - run_start >= fewest)
          for (int x = run_start; x < w; ++x) {
            const Eigen::Vector3i& q = cell(x);
            if (marks.cells_held() > most_held) return false;
            marks.at(q.x(), q.y(), q.z()) |= kStanding;
          }
        run_start = w + 1;
      }
    }
  return true;
}

// Marks kDropping below every standing cell, down through clear cells: an
// agent stepping off a ledge falls straight down. Only columns of blocks
// holding cells (every standing cell is in one) are walked; a block no
// fall enters is skipped whole, and one a fall enters is classified first.
bool mark_drops(const AgentShape& agent, long long most_held, ReachMarks& marks,
                const std::function<void(long long)>& classify) {
  const int axis = agent.up_axis;
  const int down = agent.up_sign > 0 ? -1 : 1;
  const Eigen::Vector3i& dims = marks.dims();
  const Eigen::Vector3i& blocks = marks.block_dims();
  const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
  Eigen::Vector3i block;
  for (int bu = 0; bu < blocks[a1]; ++bu)
    for (int bv = 0; bv < blocks[a2]; ++bv) {
      block[a1] = bu;
      block[a2] = bv;
      bool any_held = false;
      for (int bw = 0; bw < blocks[axis] && !any_held; ++bw) {
        block[axis] = bw;
        any_held = marks.held(marks.block_index(block)) != nullptr;
      }
      if (!any_held) continue;
      const int u_end = std::min(dims[a1], (bu + 1) * kReachBlock), v_end = std::min(dims[a2], (bv + 1) * kReachBlock);
      for (int u = bu * kReachBlock; u < u_end; ++u)
        for (int v = bv * kReachBlock; v < v_end; ++v) {
          bool falling = false;
          Eigen::Vector3i c;
          c[a1] = u;
          c[a2] = v;
          const int first = down < 0 ? dims[axis] - 1 : 0;
          for (int w = first; w >= 0 && w < dims[axis]; w += down) {
            c[axis] = w;
            const long long b = marks.block_index(ReachMarks::block_of(c));
            if (!falling && !marks.held(b)) {
              // No standing cell here (standing cells are held): on to the
              // next block down.
              w = down < 0 ? w / kReachBlock * kReachBlock
                           : std::min(dims[axis], (w / kReachBlock + 1) * kReachBlock) - 1;
              continue;
            }
            if (marks.cells_held() > most_held) return false;
            if (!marks.classified(b)) classify(b);
            const std::uint8_t m = marks.get(c.x(), c.y(), c.z());
            if (!(m & kClear))
              falling = false;
            else if (m & kStanding)
              falling = true;
            else if (falling)
              marks.at(c.x(), c.y(), c.z()) |= kDropping;
          }
        }
    }
  return marks.cells_held() <= most_held;
}

void add_outer_cells(ReachMarks& marks, FloodStarts& out) {
  const Eigen::Vector3i& d = marks.dims();
  const Eigen::Vector3i& blocks = marks.block_dims();
  for (long long b = 0; b < marks.block_count(); ++b) {
    const Eigen::Vector3i block = marks.block_at(b);
    if (!(block.array() == 0).any() && !(block.array() == blocks.array() - 1).any()) continue;
    if (marks.uniform(b)) {
      if (marks.uniform_byte(b) & kClear) out.blocks.push_back(b);
      continue;
    }
    const std::uint8_t* bytes = marks.held(b);
    if (!bytes) continue;
    const Eigen::Vector3i lo = block * kReachBlock;
    const Eigen::Vector3i hi = (lo.array() + kReachBlock).min(d.array());
    for (int k = lo.z(); k < hi.z(); ++k)
      for (int j = lo.y(); j < hi.y(); ++j)
        for (int i = lo.x(); i < hi.x(); ++i) {
          const bool outer = i == 0 || j == 0 || k == 0 || i == d.x() - 1 || j == d.y() - 1 || k == d.z() - 1;
          if (outer && (bytes[ReachMarks::in_block(i, j, k)] & kClear)) out.cells.push_back(cell_key(i, j, k));
        }
  }
}

void flood(const FloodStarts& starts, std::uint8_t through, ReachMarks& marks) {
  flood_through(marks, starts.cells, starts.blocks, through, kSeeded);
}

// Floods kSeeded from `starts` as a walking agent moves: between standing
// cells freely (stepping and climbing lie within their envelopes), from a
// standing cell into a dropping cell beside or below it, and from a
// dropping cell only straight down. Never up a drop: a ledge out of reach
// stays out of reach. Walkable cells are all in held blocks.
void flood_walking(const AgentShape& agent, std::vector<CellKey> starts, ReachMarks& marks) {
  std::vector<CellKey>& stack = starts;
  for (CellKey key : stack) {
    const Eigen::Vector3i c = cell_of(key);
    marks.at(c.x(), c.y(), c.z()) |= kSeeded;
  }
  const Eigen::Vector3i& dims = marks.dims();
  const int down = agent.up_sign > 0 ? -1 : 1; // the index step along the up axis that goes down
  while (!stack.empty()) {
    const Eigen::Vector3i c = cell_of(stack.back());
    stack.pop_back();
    const bool standing = (marks.get(c.x(), c.y(), c.z()) & kStanding) != 0;
    for (int a = 0; a < 3; ++a)
      for (int s = -1; s <= 1; s += 2) {
        const bool going_down = a == agent.up_axis && s == down;
        const bool going_up = a == agent.up_axis && s != down;
        if (!standing && !going_down) continue; // falling: straight down only
        Eigen::Vector3i n = c;
        n[a] += s;
        if (n[a] < 0 || n[a] >= dims[a]) continue;
        const std::uint8_t m = marks.get(n.x(), n.y(), n.z());
        if ((m & kSeeded) || !(m & kWalkable)) continue;
        if (going_up && !(m & kStanding)) continue; // no climbing up a drop
        marks.at(n.x(), n.y(), n.z()) |= kSeeded;
        stack.push_back(cell_key(n.x(), n.y(), n.z()));
      }
  }
}

} // namespace hullcover::detail
