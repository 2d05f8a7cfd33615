#include "movement/reach_grid.h"

#include "hullcover/geometry/convex_polytope.h"
#include "hullcover/geometry/parallel_for.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <string>

namespace hullcover::detail {
namespace {

// Per-cell marks while the grid is built.
constexpr std::uint8_t kClear = 1;     // may hold a point at clearance >= r
constexpr std::uint8_t kStanding = 2;  // within a walkable face's standing envelope
constexpr std::uint8_t kDropping = 4;  // below a standing cell, falling straight down
constexpr std::uint8_t kSeeded = 8;    // reached from a seed
constexpr std::uint8_t kWalkable = 16; // clear, and standing or dropping: a walking agent's centre may be here

// Blocks of this many cells a side are classified on their own (in parallel).
constexpr int kBlock = 32;

std::string number_text(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

std::string point_text(const Eigen::Vector3d& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", p.x(), p.y(), p.z());
  return text;
}

struct GridBuild {
  const ReachGrid& grid;
  const SceneClearance& clearance;
  double threshold; // a cell may hold a clear centre when its centre's clearance is at least this
  double radius;
  std::vector<std::uint8_t>& marks;

  // Marks kClear in the cells of the cube of `size` cells (a power of 2) at
  // `lo`, clipped to the grid. The clearance at the middle of the cube's
  // cell centres bounds every one of them within `spread` (1-Lipschitz).
  void classify(const Eigen::Vector3i& lo, int size) const {
    const Eigen::Vector3i& dims = grid.dims;
    if (lo.x() >= dims.x() || lo.y() >= dims.y() || lo.z() >= dims.z()) return;
    const Eigen::Vector3d middle = grid.origin + (lo.cast<double>().array() + 0.5 * size).matrix() * grid.cell;
    const double spread = 0.5 * (size - 1) * grid.cell * std::sqrt(3.0);
    const NearestFace near = clearance.nearest(middle, threshold + spread + grid.cell);
    const double d = near.distance;
    if (d + spread < threshold) return;
    const Eigen::Vector3i hi = (lo.array() + size).min(dims.array());
    // No point of the cells at clearance r or more: one triangle is nearer
    // than r to all of them (the cells beside a surface, whose centres
    // alone would let them hold centres on both of its sides).
    Aabb cells;
    cells.min = grid.origin + lo.cast<double>() * grid.cell;
    cells.max = grid.origin + hi.cast<double>() * grid.cell;
    if (near.face >= 0 && clearance.farthest_in_box(cells, near.face) < radius) return;
    if (d - spread >= threshold || size == 1) {
      if (size == 1 && d < threshold) return;
      for (int k = lo.z(); k < hi.z(); ++k)
        for (int j = lo.y(); j < hi.y(); ++j)
          for (int i = lo.x(); i < hi.x(); ++i) marks[grid.index(i, j, k)] |= kClear;
      return;
    }
    const int half = size / 2;
    for (int child = 0; child < 8; ++child)
      classify(lo + Eigen::Vector3i((child & 1) * half, ((child >> 1) & 1) * half, ((child >> 2) & 1) * half), half);
  }
};

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
        double lowest = part[0][axis];
        for (const Eigen::Vector3d& q : part) lowest = std::max(lowest, q[axis]);
        last = std::min(last, static_cast<int>(std::floor((lowest - grid.origin[axis]) / grid.cell)) + 1);
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

} // namespace

double ReachGrid::half_diagonal() const { return 0.5 * cell * std::sqrt(3.0); }

bool ReachGrid::reachable_at(const Eigen::Vector3d& p) const {
  Eigen::Vector3i c;
  for (int a = 0; a < 3; ++a) {
    const double f = std::floor((p[a] - origin[a]) / cell);
    if (!(f >= 0.0 && f < dims[a])) return true;
    c[a] = static_cast<int>(f);
  }
  return reachable(index(c.x(), c.y(), c.z()));
}

void ReachGrid::set_reachable(std::vector<std::uint8_t> reachable) {
  reachable_ = std::move(reachable);
  bricks_ = (dims.array() + kBrick - 1) / kBrick;
  brick_counts_.assign(static_cast<size_t>(bricks_.x()) * bricks_.y() * bricks_.z(), 0);
  for (int k = 0; k < dims.z(); ++k)
    for (int j = 0; j < dims.y(); ++j)
      for (int i = 0; i < dims.x(); ++i)
        if (reachable_[index(i, j, k)])
          ++brick_counts_[(static_cast<size_t>(k / kBrick) * bricks_.y() + j / kBrick) * bricks_.x() + i / kBrick];
}

long long ReachGrid::reachable_count() const {
  long long n = 0;
  for (std::uint16_t c : brick_counts_) n += c;
  return n;
}

bool ReachGrid::any_reachable(const Aabb& box) const {
  Eigen::Vector3i lo, hi;
  for (int a = 0; a < 3; ++a) {
    const double l = std::floor((box.min[a] - origin[a]) / cell), h = std::floor((box.max[a] - origin[a]) / cell);
    if (!(l >= 0.0 && h < dims[a])) return true; // leaves the grid (or NaN): may reach
    lo[a] = static_cast<int>(l);
    hi[a] = static_cast<int>(h);
  }
  const Eigen::Vector3i blo = lo / kBrick, bhi = hi / kBrick;
  for (int bk = blo.z(); bk <= bhi.z(); ++bk)
    for (int bj = blo.y(); bj <= bhi.y(); ++bj)
      for (int bi = blo.x(); bi <= bhi.x(); ++bi) {
        if (brick_counts_[(static_cast<size_t>(bk) * bricks_.y() + bj) * bricks_.x() + bi] == 0) continue;
        const Eigen::Vector3i clo = lo.cwiseMax(Eigen::Vector3i(bi, bj, bk) * kBrick);
        const Eigen::Vector3i chi =
            hi.cwiseMin((Eigen::Vector3i(bi, bj, bk).array() + 1).matrix() * kBrick - Eigen::Vector3i::Ones());
        for (int k = clo.z(); k <= chi.z(); ++k)
          for (int j = clo.y(); j <= chi.y(); ++j)
            for (int i = clo.x(); i <= chi.x(); ++i)
              if (reachable_[index(i, j, k)]) return true;
      }
  return false;
}

bool is_walkable(const Mesh& mesh, const AgentShape& agent, int face) {
  const Eigen::Vector3i& t = mesh.triangles[face];
  const Eigen::Vector3d n =
      (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]);
  const double length = n.norm();
  if (!(length > 0.0)) return false;
  return agent.up_sign * n[agent.up_axis] / length >= agent.min_up_cosine;
}

Result<ReachGrid> build_reach_grid(const Mesh& mesh, const SceneClearance& clearance, const AgentShape& agent,
                                   const std::vector<Eigen::Vector3d>& seeds, bool seeds_given, int threads) {
  ReachGrid grid;
  grid.cell = kReachCellInRadii * agent.radius;
  Aabb box;
  for (const Eigen::Vector3i& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) box.extend(mesh.positions[t[k]]);
  box = grown(box, agent.radius + grid.cell);
  // Room above the highest walkable face for a walker's whole axis.
  if (agent.reach == AgentReach::walk) {
    const double rise = std::min(agent.climb + agent.height - agent.radius, box.diagonal() + agent.radius);
    if (agent.up_sign > 0)
      box.max[agent.up_axis] += rise;
    else
      box.min[agent.up_axis] -= rise;
  }
  const Eigen::Vector3d cells = ((box.max - box.min) / grid.cell).array().ceil();
  if (!(cells.prod() <= static_cast<double>(kMostReachCells)))
    return Status{StatusCode::limit_exceeded,
                  "the reach grid of this scene at agent radius " + std::to_string(agent.radius) + " would need " +
                      number_text(cells.prod()) + " cells (at most " + std::to_string(kMostReachCells) +
                      "): use a larger radius or a part of the scene"};
  grid.origin = box.min;
  grid.dims = cells.cast<int>().cwiseMax(1);

  std::vector<std::uint8_t> marks(static_cast<size_t>(grid.cell_count()), 0);
  const GridBuild build{grid, clearance, agent.radius - grid.half_diagonal(), agent.radius, marks};
  const Eigen::Vector3i blocks = (grid.dims.array() + kBlock - 1) / kBlock;
  // Blocks of kBlock cells a side: each writes only its own cells.
  parallel_for(blocks.prod(), threads, [&](int b) {
    const Eigen::Vector3i at(b % blocks.x(), (b / blocks.x()) % blocks.y(), b / (blocks.x() * blocks.y()));
    build.classify(at * kBlock, kBlock);
  });

  const bool walking = agent.reach == AgentReach::walk;
  if (walking)
    for (int f = 0; f < static_cast<int>(mesh.triangles.size()); ++f)
      if (is_walkable(mesh, agent, f)) mark_standing(grid, mesh, agent, f, marks);
  if (walking) mark_drops(grid, agent, marks);
  const auto walkable_cell = [](std::uint8_t m) { return (m & kClear) && (m & (kStanding | kDropping)); };
  const auto occupiable = [&](std::uint8_t m) { return walking ? walkable_cell(m) : (m & kClear) != 0; };

  std::vector<std::uint32_t> starts;
  for (const Eigen::Vector3d& seed : seeds) {
    const Eigen::Vector3d at = ((seed - grid.origin) / grid.cell).array().floor();
    if (!((at.array() >= 0.0).all() && (at.array() < grid.dims.cast<double>().array()).all())) {
      // Beyond the grid: open sky, joined to the scene through the grid's
      // outer cells (flying); no walker stands there.
      if (walking && seeds_given)
        return Status{StatusCode::invalid_argument,
                      "seed " + point_text(seed) + " lies beyond the scene: no walkable face below it"};
      if (!walking) add_outer_cells(grid, marks, starts);
      continue;
    }
    const long long c = grid.index(static_cast<int>(at.x()), static_cast<int>(at.y()), static_cast<int>(at.z()));
    if (!occupiable(marks[c]) && !seeds_given) continue;
    if (!occupiable(marks[c]))
      return Status{StatusCode::invalid_argument,
                    "seed " + point_text(seed) +
                        (walking ? " is not where a walking agent can be (no walkable face within its height below "
                                   "it, or too near the triangles)"
                                 : " is too near the triangles for the agent")};
    starts.push_back(static_cast<std::uint32_t>(c));
    ++grid.seeds_used;
  }
  if (walking)
    for (std::uint8_t& m : marks)
      if (walkable_cell(m)) m |= kWalkable;
  const std::uint8_t through = walking ? kWalkable : kClear;
  if (!seeds.empty()) {
    if (walking)
      flood_walking(grid, agent, std::move(starts), marks);
    else
      flood(grid, std::move(starts), through, marks);
  } else {
    // No seed (flying over a scene with nothing to stand on): all clear
    // space, no connectivity asked.
    for (std::uint8_t& m : marks)
      if (m & through) m |= kSeeded;
  }
  for (std::uint8_t& m : marks) m = (m & kSeeded) ? 1 : 0;
  grid.set_reachable(std::move(marks));
  return grid;
}

std::vector<Eigen::Vector3d> default_seeds(const SceneClearance& clearance, const AgentShape& agent, double tol) {
  const Mesh& mesh = clearance.mesh();
  std::vector<Eigen::Vector3d> seeds;
  for (int f = 0; f < static_cast<int>(mesh.triangles.size()); ++f) {
    if (!is_walkable(mesh, agent, f)) continue;
    const Eigen::Vector3i& t = mesh.triangles[f];
    const Eigen::Vector3d &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
    const Eigen::Vector3d normal = (b - a).cross(c - a).normalized();
    const Eigen::Vector3d centroid = (a + b + c) / 3.0;
    const Eigen::Vector3d lift = (agent.radius + 2.0 * tol) * normal;
    for (const Eigen::Vector3d& base : {centroid, Eigen::Vector3d(0.5 * (centroid + a)),
                                        Eigen::Vector3d(0.5 * (centroid + b)), Eigen::Vector3d(0.5 * (centroid + c))}) {
      const Eigen::Vector3d seed = base + lift;
      if (clearance.nearest(seed, agent.radius).distance >= agent.radius) seeds.push_back(seed);
    }
  }
  return seeds;
}

bool face_may_be_touched(const ReachGrid& grid, const SceneClearance& clearance, const AgentShape& agent, int face) {
  const Mesh& mesh = clearance.mesh();
  Aabb box;
  for (int k = 0; k < 3; ++k) box.extend(mesh.positions[mesh.triangles[face][k]]);
  const double reach = agent.radius + grid.half_diagonal();
  box = grown(box, reach);
  Eigen::Vector3i lo, hi;
  cell_range(grid, box, lo, hi);
  for (int k = lo.z(); k <= hi.z(); ++k)
    for (int j = lo.y(); j <= hi.y(); ++j)
      for (int i = lo.x(); i <= hi.x(); ++i)
        if (grid.reachable(grid.index(i, j, k)) && clearance.to_face(grid.centre(i, j, k), face) <= reach) return true;
  return false;
}

} // namespace hullcover::detail
