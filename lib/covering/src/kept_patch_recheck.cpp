// Re-checking a cell's patches from an earlier bake against an edited scene
// (StagedDecomposition::still_valid): the same conditions a merge checks,
// applied to each finished patch as a whole.

#include "flat_polygon_cover.h"
#include "patch_merging.h"

#include "hullcover/geometry/planar_hull.h"
#include "hullcover/geometry/tolerances.h"

namespace hullcover::detail {
namespace {

std::vector<Eigen::Vector3d> face_corners(const Mesh& mesh, int face) {
  std::vector<Eigen::Vector3d> corners;
  for (int k = 0; k < 3; ++k) corners.push_back(mesh.positions[mesh.triangles[face][k]]);
  return corners;
}

} // namespace

Validity PatchMerger::recheck_patches() {
  const Mesh& mesh = index_.mesh();
  const double tol = index_.tol();
  for (int p = 0; p < static_cast<int>(patches_.size()); ++p) {
    const Patch& patch = patches_[p];
    if (!patch.alive || patch.faces.size() < 2) continue;
    const auto in_patch = [&](int f) { return patch_of(f) == p; };
    Validity validity = Validity::valid;
    if (patch.planar) {
      const FlatPolygon polygon =
          make_flat_polygon(mesh.positions, vertices_of_faces(mesh, patch.faces), patch.area_vector.normalized(), tol);
      // Its own first two faces stand for the merge's two parts: covered
      // by themselves; the rest must be covered by faces of this scene.
      if (index_.mode == ValidityMode::exact)
        validity = check_polygon_covered(index_, polygon, face_corners(mesh, patch.faces[0]),
                                         face_corners(mesh, patch.faces[1]), scratch_,
                                         kRecheckSlabInTolerances);
      if (validity == Validity::valid) validity = check_flat_polygon(index_, polygon, in_patch, scratch_);
    } else if (!patch.solid) {
      validity = Validity::hull_failed;
    } else {
      // A stored solid must still hold its own faces (within tol): the bytes
      // say so, this makes sure.
      for (int f : patch.faces)
        for (int k = 0; k < 3 && validity == Validity::valid; ++k)
          if (deepest_signed_distance(patch.solid->planes, mesh.positions[mesh.triangles[f][k]]) > tol)
            validity = Validity::face_not_on_hull;
      if (validity != Validity::valid) return validity;
      validity = check_solid_hull(index_, *patch.solid, scratch_);
      if (validity == Validity::valid) validity = check_thin_hull(p, p, *patch.solid, patch.hull_vertices);
    }
    if (validity != Validity::valid) return validity;
  }
  return Validity::valid;
}

} // namespace hullcover::detail
