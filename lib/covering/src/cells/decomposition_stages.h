#pragma once
// What every cell of a decomposition shares, internal to the decomposer:
// the resolved options and lengths, islands, cells, and the scene index
// with its views. Made by prepare_stages (cell_merging.h); read by every
// stage after it.

#include "hullcover/covering/covering_types.h"
#include "hullcover/covering/merge_cells.h"
#include "hullcover/mesh/mesh_islands.h"
#include "hullcover/mesh/tolerance.h"

#include "prepared_scene_view.h"
#include "validity/scene_index.h"

#include <memory>
#include <vector>

namespace hullcover::detail {

/// What the cells share. Views the arrays of the scene it was made for,
/// which must outlive it; a scene far from the origin is worked in a local
/// frame (local_frame.h), on a moved copy the stages own.
struct DecompositionStages {
  /// Works `scene` where it is.
  explicit DecompositionStages(const PreparedSceneView& scene) : prepared(scene), place_tolerance(prepared.tolerance) {}
  /// Works `local` (the scene moved by -origin), and owns it.
  DecompositionStages(std::unique_ptr<const PreparedMesh> local, const Eigen::Vector3d& origin)
      : local_scene(std::move(local)), frame_origin(origin), prepared(view_of(*local_scene)),
        place_tolerance(local_scene->tolerance) {}
  // The views in `island_index` refer to `index_data`: never copied or moved.
  DecompositionStages(const DecompositionStages&) = delete;
  DecompositionStages& operator=(const DecompositionStages&) = delete;
  /// The moved copy, when the scene is worked in a local frame.
  const std::unique_ptr<const PreparedMesh> local_scene;
  /// Where the local frame's origin lies in the scene's frame (zero: none);
  /// finish_stages moves the hulls back by it.
  const Eigen::Vector3d frame_origin = Eigen::Vector3d::Zero();
  /// The scene every stage works on (the local copy, when there is one).
  const PreparedSceneView prepared;
  /// The tolerance of each place, and where each island's zone is.
  const PlaceTolerance place_tolerance;
  /// Options and resolved lengths; no hulls yet. Statistics: faces, index
  /// time, islands, cells.
  Covering covering;
  CellLayout cells;
  /// Per island: the tolerance its cells, seam pass and hulls are checked
  /// at, scene units: its place's (hullcover/mesh/tolerance.h; its hulls stay
  /// out of every zone of a smaller one).
  std::vector<double> island_tolerance;
  /// What every check reads, built once...
  SceneIndexData index_data;
  /// ... and its views: per island, at the island's tolerance
  /// (Tolerance::island_lengths), then the whole scene's at the smallest.
  std::vector<SceneIndex> island_index;

  /// The view the checks of island `island` use; -1: the whole scene's (the
  /// one cell of --cell-size 0, which spans every island).
  const SceneIndex& index_of_island(int island) const {
    return island < 0 ? island_index.back() : island_index[island];
  }
  /// The view cell `cell` merges with.
  const SceneIndex& index_of_cell(int cell) const { return index_of_island(cells.island_of_cell[cell]); }
};

} // namespace hullcover::detail
