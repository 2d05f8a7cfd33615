#include "hullcover/validate/accessible_space.h"

#include "allowance_judge.h"
#include "probe_rays.h"
#include "segment_in_hull.h"

#include "hullcover/geometry/aabb_tree.h"
#include "hullcover/geometry/parallel_for.h"
#include "hullcover/geometry/tolerances.h"

#include <octomap/OcTree.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <unordered_set>

namespace hullcover::validate {
namespace {

// OctoMap keys have 16 bits per axis: 32768 cells either side of its origin.
constexpr double kMaxCellsPerAxis = 32768.0;

// Distance along unit `dir` from `start` to where the ray leaves `box`;
// 0 or less when it starts outside and never enters.
double exit_distance(const Aabb& box, const Eigen::Vector3d& start, const Eigen::Vector3d& dir) {
  double enter = 0.0, leave = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    if (dir[axis] == 0.0) {
      if (start[axis] < box.min[axis] || start[axis] > box.max[axis]) return 0.0;
      continue;
    }
    double t0 = (box.min[axis] - start[axis]) / dir[axis], t1 = (box.max[axis] - start[axis]) / dir[axis];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  }
  return enter <= leave ? leave : 0.0;
}

// A ray's parts deeper than tol inside hulls, with their hull (distances
// along the ray).
using Stretches = std::vector<std::pair<std::pair<double, double>, int>>;

// One open ray that loses space, as the report needs it.
struct LostRay {
  LostPlace deepest; // its deepest point inside a hull
  int pieces = 0;    // how many of ItemRays::pieces are its own (in order)
};

// What one work item's rays found: one face's front rays, or one open
// edge's. Items are traced on many threads, each into its own ItemRays, and
// added to the report in item order by FindingsCollector.
struct ItemRays {
  long rays = 0, enclosed = 0;
  std::vector<LostRay> lost;
  // The lost rays' new lengths, stretch by stretch: added to the tally one
  // by one, the sum is that of one thread tracing every ray in order.
  std::vector<double> pieces;
  AllowanceReport allowance; // the allowance's figures of these rays alone (options unset)
};

// Traces rays and decides them against the hulls. Const: one tracer serves
// every thread, each passing its own ItemRays and scratch stretches.
class RayTracer {
public:
  RayTracer(const PreparedMesh& prepared, const bvh::TriangleWorld& triangles, const bvh::HullWorld& hulls,
            std::optional<double> cap, const AllowanceOptions& allowance)
      : prepared_(prepared), triangles_(triangles), hulls_(hulls.hulls()), cap_(cap) {
    // Each test at the tolerance of its place (hullcover/mesh/tolerance.h):
    // a ray leaves its face at the face's island's, and a hull is entered
    // deeper than the tolerance at the hull's box.
    const PlaceTolerance place_tolerance(prepared.tolerance);
    for (const bvh::RuntimeHull& h : hulls_) hull_tol_.push_back(place_tolerance.at(h.box));
    // Past this box no hull exists, so a ray that meets nothing is decided
    // once it leaves it (grown by the stand-off: a ray starting on the
    // scene's outermost face starts inside).
    world_ = referenced_bounding_box(prepared.mesh);
    std::vector<Aabb> boxes;
    for (const bvh::RuntimeHull& h : hulls_) {
      boxes.push_back(h.box);
      world_.extend(h.box.min);
      world_.extend(h.box.max);
    }
    // With an agent radius, a ball centred up to r beyond the box reaches
    // into it: rays run that much farther (no hull lies out there, so the
    // strict probe's verdict is the same).
    world_ = grown(
        world_, kRayStandOffInTolerances * prepared.tolerance.largest_length() + allowance.agent_radius.value_or(0.0));
    hull_tree_ = AabbTree(boxes);
    if (allowance.any())
      judge_ = std::make_unique<const probe::AllowanceJudge>(prepared, triangles, hulls, hull_tol_, allowance);
  }

  void trace(const probe::ProbeRay& ray, ItemRays& out, Stretches& stretches) const {
    ++out.rays;
    const double tol = prepared_.face_tolerance(ray.face);
    const double stand_off = kRayStandOffInTolerances * tol;
    // Faces count as met only past the stand-off (a neighbour in the plane
    // of the face the ray leaves, within rounding of it, is not a wall in
    // front of it), as the decomposer's witness rays meet them. The hulls
    // are judged from the ray's origin to that first hit, exactly
    // (the strict definition's 0 < t < first hit): a hull entered and left within the
    // stand-off takes free space too.
    const Eigen::Vector3d start = ray.origin + ray.direction * stand_off;
    const double out_of_world = exit_distance(world_, start, ray.direction);
    if (out_of_world <= 0.0) return;
    double length = out_of_world;
    bvh::RayResult hit;
    if (triangles_.ray_cast({start, ray.direction, out_of_world}, hit).ok() && hit.hit) {
      if (enclosed(start, ray.direction, hit.first.t, tol)) {
        ++out.enclosed;
        return;
      }
      length = hit.first.t;
    }
    if (cap_) length = std::min(length, *cap_);
    if (length <= 0.0) return;
    decide(ray, ray.origin, stand_off + length, out, stretches);
    if (judge_) judge_->judge(ray, start, length, stand_off, stretches, out.allowance);
  }

private:
  // The same "within tol" as the decomposer's first_mesh_hit: a front a
  // little further on is not at the first hit.
  bool enclosed(const Eigen::Vector3d& start, const Eigen::Vector3d& dir, double first_hit, double tol) const {
    return probe::ends_on_backs(triangles_, prepared_.mesh, start, dir, first_hit, tol);
  }

  // Clips the free segment against every hull whose box it meets; the
  // union of the stretches inside is the ray's lost length. Leaves the
  // stretches in `stretches`, sorted, for the allowance judge.
  void decide(const probe::ProbeRay& ray, const Eigen::Vector3d& start, double length, ItemRays& out,
              Stretches& stretches) const {
    stretches.clear();
    LostPlace deepest;
    const Eigen::Vector3d end = start + length * ray.direction;
    hull_tree_.nearest_along_segment(start, end, 0.0, 0.0, [&](int h) {
      const std::optional<probe::InsideStretch> inside =
          probe::stretch_inside(hulls_[h].shape.planes, start, ray.direction, length, hull_tol_[h]);
      if (inside) {
        stretches.push_back({{inside->from, inside->to}, h});
        if (inside->depth > deepest.depth)
          deepest = {start + inside->deepest_at * ray.direction, ray.face, h, inside->depth, ray.opening};
      }
      return std::numeric_limits<double>::infinity(); // visit every hull along the segment, not the nearest
    });
    if (stretches.empty()) return;
    std::sort(stretches.begin(), stretches.end());
    LostRay lost{deepest, 0};
    double reached = stretches.front().first.first;
    for (const auto& [stretch, hull] : stretches) {
      const auto& [from, to] = stretch;
      const double begin = std::max(from, reached);
      if (to > begin) {
        out.pieces.push_back(to - begin);
        ++lost.pieces;
      }
      reached = std::max(reached, to);
    }
    out.lost.push_back(lost);
  }

  const PreparedMesh& prepared_;
  const bvh::TriangleWorld& triangles_;
  const std::vector<bvh::RuntimeHull>& hulls_;
  std::optional<double> cap_;
  std::vector<double> hull_tol_; // per hull: the tolerance at its box
  Aabb world_;
  AabbTree hull_tree_;
  std::unique_ptr<const probe::AllowanceJudge> judge_; // with an allowance only
};

// Adds the items' findings to the report, one item after another in item
// order on one thread: the tallies, the deepest places, the octree's cells.
class FindingsCollector {
public:
  // The octree's origin is the scene's box centre (ProbeReport::octree_origin).
  FindingsCollector(const PreparedMesh& prepared, ProbeReport& report) : report_(report), tree_(report.resolution) {
    const Aabb scene = referenced_bounding_box(prepared.mesh);
    centre_ = 0.5 * (scene.min + scene.max);
    report.octree_origin = centre_;
  }

  void add(const ItemRays& item, RayTally& tally) {
    tally.rays += item.rays;
    tally.enclosed += item.enclosed;
    size_t piece = 0;
    for (const LostRay& ray : item.lost) {
      ++tally.lost;
      for (int k = 0; k < ray.pieces; ++k) tally.lost_length += item.pieces[piece++];
      if (ray.deepest.depth > tally.deepest.depth) tally.deepest = ray.deepest;
      mark_cell(ray.deepest.point);
      note(ray.deepest);
    }
    probe::add_allowance_figures(report_.allowance, item.allowance);
  }

  // The octree cells of the lost rays' deepest points, and their count.
  void fill_octree() {
    for (const octomap::OcTreeKey& key : lost_keys_) tree_.updateNode(key, true, true);
    tree_.updateInnerOccupancy();
    report_.lost_cells = static_cast<long>(lost_keys_.size());
  }

  octomap::OcTree& tree() { return tree_; }

private:
  // OctoMap's keys are 16 bits: 2^15 cells each side of the centre.
  static constexpr double kOctreeKeysEachSide = 32768.0;

  // The octree's picture of the lost rays: the cell of each one's deepest
  // point (every cell along every stretch would cost as much as the volume
  // lost, which peers' hulls make most of the scene).
  void mark_cell(const Eigen::Vector3d& p) {
    const Eigen::Vector3d local = p - centre_;
    octomap::OcTreeKey key;
    // A cell beyond the octree's reach (a hull far outside the scene) is
    // left out of the picture; the rays have counted it. Judged here first:
    // OctoMap converts the coordinate to an int before its own check, which
    // is undefined for one far out (a hull at 1e38).
    if (!(local.cwiseAbs().maxCoeff() < tree_.getResolution() * kOctreeKeysEachSide)) return; // NaN too
    if (tree_.coordToKeyChecked(octomap::point3d(static_cast<float>(local.x()), static_cast<float>(local.y()),
                                                 static_cast<float>(local.z())),
                                key))
      lost_keys_.insert(key);
  }

  // Keeps the deepest place per hull, the kWorstPlaces deepest hulls.
  void note(const LostPlace& place) {
    report_.max_lost_depth = std::max(report_.max_lost_depth, place.depth);
    std::vector<LostPlace>& worst = report_.worst;
    const auto same_hull =
        std::find_if(worst.begin(), worst.end(), [&](const LostPlace& w) { return w.hull == place.hull; });
    if (same_hull != worst.end()) {
      if (same_hull->depth >= place.depth) return;
      worst.erase(same_hull);
    }
    worst.push_back(place);
    std::sort(worst.begin(), worst.end(), [](const LostPlace& a, const LostPlace& b) { return a.depth > b.depth; });
    if (worst.size() > kWorstPlaces) worst.pop_back();
  }

  ProbeReport& report_;
  octomap::OcTree tree_;
  Eigen::Vector3d centre_;
  std::unordered_set<octomap::OcTreeKey, octomap::OcTreeKey::KeyHash> lost_keys_;
};

} // namespace

// The part of the probe's progress its front rays stand for (they
// outnumber the openings' rays several times on real scenes).
constexpr double kFrontRayShareOfProbe = 0.8;
// Faces or edges traced between two additions to the report: their
// findings are kept until then (memory bounded by a batch), and a batch is
// long enough that its threads seldom wait for one another at its end.
constexpr int kItemsPerBatch = 4096;

Result<ProbeReport> probe_accessible_space(const PreparedMesh& prepared, const bvh::TriangleWorld& triangles,
                                           const bvh::HullWorld& hulls, const ProbeOptions& options, int threads) {
  ProbeReport report;
  const double diagonal = prepared.tolerance.diagonal;
  report.probe_distance = options.probe_distance;
  report.resolution = options.resolution.value_or(kDefaultProbeSpacingRelative * diagonal);
  const auto positive_length = [](double x) { return x > 0.0 && std::isfinite(x); };
  if ((options.probe_distance && !positive_length(*options.probe_distance)) || !positive_length(report.resolution))
    return Status{StatusCode::invalid_argument, "probe distance and resolution must be positive lengths"};
  const AllowanceOptions& allowance = options.allowance;
  if ((allowance.agent_radius && !(*allowance.agent_radius > 2.0 * prepared.tolerance.largest_length() &&
                                   std::isfinite(*allowance.agent_radius))) ||
      (allowance.max_deviation && !positive_length(*allowance.max_deviation)))
    return Status{
        StatusCode::invalid_argument,
        "the agent radius must be a finite length above twice the tolerance, the max deviation a positive length"};
  if (allowance.max_evaluations_per_ray < 2)
    return Status{StatusCode::invalid_argument, "a ray needs at least 2 evaluations (its two ends)"};
  if (0.5 * diagonal / report.resolution > kMaxCellsPerAxis)
    return Status{StatusCode::invalid_argument, "resolution too fine: the octree has 16 levels (32768 cells a side)"};
  if (threads < 0) return Status{StatusCode::invalid_argument, "the thread count must be 0 (every core) or more"};
  threads = threads_to_use(threads);
  try {
    report.allowance.options = allowance;
    const RayTracer tracer(prepared, triangles, hulls, options.probe_distance, allowance);
    FindingsCollector collector(prepared, report);
    std::vector<ItemRays> items(kItemsPerBatch);
    // Traces every item of one kind (faces' front rays, or edges' opening
    // rays) on the threads, adding them to `tally` in item order; progress
    // goes from `start` to `start + share` as items are added.
    const auto trace_items = [&](int count, const auto& rays_of_item, RayTally& tally, double start, double share) {
      const auto trace_item = [&](int i) {
        ItemRays& item = items[i % kItemsPerBatch];
        Stretches stretches;
        rays_of_item(i, [&](const probe::ProbeRay& ray) { tracer.trace(ray, item, stretches); });
      };
      const auto add_item = [&](int i) {
        ItemRays& item = items[i % kItemsPerBatch];
        collector.add(item, tally);
        item = ItemRays{};
        if (options.progress) options.progress(start + share * (i + 1.0) / count);
      };
      parallel_for_ordered(count, threads, kItemsPerBatch, trace_item, add_item);
    };
    // Per island: a map inside a world gets the rays it gets alone. An
    // island of one point (all its faces of no area) has no length: the
    // scene's spacing.
    std::vector<double> spacing_of_island;
    for (const Aabb& box : prepared.islands.boxes) {
      const double spacing = options.resolution.value_or(kDefaultProbeSpacingRelative * box.diagonal());
      spacing_of_island.push_back(spacing > 0.0 ? spacing : report.resolution);
    }
    const auto spacing_of_face = [&](int face) { return spacing_of_island[prepared.islands.island_of_face[face]]; };
    report.finest_spacing = report.coarsest_spacing = report.resolution;
    if (!spacing_of_island.empty()) {
      const auto [finest, coarsest] = std::minmax_element(spacing_of_island.begin(), spacing_of_island.end());
      report.finest_spacing = *finest;
      report.coarsest_spacing = *coarsest;
    }
    const auto front_rays = [&](int face, const std::function<void(const probe::ProbeRay&)>& trace) {
      probe::front_rays_of_face(prepared, spacing_of_face(face), face, trace);
    };
    const auto opening_rays = [&](int edge, const std::function<void(const probe::ProbeRay&)>& trace) {
      const MeshConnectivity& c = prepared.connectivity;
      const double spacing = spacing_of_face(c.edge_uses[c.edges[edge].first_use].face);
      probe::opening_rays_of_edge(prepared, spacing, edge, trace);
    };
    trace_items(static_cast<int>(prepared.mesh.triangles.size()), front_rays, report.front, 0.0, kFrontRayShareOfProbe);
    trace_items(static_cast<int>(prepared.connectivity.edges.size()), opening_rays, report.opening,
                kFrontRayShareOfProbe, 1.0 - kFrontRayShareOfProbe);
    if (options.progress) options.progress(1.0);
    collector.fill_octree();
    if (!options.octree_path.empty() && !collector.tree().writeBinary(options.octree_path))
      return Status{StatusCode::unwritable_file, options.octree_path + ": cannot write the octree"};
    return report;
  } catch (const std::exception& e) {
    return Status{StatusCode::internal_error, std::string("accessible-space probe failed: ") + e.what()};
  }
}

} // namespace hullcover::validate
