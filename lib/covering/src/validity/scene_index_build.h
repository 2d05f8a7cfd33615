#pragma once
// Building the scene index (scene_index.h), internal to the decomposer:
// the bars, the element trees, and in exact mode how far each face's and
// open edge's sweeps of free space reach before they first meet a face
// (first_hit_bound.h), which needs the index's own look-ups. Apart from
// scene_index.h so that the look-ups do not depend on the sweeps' bounds.

#include "validity/scene_index.h"

#include <vector>

namespace hullcover {

/// What bars guard.
struct BarOptions {
  /// Half-length of each bar, scene units (> 0), unless
  /// `half_length_of_island` is given.
  double half_length = 1.0;
  /// Also put bars on edges between faces of different materials (one per
  /// face), so hulls keep materials apart (paper 4.3).
  bool material_boundaries = false;
  /// `exact`: sheets along whole edges, on boundary AND fold edges (the rim
  /// of a double-sided sheet), and the checks of exact_conditions.h.
  ValidityMode mode = ValidityMode::paper;
  /// Exact mode: how far free space is kept, scene units (> 0); the
  /// decomposer passes a length beyond which no hull can lie when no cap is
  /// asked for (uncapped_free_space_reach).
  double free_space_reach = 1.0;
  /// How far outside the scene's bounding box a hull may reach (a prism
  /// extrudes up to its cap behind a face); sweeps are indexed only within
  /// the box grown by this, since no hull lies beyond it.
  double hull_margin = 0.0;
  /// Free space hulls may take beyond exact mode (loss_allowance.h), scene
  /// units, 0 for none: out of reach of balls of this radius...
  double agent_radius = 0.0;
  /// ... or within this distance of the mesh.
  double max_deviation = 0.0;
  /// Where hulls can be, when known more closely than the scene's box grown
  /// by `hull_margin`: boxes (already grown by the margin) such that every
  /// hull lies within one of them. The decomposer passes each island's box
  /// grown by the margin (its patches never span islands); sweeps are then
  /// indexed only where they cross one, so a wall's outward sweep across a
  /// world of far-apart maps is not met by every hull check on its way.
  /// Empty: the scene's box grown by `hull_margin`.
  std::vector<Aabb> hull_zones = {};
  /// When not empty, per island (mesh_islands.h numbering): the half-length
  /// of its faces' bars (exact mode's default: a multiple of each island's
  /// own tolerance), in place of `half_length`.
  std::vector<double> half_length_of_island = {};
  /// Threads that find how far the sweeps reach (0: every core); the index
  /// does not depend on it.
  int threads = 1;
};

/// Builds the index: face normals and areas, bars on every boundary edge
/// (exact mode: sheets on every boundary and fold edge; and material
/// boundaries when asked), and the four trees; each face's sweeps at its
/// island's tolerance. O(n log n).
SceneIndexData build_scene_index(const PreparedSceneView& prepared, const BarOptions& bars);

} // namespace hullcover
