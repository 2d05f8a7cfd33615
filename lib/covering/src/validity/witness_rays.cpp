#include "validity/witness_rays.h"

#include "validity/loss_allowance.h"
#include "validity/mesh_ray.h"
#include "validity/shadow_pieces.h"

#include "hullcover/geometry/planar_hull.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace hullcover::detail {

namespace {

// Where the ray from `origin` along unit `dir` first lies strictly behind
// every plane (of an interior, already shrunk by tol), if it ever does
// (Cyrus-Beck on t >= 0).
std::optional<double> ray_entry(const std::vector<Plane>& planes, const Eigen::Vector3d& origin,
                                const Eigen::Vector3d& dir) {
  double enter = 0.0, leave = std::numeric_limits<double>::infinity();
  for (const Plane& plane : planes) {
    const double start = plane.signed_distance(origin); // must become < 0
    const double rate = plane.normal.dot(dir);
    if (rate == 0.0) {
      if (start >= 0.0) return std::nullopt;
      continue;
    }
    const double t = -start / rate;
    if (rate < 0.0)
      enter = std::max(enter, t);
    else
      leave = std::min(leave, t);
    if (enter >= leave) return std::nullopt;
  }
  return enter;
}

// Witness rays start this fraction of the way in from a region's corners
// toward its middle, where its middle's ray does not decide it.
constexpr double kWitnessInset = 0.05;

// The first face the sweep's ray from `base` meets past its stand-off (the
// probe's rays stand off the surface they leave), within the scene.
std::optional<MeshRayHit> first_hit_past_stand_off(const SceneIndex& index, const FreeSpaceSweep& sweep,
                                                   const Eigen::Vector3d& base, std::vector<int>& scratch) {
  return first_mesh_hit(index, base, sweep.direction, kRayStandOffInTolerances * index.tol(),
                        index.prepared->tolerance.diagonal, scratch);
}

// What one witness ray found: whether it loses space, and the face that
// kept it from doing so (met before the hull, or met from behind inside
// it), -1 for none.
struct WitnessRay {
  bool loses = false;
  int deciding_face = -1;
  bool enclosed = false; ///< kept because its first face, beyond the entry, is met from behind
};

// Whether face f, met from behind as a ray's first hit, encloses the rays
// of `sweep`: only a face of the sweep's own place does (FreeSpaceSweep::
// place), so that what a map's hulls may fill never depends on the maps
// around it.
bool encloses(const SceneIndex& index, const FreeSpaceSweep& sweep, int f) {
  return sweep.place < 0 || index.prepared->face_place(f) == sweep.place;
}

// The probe's verdict on the sweep's ray through `point`: it starts on the
// base, runs to its first mesh hit (faces count as met only past the
// stand-off, as the probe's rays meet them) or the reach, and loses space
// when it lies deeper than tol inside the hull on the way - unless it first
// meets a face from behind (enclosed space). The hull is judged from the
// base itself, not from the stand-off (the strict definition's 0 < t): a hull entered
// and left within the stand-off takes free space too.
WitnessRay witness_ray(const SceneIndex& index, const FreeSpaceSweep& sweep, const HullInterior& interior,
                       const Eigen::Vector3d& point, std::vector<int>& scratch) {
  const Eigen::Vector3d& dir = sweep.direction;
  const Eigen::Vector3d base = ray_base(sweep, point);
  const std::optional<double> inside_from = ray_entry(interior.planes, base, dir);
  if (!inside_from) return {};
  const double enter = *inside_from;
  if (enter > sweep.reach) return {};
  // The first face at or before the entry ends the free space before the
  // hull (exactly: one met within tol beyond it would leave the ray up to
  // 2 tol deep, which is inside).
  const std::optional<MeshRayHit> hit = first_hit_past_stand_off(index, sweep, base, scratch);
  if (hit && hit->t <= enter) return {false, hit->face, false};
  if (hit && hit->from_behind && encloses(index, sweep, hit->face)) return {false, hit->face, true};
  return {true, -1, false};
}

// How a face settles a piece inside its shadow (grown as rays meet faces).
// Blocked: the face lies between the ray's stand-off and the hull for every
// ray. Enclosed: the face lies beyond the entry and the stand-off, met from
// behind, and no face met from the front stands between the entry and it
// (faces met from behind there enclose the space as well). The distances are affine over
// the piece, so its corners decide; where a condition holds over part of
// the piece only, the piece is cut where it changes.
struct Settling {
  bool settled = false;
  /// Unsettled by a face met from the front in part of the piece: the piece
  /// is cut along that face's shadow (inside and beside) in the storage's
  /// near_split, to judge each part.
  bool obstacle = false;
  std::optional<Plane>
      cut; ///< unsettled: cut the piece here (the face decides the side behind it) and judge both sides
};

Settling settle_by_face(const SceneIndex& index, const FreeSpaceSweep& sweep, const std::vector<Eigen::Vector3d>& piece,
                        int f, bool enclosed, SweepJudgeStorage& storage) {
  const MeshView& mesh = index.mesh();
  const double tol = index.tol();
  const Plane face{index.face_normals[f], index.face_normals[f].dot(mesh.positions[mesh.triangles[f][0]])};
  const double slope = face.normal.dot(sweep.direction);
  if (std::abs(slope) <= kParallelSine) return {};
  if (enclosed && slope <= 0.0) return {};
  const Affine to_entry = distance_to_point(sweep);
  const Affine to_face = distance_to_plane(sweep, face);
  const Affine stand_off{Eigen::Vector3d::Zero(), kRayStandOffInTolerances * tol};
  // Each condition is an affine margin that must not be negative anywhere
  // on the piece: its corners decide. Where it holds on part of the piece,
  // the piece is cut where the margin is zero.
  // Either way the face must lie past the stand-off, where rays meet faces:
  // a hull is judged from the surface on, so its entry may lie nearer.
  const std::array<Affine, 2> margins = enclosed ? std::array<Affine, 2>{to_face - to_entry, to_face - stand_off}
                                                 : std::array<Affine, 2>{to_face - stand_off, to_entry - to_face};
  for (const Affine& margin : margins) {
    const auto [lowest, highest] = range_over(margin, piece);
    if (lowest >= 0.0) continue;
    if (highest <= 0.0) return {};
    const std::optional<Plane> cut = splitting_cut(piece, margin, tol);
    if (!cut) continue; // negative only by rounding
    return {false, false, cut};
  }
  if (!enclosed) return {true, false, std::nullopt};
  double farthest = 0.0;
  for (const Eigen::Vector3d& p : piece) farthest = std::max(farthest, to_face(p));
  Aabb column;
  for (const Eigen::Vector3d& p : piece) {
    column.extend(p);
    column.extend(p + (farthest + sweep.start.signed_distance(p)) * sweep.direction);
  }
  std::vector<int>& near = storage.near;
  near.clear();
  index.face_tree.overlapping(grown(column, kFaceBoxMarginInTolerances * tol), near); // where shadows reach
  std::vector<Eigen::Vector3d>& triangle = storage.triangle;
  const Affine one_tol{Eigen::Vector3d::Zero(), tol};
  for (int g : near) {
    if (g == f || index.face_normals[g].dot(sweep.direction) >= 0.0) continue; // met from behind, or zero area
    triangle_corners(mesh, g, triangle);
    // Most faces near the column shadow none of the piece: one side of
    // their column tells, before any cutting.
    const ShadowColumn shadow = shadow_column(triangle, sweep.direction, tol);
    if (shadow.misses(piece)) continue;
    ShadowSplit& split = storage.near_split;
    split_by_shadow(piece, shadow, tol, split);
    if (split.inside.empty()) continue;
    // One running along the rays is not met (mesh_ray.h).
    const Plane other{index.face_normals[g], index.face_normals[g].dot(triangle[0])};
    if (std::abs(other.normal.dot(sweep.direction)) <= kParallelSine) continue;
    // g stands clear when it lies beyond f (by more than tol: one met
    // there with f is a front at the first hit), or before the entry
    // (there it blocks), over all of its part of the piece.
    const Affine to_other = distance_to_plane(sweep, other);
    const Affine beyond = to_other - to_face - one_tol, before = to_entry - to_other;
    const auto [beyond_low, beyond_high] = range_over(beyond, split.inside);
    const auto [before_low, before_high] = range_over(before, split.inside);
    // Clear as well where the margin is negative only by rounding.
    const auto clear = [&](const Affine& margin, double low, double high) {
      return low > 0.0 || (high > 0.0 && !splitting_cut(split.inside, margin, tol));
    };
    if (clear(beyond, beyond_low, beyond_high) || clear(before, before_low, before_high)) continue;
    // g shadows part of the piece: cut along its shadow first.
    if (!split.beside.empty()) return {false, true, std::nullopt};
    // g shadows it all, clear of it in part: cut where that changes.
    if (beyond_high > 0.0)
      if (const std::optional<Plane> cut = splitting_cut(split.inside, beyond, tol)) return {false, false, cut};
    if (before_high > 0.0)
      if (const std::optional<Plane> cut = splitting_cut(split.inside, before, tol)) return {false, false, cut};
    return {}; // between the entry and f everywhere: not enclosed by f
  }
  return {true, false, std::nullopt};
}

// Judges regions exactly, piece by piece: each piece's middle ray names the
// face that keeps it (met before the hull, or met from behind beyond it);
// inside that face's shadow the face settles every ray at once (the
// distances are affine), and the rest is cut into pieces judged the same
// way. A piece not settled within the budget counts as losing space:
// conservative, never optimistic. Pieces wait on an explicit stack, taken in
// the order a recursive judge would take them: a region cut a thousand times
// must not cost a thousand stack frames.
class RegionJudge {
public:
  RegionJudge(const SceneIndex& index, const FreeSpaceSweep& sweep, const HullInterior& interior,
              SweepJudgeStorage& storage)
      : index_(index), sweep_(sweep), interior_(interior), storage_(storage), pending_(storage.pending) {}

  bool loses_space(const std::vector<Eigen::Vector3d>& region) {
    pending_.clear();
    pending_.push_back({region, -1, false});
    while (!pending_.empty()) {
      Piece work = std::move(pending_.back());
      pending_.pop_back();
      const bool loses = work.settling_face >= 0 ? !settles(work.corners, work.settling_face, work.enclosed)
                                                 : piece_loses_space(work.corners);
      if (loses) return true;
    }
    return false;
  }

private:
  using Piece = SweepJudgeStorage::Piece;

  // Whether `region` loses space by its own rays; the pieces it is cut into
  // wait on the stack, the part the deciding face settles first.
  bool piece_loses_space(const std::vector<Eigen::Vector3d>& region) {
    // A piece of no area holds no ray apart from its neighbours'.
    const double tol = index_.tol();
    if (negligible(region, tol)) return false;
    if (--budget_ < 0) return true;
    std::vector<int>& faces = storage_.faces;
    WitnessRay ray = witness_ray(index_, sweep_, interior_, centroid_of(region), faces);
    if (ray.loses) return !piece_loss_allowed(index_, sweep_, interior_, region, faces);
    if (ray.deciding_face < 0) {
      // The middle ray misses the interior (a piece where the sweep only
      // grazes it): its corners' rays, pulled in a little, tell.
      const Eigen::Vector3d middle = centroid_of(region);
      for (const Eigen::Vector3d& corner : region) {
        ray = witness_ray(index_, sweep_, interior_, corner + kWitnessInset * (middle - corner), faces);
        if (ray.loses) return !piece_loss_allowed(index_, sweep_, interior_, region, faces);
        if (ray.deciding_face >= 0) break;
      }
      if (ray.deciding_face < 0) return false;
    }
    std::vector<Eigen::Vector3d>& triangle = storage_.triangle;
    triangle_corners(index_.mesh(), ray.deciding_face, triangle);
    ShadowSplit& split = storage_.split;
    split_by_shadow(region, shadow_column(triangle, sweep_.direction, tol), tol, split);
    for (auto piece = split.beside.rbegin(); piece != split.beside.rend(); ++piece)
      pending_.push_back({std::move(*piece), -1, false});
    if (split.inside.size() >= 3) pending_.push_back({std::move(split.inside), ray.deciding_face, ray.enclosed});
    return false;
  }

  // Whether face f settles every ray through `piece` (inside its shadow),
  // or cuts it into pieces (left on the stack) that will be judged; false
  // when it can do neither.
  bool settles(const std::vector<Eigen::Vector3d>& piece, int f, bool enclosed) {
    const Settling settling = settle_by_face(index_, sweep_, piece, f, enclosed, storage_);
    if (settling.settled) return true;
    if (settling.cut) {
      const Plane& cut = *settling.cut;
      std::vector<Eigen::Vector3d> decided = clip_polygon(piece, cut, 0.0);
      std::vector<Eigen::Vector3d> rest = clip_polygon(piece, cut.flipped(), 0.0);
      // A cut that leaves the piece whole would come back here.
      if (decided.size() < 3 || rest.size() < 3) return false;
      pending_.push_back({std::move(rest), -1, false});
      pending_.push_back({std::move(decided), -1, false});
      return true;
    }
    if (settling.obstacle) {
      ShadowSplit& split = storage_.near_split;
      pending_.push_back({std::move(split.inside), -1, false});
      for (auto part = split.beside.rbegin(); part != split.beside.rend(); ++part)
        pending_.push_back({std::move(*part), -1, false});
      return true;
    }
    return false;
  }

  const SceneIndex& index_;
  const FreeSpaceSweep& sweep_;
  const HullInterior& interior_;
  SweepJudgeStorage& storage_;
  std::vector<Piece>& pending_;
  int budget_ = kMaxJudgedPieces;
};

} // namespace

bool region_loses_space(const SceneIndex& index, const FreeSpaceSweep& sweep, const HullInterior& interior,
                        const std::vector<Eigen::Vector3d>& region, SweepJudgeStorage& storage) {
  RegionJudge judge(index, sweep, interior, storage);
  return judge.loses_space(region);
}

} // namespace hullcover::detail
