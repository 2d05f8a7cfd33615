#pragma once
/// \file decompose_options.h
/// How to decompose (DecomposeOptions, with the defaults every option
/// takes) and what a decomposition counted (CoveringStatistics). Kept apart
/// from covering.h so the merging code, which reads both, does not depend
/// on the result type it feeds.

#include "hullcover/covering/validity.h"

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace hullcover {

/// Default bar half-length as a fraction of the bounding-box diagonal (the
/// value the prototype measured the paper with: docs/results/covering.md).
inline constexpr double kDefaultBarHalfLengthRelative = 0.1;
/// The audit's default probe distance as a fraction of the diagonal (the
/// decomposer itself keeps free space with no cap unless asked for one).
inline constexpr double kDefaultFreeSpaceReachRelative = 0.02;
/// Default distance of the near merges as a fraction of the diagonal: gaps
/// as wide as the audit's probe distance.
inline constexpr double kDefaultNearMergeRelative = kDefaultFreeSpaceReachRelative;
/// Default cap on prism thickness as a fraction of the diagonal.
inline constexpr double kDefaultPrismCapRelative = 0.01;
/// PhysX, Unity and Jolt reject convex shapes with more vertices.
inline constexpr int kDefaultMaxHullVertices = 255;
/// The smallest max_hull_triangles accepted: a box's 12 (no hull over a
/// quad's prism has fewer).
inline constexpr int kFewestTrianglesOfAHullLimit = 12;

/// Triangles of a convex polytope's facets once each is fanned: a facet of
/// k corners gives k - 2.
inline int triangles_of_facets(const std::vector<std::vector<int>>& facets) {
  int triangles = 0;
  for (const std::vector<int>& facet : facets) triangles += static_cast<int>(facet.size()) - 2;
  return triangles;
}
/// Triangles of the prism an engine export makes of a flat n-gon: two caps
/// of n - 2 and n sides of 2.
inline int triangles_of_prism(int corners) { return 4 * corners - 4; }

/// The order in which mergeable pairs are taken.
enum class MergeOrder {
  compact, ///< cheapest 1 / compactness first (the paper's method)
  random,  ///< pseudo-random, seeded (the paper's comparison)
};

/// How to decompose. Lengths are in scene units; unset ones take the
/// defaults named beside them (relative to the scene's bounding-box diagonal,
/// or to the tolerance).
struct DecomposeOptions {
  /// `exact` (default) keeps every condition of lib/covering/src/validity/exact_conditions.h too, so
  /// no free space is lost; `paper` applies the paper's four alone, so the
  /// cost of exactness stays measurable.
  ValidityMode conditions = ValidityMode::exact;
  /// Half-length of the boundary bars (> 0); default exact
  /// kExactBarHalfLengthInTolerances x tol, paper kDefaultBarHalfLengthRelative
  /// x diagonal.
  std::optional<double> bar_half_length;
  /// Exact mode: how far in front of faces and beyond open edges free space
  /// is kept, scene units (> 0). Unset (the default): no cap, as docs/definitions-and-proofs.md
  /// defines free space; a cap trades exactness for speed.
  std::optional<double> free_space_reach;
  /// Exact mode, relaxed for agents: hulls may also take free space that no
  /// ball of this radius touching no triangle reaches (README "Agent-exact
  /// coverings"), scene units, >= 0; unset or 0: exact. Spheres and
  /// capsules at least this wide then collide with the hulls exactly as with
  /// the triangles.
  std::optional<double> agent_radius;
  /// Exact mode, relaxed for props: hulls may also take free space within
  /// this distance of the mesh, scene units, >= 0; unset or 0: exact.
  /// With agent_radius as well, both hold: a hull takes only space no
  /// agent reaches that also lies within this distance of the mesh.
  std::optional<double> max_deviation;
  /// Cap on a planar patch's prism thickness (>= 0); default
  /// kDefaultPrismCapRelative x diagonal.
  std::optional<double> prism_thickness_cap;
  /// Near merges, after the paper's merging of patches that share an edge:
  /// patches sharing none whose faces come within this distance (nearest points),
  /// scene units, are tried as pairs too, under the same conditions; then
  /// the paper's pass resumes, until neither merges. >= 0, 0 = off; default
  /// exact kDefaultNearMergeRelative x diagonal, paper 0 (the paper's
  /// algorithm alone).
  std::optional<double> near_merge_distance;
  /// Dissolving, after the merging: a patch whose faces can each join
  /// another patch (across an edge or within the near-merge distance) under
  /// the same conditions is emptied into them; then merging resumes. Default
  /// exact on, paper off (the paper's algorithm alone).
  std::optional<bool> dissolve;
  MergeOrder order = MergeOrder::compact;
  std::uint64_t seed = 1; ///< for MergeOrder::random
  /// Merge this many times (>= 1): in `order` first, then in random orders
  /// seeded seed, seed + 1, ...; the covering with the fewest hulls is kept
  /// (the first of equals). Costs that many times the merging time.
  int order_tries = 1;
  bool keep_materials_apart = false;               ///< one material per hull, bars on material borders
  int max_hull_vertices = kDefaultMaxHullVertices; ///< >= 8 (a prism of a quad)
  /// Most triangles a hull may have once its facets are triangulated, >= 12
  /// (a box); a planar patch counts as the prism an engine export makes of
  /// it (4 n - 4 for an n-gon). Unity's convex MeshCollider takes 255.
  /// Unset: no limit beyond max_hull_vertices.
  std::optional<int> max_hull_triangles;
  /// Cells (hullcover/covering/merge_cells.h): patches merge only within a
  /// cell, while every hull is still checked against the whole scene.
  /// Scene units, >= 0. Unset: automatic, per island (a grid centred on
  /// each island, fine enough that its occupied cells hold
  /// kFacesPerAutomaticCell faces on average, a cube holding more than
  /// kMostFacesPerAutomaticCell cut into eighths; one cell for a smaller
  /// island). 0: one cell for the whole scene (no cells).
  std::optional<double> cell_size;
  /// Threads that merge cells at once (>= 0; 0 = every core). The covering
  /// does not depend on it: the same hulls in the same order for any count.
  int threads = 0;
  /// Called now and then with the fraction of work done (0..1); may be
  /// empty. Called from the merging threads, one call at a time.
  std::function<void(double)> progress;
};

/// Whether `options` let hulls take free space exact mode keeps (an agent
/// radius or a max deviation above 0).
inline bool has_allowance(const DecomposeOptions& options) {
  return options.agent_radius.value_or(0.0) > 0.0 || options.max_deviation.value_or(0.0) > 0.0;
}

/// Counts and timings of a decomposition.
struct CoveringStatistics {
  int faces = 0;
  int zero_area_faces_skipped = 0; ///< faces without a reliable normal (height <= tol): in no patch
  /// Faces no patch's hull covered within tol (thin ones, and faces a hull
  /// grown through a thin slab missed), each given a flat hull of its own:
  /// coverage, docs/definitions-and-proofs.md (face_coverage.h in the sources).
  int faces_given_flat_hulls = 0;
  int thin_faces_given_flat_hulls = 0; ///< of those, faces thinner than tol
  /// Faces no hull covers within tol and too thin for even a flat triangle
  /// (smallest angle's sine under kParallelSine); 0 on every scene measured.
  int faces_left_uncovered = 0;
  int merges = 0;
  int order_tries = 1;       ///< merging runs made; the statistics are the kept run's, times the total
  int kept_try = 0;          ///< which run was kept (0: the given order)
  int near_merges = 0;       ///< merges of patches sharing no edge (the near-merge pass)
  int dissolved_patches = 0; ///< patches emptied into others (dissolving)
  long candidates_tested = 0;
  std::array<long, kValidityCount> rejections{}; ///< by Validity
  long qhull_calls = 0;
  long incremental_hulls = 0;   ///< merge hulls grown from a known hull instead of rebuilt
  int prisms_made_flat = 0;     ///< planar hulls with thickness 0
  int solids_kept_as_grown = 0; ///< solid hulls output as validated during merging (Qhull's rebuild differed)
  double seconds_index = 0.0;
  double seconds_merging = 0.0; ///< wall time of the cells' merging (all threads) and the seam pass
  double seconds_output = 0.0;  ///< wall time of making the hulls (all threads)
  double seconds_seams = 0.0;   ///< wall time of the seam pass alone (part of seconds_merging)
  int seam_merges = 0;          ///< merges of patches across cell borders (the seam pass), part of `merges`
  int cells = 0;                ///< cells merged apart (merge_cells.h)
  int islands = 0;              ///< the scene's islands (hullcover/mesh/mesh_islands.h)
};

} // namespace hullcover
