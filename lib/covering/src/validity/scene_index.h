#pragma once
/// \file scene_index.h
/// Everything the validity conditions test a candidate hull against, for
/// the WHOLE mesh (paper section 3: checks run on the entire mesh, not the
/// patch's component): vertices, edges, faces and boundary constraint bars,
/// each in a bounding-volume tree.

#include "validity/free_space_sweep.h"
#include "hullcover/covering/validity.h"
#include "hullcover/geometry/aabb_tree.h"
#include "hullcover/geometry/mappable_array.h"
#include "prepared_scene_view.h"

#include <array>
#include <vector>

namespace hullcover {

/// A boundary constraint bar (paper 4.1, condition 3): the segment through
/// an open edge's midpoint along its face's unit normal, `bar_half_length`
/// to each side. In exact mode the bar is swept along the whole edge (a
/// *sheet*: the quad a, a + along, b + along, b), so the opening is guarded
/// at every point of the edge, not only at its midpoint.
struct BoundaryBar {
  Eigen::Vector3d a = Eigen::Vector3d::Zero();     ///< behind the face (at the edge's start for a sheet)
  Eigen::Vector3d b = Eigen::Vector3d::Zero();     ///< in front of the face
  Eigen::Vector3d along = Eigen::Vector3d::Zero(); ///< edge vector of a sheet; zero for a bar
  int edge = -1;                                   ///< the mesh edge it guards
  int face = -1;                                   ///< the face whose normal it follows

  bool is_sheet() const { return !along.isZero(); }
  /// Its outline: the segment a-b, or the sheet's four corners in order.
  std::vector<Eigen::Vector3d> outline() const;
};

/// What build_scene_index computes once per scene, for every view of it
/// (SceneIndex). Holds a reference to `prepared`, which must outlive it.
struct SceneIndexData {
  const PreparedSceneView* prepared = nullptr;
  ValidityMode mode = ValidityMode::paper;
  double free_space_reach = 0.0; ///< exact mode, scene units
  double agent_radius = 0.0;     ///< BarOptions::agent_radius
  double max_deviation = 0.0;    ///< BarOptions::max_deviation
  /// Per edge: the use (index into MeshConnectivity::edge_uses) of the face
  /// whose plane holds the opening beyond it (boundary and, in exact mode,
  /// fold edges), or -1 for an edge that is not open.
  MappableArray<int> open_edge_use;
  /// Unit front normal per face; zero for zero-area faces.
  MappableArray<Eigen::Vector3d> face_normals;
  /// Area per face, scene units squared.
  MappableArray<double> face_areas;
  MappableArray<BoundaryBar> bars;
  AabbTree vertex_tree; ///< over mesh vertices
  AabbTree edge_tree;   ///< over MeshConnectivity::edges
  AabbTree face_tree;   ///< over faces
  AabbTree bar_tree;    ///< over pieces of bars (long bars are split, so boxes stay small)
  /// Exact mode: over the boxes of the faces' front sweeps (the triangle
  /// swept along its normal by the reach), one per hull zone the sweep
  /// crosses (BarOptions::hull_zones), clipped to it; item i is face
  /// front_sweep_face[i] (a face may have several items). A hull can lose a
  /// face's front space only where its box meets one of that face's boxes.
  AabbTree front_sweep_tree;
  MappableArray<int> front_sweep_face;
  /// Exact mode, per face: how far its front sweep runs, scene units: the
  /// free-space reach, or less where every ray of it meets a face sooner
  /// (first_hit_bound, witness_rays.h). 0 for a face with no sweep.
  MappableArray<double> front_reach;
  /// Exact mode: the same for the openings beyond open edges; item i is
  /// edge opening_sweep_edge[i] (an edge may have several items).
  AabbTree opening_sweep_tree;
  MappableArray<int> opening_sweep_edge;
  /// Exact mode, per open edge and fan (free_space_sweep.h): how far that
  /// fan runs, as front_reach.
  MappableArray<std::array<double, kOpeningFans>> opening_reach;
  MappableArray<int> bar_of_piece; ///< bar index of each piece in bar_tree
};

/// The mesh as the validity checks see it, at one tolerance: a view of a
/// SceneIndexData (which must outlive it; fields as there). Every island
/// has its own tolerance (hullcover/mesh/tolerance.h), so the checks of one
/// island's patches run on a view at that island's; the data is shared.
struct SceneIndex {
  /// A view of `data` whose tests use `tolerance` (scene units, > 0), for
  /// patches no wider than `patch_extent` (scene units: an island's
  /// diagonal, or the largest island's for the whole scene).
  SceneIndex(const SceneIndexData& data, double tolerance, double patch_extent);
  SceneIndex(SceneIndexData&&, double, double) = delete; // would refer to a temporary

  const PreparedSceneView* prepared;
  ValidityMode mode;
  double free_space_reach;
  double agent_radius;
  double max_deviation;
  const MappableArray<int>& open_edge_use;
  const MappableArray<Eigen::Vector3d>& face_normals;
  const MappableArray<double>& face_areas;
  const MappableArray<BoundaryBar>& bars;
  const AabbTree& vertex_tree;
  const AabbTree& edge_tree;
  const AabbTree& face_tree;
  const AabbTree& bar_tree;
  const AabbTree& front_sweep_tree;
  const MappableArray<int>& front_sweep_face;
  const MappableArray<double>& front_reach;
  const AabbTree& opening_sweep_tree;
  const MappableArray<int>& opening_sweep_edge;
  const MappableArray<std::array<double, kOpeningFans>>& opening_reach;
  const MappableArray<int>& bar_of_piece;
  /// The place (hullcover/mesh/tolerance.h) whose hulls this view checks,
  /// or -1 for hulls that may span places (the one cell of --cell-size 0).
  /// Rays of that place are enclosed only by its own faces, as in the place
  /// alone (FreeSpaceSweep::place).
  int place = -1;

  /// Appends, once each and ascending, the bars with a piece overlapping `box`.
  void bars_overlapping(const Aabb& box, std::vector<int>& out) const;

  const MeshView& mesh() const { return prepared->mesh; }
  /// Whether hulls may take free space exact mode keeps (agent radius or
  /// max deviation set): the paper's conditions 1 and 2 then give way to
  /// the exact conditions' proofs (loss_allowance.h).
  bool has_allowance() const { return agent_radius > 0.0 || max_deviation > 0.0; }
  /// The tolerance of this view's tests, scene units.
  double tol() const { return tolerance_; }
  /// The same data seen at another tolerance (scene units, > 0).
  SceneIndex at_tolerance(double tolerance) const {
    SceneIndex view = *this;
    view.tolerance_ = tolerance;
    return view;
  }
  /// How far apart two faces of one patch can lie, scene units.
  double patch_extent() const { return patch_extent_; }

private:
  double tolerance_;
  double patch_extent_;
};

/// Bars are indexed in pieces no longer than the diagonal / this: a bar
/// is long (a tenth of the scene by default), and one long box per bar would
/// make every query visit most of the tree.
inline constexpr double kBarPiecesPerDiagonal = 64.0;

/// The free-space reach that amounts to no cap: longer than any segment from
/// a face to a point of a hull (hulls lie within the scene's box grown by
/// `hull_margin`), so every ray of free space is followed to the last hull.
double uncapped_free_space_reach(const PreparedSceneView& prepared, double hull_margin);

/// True for a fold edge: a manifold edge whose second face folds back onto
/// the first (its far corner within tol (the first face's island's) of the
/// first face's plane, normals opposite): the rim of a double-sided sheet,
/// as open as a boundary edge.
bool is_fold_edge(const PreparedSceneView& prepared, int edge);

} // namespace hullcover
