#include "movement/reach_moves.h"

#include "hullcover/geometry/convex_polytope.h"

#include <algorithm>
#include <cmath>

namespace hullcover::detail {

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
void mark_standing(const ReachGrid& grid, const Mesh& mesh, const AgentShape& agent, int face,
                   std::vector<std::uint8_t>& marks) {
  Aabb box;
  std::vector<Eigen::Vector3d> triangle;
  for (int k = 0; k < 3; ++k) {
    box.extend(mesh.positions[mesh.triangles[face][k]]);
    triangle.push_back(mesh.positions[mesh.triangles[face][k]]);
  }
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
  Eigen::Vector3i lo, hi;
  cell_range(grid, box, lo, hi);
  const int axis = agent.up_axis;
  const int fewest = static_cast<int>(
      std::min(std::floor((agent.height - 2.0 * agent.radius) / grid.cell), double(grid.dims[agent.up_axis] + 1)));
  Eigen::Vector3i c;
  const auto at = [&](int w) {
    c[axis] = w;
    return grid.index(c.x(), c.y(), c.z());
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
        if (w <= last && (marks[at(w)] & kClear)) continue;
        if (w - run_start >= fewest)
          for (int x = run_start; x < w; ++x) marks[at(x)] |= kStanding;
        run_start = w + 1;
      }
    }
}

// Marks kDropping below every standing cell, down through clear cells: an
// agent stepping off a ledge falls straight down.
void mark_drops(const ReachGrid& grid, const AgentShape& agent, std::vector<std::uint8_t>& marks) {
  const int axis = agent.up_axis;
  const int down = agent.up_sign > 0 ? -1 : 1;
  const Eigen::Vector3i& dims = grid.dims;
  const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
  for (int u = 0; u < dims[a1]; ++u)
    for (int v = 0; v < dims[a2]; ++v) {
      bool falling = false;
      const int first = down < 0 ? dims[axis] - 1 : 0;
      for (int w = first; w >= 0 && w < dims[axis]; w += down) {
        Eigen::Vector3i c;
        c[axis] = w;
        c[a1] = u;
        c[a2] = v;
        std::uint8_t& m = marks[grid.index(c.x(), c.y(), c.z())];
        if (!(m & kClear))
          falling = false;
        else if (m & kStanding)
          falling = true;
        else if (falling)
          m |= kDropping;
      }
    }
}

// Appends the grid's outer clear cells (where the sky beyond meets it).
void add_outer_cells(const ReachGrid& grid, const std::vector<std::uint8_t>& marks, std::vector<std::uint32_t>& out) {
  const Eigen::Vector3i& d = grid.dims;
  for (int k = 0; k < d.z(); ++k)
    for (int j = 0; j < d.y(); ++j)
      for (int i = 0; i < d.x(); ++i) {
        const bool outer = i == 0 || j == 0 || k == 0 || i == d.x() - 1 || j == d.y() - 1 || k == d.z() - 1;
        if (!outer) {
          i = d.x() - 2; // jump to the far face of this row
          continue;
        }
        const long long c = grid.index(i, j, k);
        if (marks[c] & kClear) out.push_back(static_cast<std::uint32_t>(c));
      }
}

// Floods kSeeded from the cells in `starts` through cells holding every bit
// of `through`, across shared faces.
void flood(const ReachGrid& grid, std::vector<std::uint32_t> starts, std::uint8_t through,
           std::vector<std::uint8_t>& marks) {
  std::vector<std::uint32_t>& stack = starts;
  for (long long c : stack) marks[c] |= kSeeded;
  const Eigen::Vector3i& dims = grid.dims;
  const long long step[3] = {1, dims.x(), static_cast<long long>(dims.x()) * dims.y()};
  while (!stack.empty()) {
    const long long c = stack.back();
    stack.pop_back();
    const long long k = c / step[2], j = (c / step[1]) % dims.y(), i = c % dims.x();
    const long long at[3] = {i, j, k};
    for (int a = 0; a < 3; ++a)
      for (int s = -1; s <= 1; s += 2) {
        const long long n = at[a] + s;
        if (n < 0 || n >= dims[a]) continue;
        const long long next = c + s * step[a];
        std::uint8_t& m = marks[next];
        if ((m & kSeeded) || (m & through) != through) continue;
        m |= kSeeded;
        stack.push_back(static_cast<std::uint32_t>(next));
      }
  }
}

// Floods kSeeded from `starts` as a walking agent moves: between standing
// cells freely (stepping and climbing lie within their envelopes), from a
// standing cell into a dropping cell beside or below it, and from a
// dropping cell only straight down. Never up a drop: a ledge out of reach
// stays out of reach.
void flood_walking(const ReachGrid& grid, const AgentShape& agent, std::vector<std::uint32_t> starts,
                   std::vector<std::uint8_t>& marks) {
  std::vector<std::uint32_t>& stack = starts;
  for (long long c : stack) marks[c] |= kSeeded;
  const Eigen::Vector3i& dims = grid.dims;
  const long long step[3] = {1, dims.x(), static_cast<long long>(dims.x()) * dims.y()};
  const int down = agent.up_sign > 0 ? -1 : 1; // the index step along the up axis that goes down
  while (!stack.empty()) {
    const long long c = stack.back();
    stack.pop_back();
    const bool standing = (marks[c] & kStanding) != 0;
    const long long at[3] = {c % dims.x(), (c / step[1]) % dims.y(), c / step[2]};
    for (int a = 0; a < 3; ++a)
      for (int s = -1; s <= 1; s += 2) {
        const bool going_down = a == agent.up_axis && s == down;
        const bool going_up = a == agent.up_axis && s != down;
        if (!standing && !going_down) continue; // falling: straight down only
        const long long n = at[a] + s;
        if (n < 0 || n >= dims[a]) continue;
        const long long next = c + s * step[a];
        std::uint8_t& m = marks[next];
        if ((m & kSeeded) || !(m & kWalkable)) continue;
        if (going_up && !(m & kStanding)) continue; // no climbing up a drop
        m |= kSeeded;
        stack.push_back(static_cast<std::uint32_t>(next));
      }
  }
}

} // namespace hullcover::detail
