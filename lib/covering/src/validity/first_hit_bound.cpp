#include "validity/first_hit_bound.h"

#include "validity/mesh_ray.h"
#include "validity/shadow_pieces.h"
#include "validity/shadow_pieces.h"

#include "hullcover/geometry/planar_hull.h"
#include "hullcover/geometry/tolerances.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>
#include <optional>

namespace hullcover::detail {
namespace {

// The bound of first_hit_bound, piece by piece, on an explicit stack (as
// RegionJudge) so that a thousand cuts cost no stack depth.
class FirstHitBound {
public:
  /// Rays stand off by `stand_off` and pass faces they run along within
  /// `parallel_tol` (scene units); they meet faces within index.tol().
  FirstHitBound(const SceneIndex& index, const FreeSpaceSweep& sweep, double stand_off, double parallel_tol,
                std::vector<int>& scratch)
      : index_(index), sweep_(sweep), stand_off_(stand_off), parallel_tol_(parallel_tol), scratch_(scratch) {}

  double over(const std::vector<Eigen::Vector3d>& region) {
    std::vector<std::vector<Eigen::Vector3d>> pending = {region};
    double farthest = 0.0;
    while (!pending.empty()) {
      std::vector<Eigen::Vector3d> piece = std::move(pending.back());
      pending.pop_back();
      farthest = std::max(farthest, bound_of_piece(piece, pending));
    }
    return farthest;
  }

private:
  // The farthest first hit over `region`'s own rays; the pieces still to
  // bound go on `pending`.
  double bound_of_piece(const std::vector<Eigen::Vector3d>& region,
                        std::vector<std::vector<Eigen::Vector3d>>& pending) {
    constexpr double kNone = std::numeric_limits<double>::infinity();
    const double tol = index_.tol();
    if (negligible(region, tol)) return 0.0;
    if (--budget_ < 0) return kNone;
    const std::optional<MeshRayHit> hit =
        first_mesh_hit(index_, ray_base(sweep_, centroid_of(region)), sweep_.direction, stand_off_,
                       index_.prepared->tolerance.diagonal, scratch_, parallel_tol_);
    if (!hit) return kNone;
    const MeshView& mesh = index_.mesh();
    std::vector<Eigen::Vector3d> triangle(3);
    triangle_corners(mesh, hit->face, triangle);
    ShadowSplit split = split_by_shadow(region, triangle, sweep_.direction, tol);
    double farthest = 0.0;
    if (!split.inside.empty()) {
      const Plane face{index_.face_normals[hit->face], index_.face_normals[hit->face].dot(triangle[0])};
      const Affine to_face = distance_to_plane(sweep_, face);
      const Affine past_stand_off = to_face - Affine{Eigen::Vector3d::Zero(), stand_off_};
      // The face bounds the rays that meet its plane past their start; the
      // others (it leans across the base) are cut off and bounded apart.
      if (const std::optional<Plane> cut = splitting_cut(split.inside, past_stand_off, tol)) {
        const std::vector<Eigen::Vector3d> met = clip_polygon(split.inside, *cut, 0.0);
        farthest = std::max(farthest, range_over(to_face, met).second);
        pending.push_back(clip_polygon(split.inside, cut->flipped(), 0.0));
      } else {
        farthest = std::max(farthest, range_over(to_face, split.inside).second);
      }
    }
    for (std::vector<Eigen::Vector3d>& piece : split.beside) pending.push_back(std::move(piece));
    return farthest;
  }

  const SceneIndex& index_;
  const FreeSpaceSweep& sweep_;
  double stand_off_;
  double parallel_tol_;
  std::vector<int>& scratch_;
  int budget_ = kMaxJudgedPieces;
};

// The rays of `sweep` first_hit_bound bounds: its base polygon, or for an
// opening (whose base is its edge) the strip `half_width` either side of
// the fan's plane, where its rays leave.
std::vector<Eigen::Vector3d> ray_bases(const FreeSpaceSweep& sweep, double half_width) {
  std::vector<Eigen::Vector3d> region = sweep.base;
  if (region.size() == 2) {
    const Eigen::Vector3d across = (region[1] - region[0]).cross(sweep.direction).normalized() * half_width;
    region = {region[0] - across, region[1] - across, region[1] + across, region[0] + across};
  }
  return region;
}

} // namespace

double first_hit_bound_over(const SceneIndex& index, const FreeSpaceSweep& sweep,
                            const std::vector<Eigen::Vector3d>& region, std::vector<int>& scratch) {
  FirstHitBound bound(index, sweep, kRayStandOffInTolerances * index.tol(), index.tol(), scratch);
  const double farthest = bound.over(region);
  // A ray meeting a face within tol of its plane's crossing still ends there.
  return farthest + index.tol();
}

double first_hit_bound(const SceneIndex& index, const FreeSpaceSweep& sweep, std::vector<int>& scratch) {
  return first_hit_bound_over(index, sweep, ray_bases(sweep, index.tol()), scratch);
}

double first_hit_bound_in_every_view(const SceneIndex& finest, const FreeSpaceSweep& sweep, double coarsest_tol,
                                     std::vector<int>& scratch) {
  // Each ray's first hit in any view is a face this following meets too
  // (it meets faces within the finest margin, stands off and passes
  // faces it runs along as the coarsest does), not nearer.
  FirstHitBound bound(finest, sweep, kRayStandOffInTolerances * coarsest_tol, coarsest_tol, scratch);
  return bound.over(ray_bases(sweep, coarsest_tol)) + coarsest_tol;
}

} // namespace hullcover::detail
