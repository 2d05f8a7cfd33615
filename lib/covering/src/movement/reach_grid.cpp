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
    if (near.face >= 0 && clearance.box_within(cells, near.face, radius)) return;
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
