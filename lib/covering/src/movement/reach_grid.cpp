#include "movement/reach_grid.h"
#include "movement/reach_moves.h"

#include "hullcover/geometry/parallel_for.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <string>

namespace hullcover::detail {
namespace {

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

// The cubes the halving starts from, kReachBlock or a multiple (a power of 2).
constexpr int kClassifiedCube = 32;
static_assert(kClassifiedCube % kReachBlock == 0, "a classified cube holds whole blocks");

struct GridBuild {
  const ReachGrid& grid;
  const SceneClearance& clearance;
  double threshold; // a cell may hold a clear centre when its centre's clearance is at least this
  double radius;
  ReachMarks& marks;

  // How the cube of `size` cells (a power of 2) at `lo` stands: none of
  // its cells may hold a point at clearance r (kNone), all may (kAll), or
  // it must be halved. The clearance at the middle of the cube's cell
  // centres bounds every one of them within `spread` (1-Lipschitz).
  enum class Cube { none, all, mixed };
  Cube judge(const Eigen::Vector3i& lo, int size) const {
    const Eigen::Vector3d middle = grid.origin + (lo.cast<double>().array() + 0.5 * size).matrix() * grid.cell;
    const double spread = 0.5 * (size - 1) * grid.cell * std::sqrt(3.0);
    const NearestFace near = clearance.nearest(middle, threshold + spread + grid.cell);
    const double d = near.distance;
    if (d + spread < threshold) return Cube::none;
    const Eigen::Vector3i hi = (lo.array() + size).min(grid.dims.array());
    // No point of the cells at clearance r or more: one triangle is nearer
    // than r to all of them (the cells beside a surface, whose centres
    // alone would let them hold centres on both of its sides).
    Aabb cells;
    cells.min = grid.origin + lo.cast<double>() * grid.cell;
    cells.max = grid.origin + hi.cast<double>() * grid.cell;
    if (near.face >= 0 && clearance.box_within(cells, near.face, radius)) return Cube::none;
    if (d - spread >= threshold) return Cube::all;
    if (size == 1) return Cube::none;
    return Cube::mixed;
  }

  // Marks kClear in the cells of the cube of `size` cells at `lo` (inside
  // the block whose bytes are `bytes`), clipped to the grid.
  void classify(const Eigen::Vector3i& lo, int size, std::uint8_t* bytes) const {
    const Eigen::Vector3i& dims = grid.dims;
    if (lo.x() >= dims.x() || lo.y() >= dims.y() || lo.z() >= dims.z()) return;
    const Cube cube = judge(lo, size);
    if (cube == Cube::none) return;
    if (cube == Cube::all) {
      const Eigen::Vector3i hi = (lo.array() + size).min(dims.array());
      for (int k = lo.z(); k < hi.z(); ++k)
        for (int j = lo.y(); j < hi.y(); ++j)
          for (int i = lo.x(); i < hi.x(); ++i) bytes[ReachMarks::in_block(i, j, k)] |= kClear;
      return;
    }
    const int half = size / 2;
    for (int child = 0; child < 8; ++child)
      classify(lo + Eigen::Vector3i((child & 1) * half, ((child >> 1) & 1) * half, ((child >> 2) & 1) * half), half,
               bytes);
  }

  // Classifies block `b`: uniform when decided whole, else a byte a cell.
  // The halving starts from the cube of kClassifiedCube cells holding the
  // block, whatever the block size: the cells kept do not depend on how
  // they are stored.
  void classify_block(long long b) const {
    const Eigen::Vector3i lo = marks.block_at(b) * kReachBlock;
    Cube cube = judge(lo / kClassifiedCube * kClassifiedCube, kClassifiedCube);
    if (cube == Cube::mixed) cube = judge(lo, kReachBlock);
    if (cube != Cube::mixed) {
      marks.set_uniform(b, cube == Cube::all ? kClear : 0);
      return;
    }
    std::uint8_t* bytes = marks.hold(b, 0);
    const int half = kReachBlock / 2;
    for (int child = 0; child < 8; ++child)
      classify(lo + Eigen::Vector3i((child & 1) * half, ((child >> 1) & 1) * half, ((child >> 2) & 1) * half), half,
               bytes);
  }
};

Status too_many_cells(const AgentShape& agent) {
  return Status{StatusCode::limit_exceeded,
                "the reach grid of this scene at agent radius " + number_text(agent.radius) + " needs more than " +
                    std::to_string(kMostReachCellsHeld) +
                    " cells held one by one (those near its surfaces): use a larger radius or a part of the scene"};
}

} // namespace

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
  // Counted in whole blocks: what the blocks' own numbers take.
  const Eigen::Vector3d blocks = (cells / kReachBlock).array().ceil();
  if (!(blocks.prod() * kReachBlockCells <= static_cast<double>(kMostReachCells)) ||
      !(cells.maxCoeff() < static_cast<double>(kMostCellsAlongAnAxis)))
    return Status{StatusCode::limit_exceeded,
                  "the reach grid of this scene at agent radius " + number_text(agent.radius) + " would span " +
                      number_text(cells.x()) + " x " + number_text(cells.y()) + " x " + number_text(cells.z()) +
                      " cells (at most " + std::to_string(kMostReachCells) + " in whole blocks of 16^3, and " +
                      std::to_string(kMostCellsAlongAnAxis - 1) +
                      " along an axis): use a larger radius or a part of the scene"};
  grid.origin = box.min;
  grid.dims = cells.cast<int>().cwiseMax(1);

  ReachMarks marks(grid.dims);
  const GridBuild build{grid, clearance, agent.radius - grid.half_diagonal(), agent.radius, marks};
  const bool walking = agent.reach == AgentReach::walk;
  // The blocks to classify: every block (flying), or those a walker may
  // stand in (the rest are classified when a fall enters them).
  std::vector<std::uint8_t> wanted; // walking: a byte a block; flying: empty, every block
  if (walking) {
    wanted.assign(static_cast<size_t>(marks.block_count()), 0);
    for (int f = 0; f < static_cast<int>(mesh.triangles.size()); ++f) {
      if (!is_walkable(mesh, agent, f)) continue;
      Eigen::Vector3i lo, hi;
      cell_range(grid, standing_box(mesh, agent, f), lo, hi);
      const Eigen::Vector3i blo = ReachMarks::block_of(lo), bhi = ReachMarks::block_of(hi);
      for (int k = blo.z(); k <= bhi.z(); ++k)
        for (int j = blo.y(); j <= bhi.y(); ++j)
          for (int i = blo.x(); i <= bhi.x(); ++i) wanted[marks.block_index({i, j, k})] = 1;
    }
  }
  // Each task writes only its own block; past the limit the rest is skipped
  // (the build fails below).
  parallel_for(static_cast<int>(marks.block_count()), threads, [&](int b) {
    if ((wanted.empty() || wanted[b]) && marks.cells_held() <= kMostReachCellsHeld) build.classify_block(b);
  });
  if (marks.cells_held() > kMostReachCellsHeld) return too_many_cells(agent);

  if (walking) {
    for (int f = 0; f < static_cast<int>(mesh.triangles.size()); ++f)
      if (is_walkable(mesh, agent, f) && !mark_standing(grid, mesh, agent, f, kMostReachCellsHeld, marks))
        return too_many_cells(agent);
    if (!mark_drops(agent, kMostReachCellsHeld, marks, [&](long long b) { build.classify_block(b); }))
      return too_many_cells(agent);
  }
  const auto walkable_cell = [](std::uint8_t m) { return (m & kClear) && (m & (kStanding | kDropping)); };
  const auto occupiable = [&](std::uint8_t m) { return walking ? walkable_cell(m) : (m & kClear) != 0; };

  FloodStarts starts;
  bool from_the_sky = false;
  for (const Eigen::Vector3d& seed : seeds) {
    const Eigen::Vector3d at = ((seed - grid.origin) / grid.cell).array().floor();
    if (!((at.array() >= 0.0).all() && (at.array() < grid.dims.cast<double>().array()).all())) {
      // Beyond the grid: open sky, joined to the scene through the grid's
      // outer cells (flying); no walker stands there.
      if (walking && seeds_given)
        return Status{StatusCode::invalid_argument,
                      "seed " + point_text(seed) + " lies beyond the scene: no walkable face below it"};
      if (!walking && !from_the_sky) add_outer_cells(marks, starts);
      from_the_sky = true;
      continue;
    }
    const Eigen::Vector3i c = at.cast<int>();
    const std::uint8_t m = marks.get(c.x(), c.y(), c.z());
    if (!occupiable(m) && !seeds_given) continue;
    if (!occupiable(m))
      return Status{StatusCode::invalid_argument,
                    "seed " + point_text(seed) +
                        (walking ? " is not where a walking agent can be (no walkable face within its height below "
                                   "it, or too near the triangles)"
                                 : " is too near the triangles for the agent")};
    starts.cells.push_back(cell_key(c.x(), c.y(), c.z()));
    ++grid.seeds_used;
  }
  // Walkable cells are standing or dropping, so all in held blocks.
  for (long long b = 0; walking && b < marks.block_count(); ++b)
    if (std::uint8_t* bytes = marks.held(b))
      for (int c = 0; c < kReachBlockCells; ++c)
        if (walkable_cell(bytes[c])) bytes[c] |= kWalkable;
  const std::uint8_t through = walking ? kWalkable : kClear;
  if (!seeds.empty()) {
    if (walking)
      flood_walking(agent, std::move(starts.cells), marks);
    else
      flood(starts, through, marks);
  } else {
    // No seed (flying over a scene with nothing to stand on): all clear
    // space, no connectivity asked.
    for (long long b = 0; b < marks.block_count(); ++b) {
      if (marks.uniform(b) && (marks.uniform_byte(b) & through)) marks.uniform_byte(b) |= kSeeded;
      if (std::uint8_t* bytes = marks.held(b))
        for (int c = 0; c < kReachBlockCells; ++c)
          if (bytes[c] & through) bytes[c] |= kSeeded;
    }
  }
  keep_cells(marks, kSeeded, grid);
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
        if (grid.reachable(i, j, k) && clearance.to_face(grid.centre(i, j, k), face) <= reach) return true;
  return false;
}

} // namespace hullcover::detail
