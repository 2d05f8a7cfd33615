// Re-checking a cell's patches from an earlier bake against an edited scene
// (StagedDecomposition::still_valid): the same conditions a merge checks,
// applied to each finished patch as a whole.

#include "cells/cell_merging.h"
#include "cells/cell_result_bytes.h"
#include "validity/flat_polygon_cover.h"
#include "merging/patch_merging.h"

#include "hullcover/geometry/planar_hull.h"
#include "hullcover/geometry/tolerances.h"

#include <algorithm>

namespace hullcover::detail {
namespace {

std::vector<Eigen::Vector3d> face_corners(const MeshView& mesh, int face) {
  std::vector<Eigen::Vector3d> corners;
  for (int k = 0; k < 3; ++k) corners.push_back(mesh.positions[mesh.triangles[face][k]]);
  return corners;
}

} // namespace

Validity PatchMerger::recheck_patches(const std::vector<char>& which) {
  const MeshView& mesh = index_.mesh();
  const double tol = index_.tol();
  for (int p = 0; p < static_cast<int>(patches_.size()); ++p) {
    const Patch& patch = patches_[p];
    if (!patch.alive || patch.faces.size() < 2 || (!which.empty() && !which[p])) continue;
    const auto in_patch = [&](int f) { return patch_of(f) == p; };
    Validity validity = Validity::valid;
    if (patch.planar) {
      const FlatPolygon polygon =
          make_flat_polygon(mesh.positions, vertices_of_faces(mesh, patch.faces), patch.area_vector.normalized(), tol);
      // Its own first two faces stand for the merge's two parts: covered
      // by themselves; the rest must be covered by faces of this scene.
      if (index_.mode == ValidityMode::exact)
        validity = check_polygon_covered(index_, polygon, face_corners(mesh, patch.faces[0]),
                                         face_corners(mesh, patch.faces[1]), scratch_, kRecheckSlabInTolerances);
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

bool cell_result_holds(const DecompositionStages& stages, int cell, const CellResult& result,
                       const std::function<bool(const Patch&, const PatchHull&)>& touched, std::string* why) {
  std::vector<char> which(result.patches.size(), 1);
  for (size_t p = 0; p < which.size(); ++p)
    if (touched) which[p] = touched(result.patches[p], result.hulls[p]);
  // No patch needs a look: no merger to build.
  if (std::find(which.begin(), which.end(), 1) == which.end()) return true;
  const auto refuse = [why](const std::string& reason) {
    if (why) *why = reason;
    return false;
  };
  // The patches as a seam pass would load them: each face in its patch.
  CoveringStatistics statistics;
  const SceneIndex& index = stages.index_of_cell(cell);
  std::vector<int> origins(result.patches.size(), cell);
  PatchMerger merger(index, stages.covering.options, stages.cells, cell, result.patches, std::move(origins),
                     statistics);
  const Validity validity = merger.recheck_patches(which);
  if (validity != Validity::valid)
    return refuse(std::string("a kept hull is no longer valid: ") + validity_name(validity));
  ConvexHullBuilder builder;
  std::vector<int> scratch;
  for (size_t p = 0; p < which.size(); ++p)
    if (which[p] &&
        !same_hull(make_patch_hull(stages, index, merger, static_cast<int>(p), builder, scratch), result.hulls[p]))
      return refuse("a kept hull would be made otherwise in this scene");
  return true;
}

bool cell_bytes_hold(const DecompositionStages& stages, int cell, const std::string& bytes,
                     const std::function<bool(const Patch&, const PatchHull&)>& touched, std::string* why) {
  Result<CellResult> read = cell_result_from_bytes(stages, cell, bytes);
  if (!read.ok()) {
    if (why) *why = read.status().message();
    return false;
  }
  return cell_result_holds(stages, cell, read.value(), touched, why);
}

} // namespace hullcover::detail
