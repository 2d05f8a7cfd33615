#pragma once
/// \file merge_cells.h
/// Cells: the decomposer merges patches only within a cell, and merges
/// cells apart (in parallel, DecomposeOptions::threads). Every candidate
/// hull is still checked against the WHOLE scene (the free-space definition
/// has no distance cap), so each hull a cell keeps is valid on its own, and
/// a union of valid hulls whose patches cover every face is a valid
/// covering (docs/definitions-and-proofs.md, "Cells"). Cells cost hulls
/// only where a patch would have grown across a border.
///
/// Layout: every island (hullcover/mesh/mesh_islands.h) has its own grid of
/// cubes of side S, centred on its box's centre, so a map's cells are the
/// same alone or in a world, moved or turned by multiples of 90 degrees
/// (the automatic layout cuts a crowded cube into the cubes of half its
/// side, which the same grid halved lays out alike). A face belongs to the
/// cell holding its centroid.

#include "hullcover/mesh/mesh_islands.h"
#include "prepared_scene_view.h"

#include <optional>
#include <vector>

namespace hullcover {

/// The automatic layout's target: an island with more faces than this is
/// cut into the coarsest centred grid (its longest side over a power of two,
/// up to 1024) whose occupied cells hold at most this many faces on average. Small enough that a large map gives both
/// cores several cells to share, large enough that borders cut few patches.
inline constexpr int kFacesPerAutomaticCell = 8192;

/// The automatic layout's bound on one cell: a cell of the grid above
/// holding more faces than this (a dense cluster of detail in a sparse map)
/// is cut into the eight cubes of half its side, and so on, until none does
/// or the cubes reach the finest grid tried. A cell's merging costs more
/// than its faces (its near pairs grow with the detail around each patch),
/// and the largest cell is what the other cores wait for: Red Eclipse's
/// absorption put 81,782 of its 112,905 faces in one cell.
inline constexpr int kMostFacesPerAutomaticCell = 2 * kFacesPerAutomaticCell;

/// Which cell each face is in.
struct CellLayout {
  /// Faces of each cell, ascending; cells ordered by island, then by grid
  /// position (x, then y, then z), a crowded cube's halves in its place, in
  /// the same order.
  std::vector<std::vector<int>> faces_of_cell;
  std::vector<int> cell_of_face;   ///< per face
  std::vector<int> slot_in_cell;   ///< per face: its index in its cell's list
  std::vector<int> island_of_cell; ///< per cell; -1 for the one cell of --cell-size 0 (every island)
  /// Per cell: how many times its cube was halved from the island's grid
  /// (0 but where the automatic layout cut a crowded cube). The default
  /// near-merge distance halves with it: where detail is that much denser,
  /// a patch meets as many others within half the reach.
  std::vector<int> cell_halvings;
  /// Cell side used per island, scene units (the grid's, before any crowded
  /// cube is halved); 0 where the island is one cell.
  std::vector<double> island_cell_size;
};

/// Lays out the cells of `prepared` (`islands` found on its mesh).
/// `cell_size`: unset for the automatic layout, 0 for one cell holding
/// every face, else the side of every island's cubes (> 0, finite). Never
/// fails for a prepared mesh; a cell is never empty.
CellLayout lay_out_cells(const PreparedSceneView& prepared, const IslandsView& islands,
                         std::optional<double> cell_size);

/// One cell per island (the seam pass's layout: no edge joins two islands).
CellLayout lay_out_islands(const PreparedSceneView& prepared, const IslandsView& islands);

} // namespace hullcover
