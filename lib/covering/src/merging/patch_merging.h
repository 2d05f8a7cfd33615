#pragma once
// Greedy patch merging (paper 4, 4.2): internal to the decomposer.

#include "hullcover/covering/convex_hull_3d.h"
#include "hullcover/covering/decompose_options.h"
#include "hullcover/covering/merge_cells.h"
#include "validity/validity_conditions.h"
#include "validity/scene_index.h"

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace hullcover::detail {

/// A set of faces that will become one hull.
struct Patch {
  std::vector<int> faces;
  std::vector<int> hull_vertices;      ///< mesh vertex ids of its hull's corners
  std::vector<Plane> face_planes;      ///< distinct planes of its faces, outward
  std::map<int, double> shared_length; ///< neighbour patch -> length of the edges they share
  double area = 0.0;
  double boundary_length = 0.0;
  Eigen::Vector3d area_vector = Eigen::Vector3d::Zero(); ///< sum of face normals x areas
  bool planar = true;
  std::optional<ConvexPolytope> solid; ///< the hull, when not planar
  int material = 0;
  int version = 0;
  long changed_at = 0;           ///< PatchMerger::changes_ when it last changed
  long dissolve_failed_at = -1;  ///< PatchMerger::changes_ when dissolving it last failed
  int dissolve_failed_face = -1; ///< the face that then found no patch to go to
  bool alive = true;
};

/// Two face planes closer than this in normal direction (1 - cos) count as
/// one plane in Patch::face_planes (with offsets within tol).
double scene_same_plane_gap(const SceneIndex& index);

/// Adds `p` to `planes` unless one of them is the same plane.
void add_plane(std::vector<Plane>& planes, const Plane& p, double cosine_gap, double tol);

/// The positions of mesh vertices `ids`, in order.
std::vector<Eigen::Vector3d> positions_of(const MeshView& mesh, const std::vector<int>& ids);

/// The mesh vertices the faces use, ascending, once each: all of a
/// planar patch's points, corners or not, which its polygon's plane must
/// stay near.
std::vector<int> vertices_of_faces(const MeshView& mesh, const std::vector<int>& faces);

/// Length of the edge from corner `corner` of triangle `face` to the next.
double face_edge_length(const MeshView& mesh, int face, int corner);

/// Condition 2 both ways: each patch's face planes have the other's hull
/// vertices behind them (within tol). Cheap, and needs no hull. Always true
/// with an allowance (SceneIndex::has_allowance): a face may then lie inside
/// its hull where the exact conditions prove its front space harmless.
bool patches_support_each_other(const SceneIndex& index, const Patch& a, const Patch& b);

/// Inverse compactness of the union of two patches sharing `shared` length
/// of boundary: B / sqrt(A) (0 for a closed union).
double merged_patch_cost(const Patch& a, const Patch& b, double shared);

/// Runs the merging of one cell's faces to the end and returns the
/// surviving patches. Patch ids are local to the cell (0 .. its face
/// count - 1, the i-th starting as its i-th face alone); faces of other
/// cells belong to no patch, so no pair, near pair or dissolving crosses a
/// cell's border. Mergers of different cells share only the read-only
/// scene index and cell layout: they may run on different threads.
class PatchMerger {
public:
  /// `near_merge_distance`: see DecomposeOptions (resolved; 0 = the
  /// paper's pass alone). `cells` and `index` must outlive the merger.
  PatchMerger(const SceneIndex& index, const DecomposeOptions& options, double near_merge_distance,
              const CellLayout& cells, int cell, CoveringStatistics& statistics);

  /// The seam pass, over cell `seam_cell` of `seams` (an island, or every
  /// face): starts from `patches`, the patches the cells kept there (patch i from cell
  /// `cell_of_patch[i]`), and merges pairs sharing an edge across a cell
  /// border, then whatever pairs those merges open, until none is left
  /// (run_seams). No near merges or dissolving: those stay within cells.
  PatchMerger(const SceneIndex& index, const DecomposeOptions& options, const CellLayout& seams, int seam_cell,
              std::vector<Patch> patches, std::vector<int> cell_of_patch, CoveringStatistics& statistics);

  /// The seam pass (see the constructor above).
  void run_seams();

  /// Whether every patch loaded by the constructor above (a cell's result
  /// from an earlier bake, its faces unchanged) still passes the checks its
  /// last merge passed, against THIS scene: an edit elsewhere can put a face
  /// inside a kept hull, or open space a kept hull now takes. The polygon
  /// of a planar patch must be covered by faces on its own (stricter than
  /// the merge, which leaned on its two parts). Single faces need no check.
  /// `which[p]` false skips patch p (an empty `which` checks them all).
  /// Returns the first failure found, else `valid`.
  Validity recheck_patches(const std::vector<char>& which = {});

  /// Merges until no mergeable pair is left: the paper's pass, then near
  /// merges (near_patch_merging.cpp) and dissolving (patch_dissolving.cpp),
  /// and the paper's pass again, while they change anything.
  void run();

  const std::vector<Patch>& patches() const { return patches_; }
  bool in_patch(int face, int patch) const { return patch_of(face) == patch; }
  /// The patch holding face `f`, -1 for a face of another cell.
  int patch_of(int f) const { return cells_.cell_of_face[f] == cell_ ? face_patch_[cells_.slot_in_cell[f]] : -1; }

private:
  struct Candidate {
    Validity validity = Validity::valid;
    std::vector<int> hull_vertices;
    bool planar = false;
    std::optional<ConvexPolytope> solid;
  };

  Candidate evaluate(int a, int b);
  /// Face `f` alone, as the merging starts.
  Patch single_face_patch(int f) const;
  /// Boundary and shared lengths of every patch, from its faces.
  void recount_shared_edges();
  /// Each patch's bounding box grown by half the near-merge distance
  /// (empty for dead patches): boxes that overlap are within that distance.
  std::vector<Aabb> near_boxes() const;
  /// Whether face `f` comes within the near-merge distance of a face of
  /// patch `q` (nearest points of the triangles, not boxes: the same pairs
  /// however the scene is turned; boxes only pick the candidates).
  bool face_near_patch(int f, int q) const;
  /// Keeps of `patches` (distinct and ascending, none holding f) those
  /// face_near_patch finds near face `f`, in the same order.
  void keep_patches_near_face(int f, std::vector<int>& patches) const;
  /// Whether patches `a` and `b` come within the near-merge distance.
  bool patches_near(int a, int b) const;
  /// Queues every pair of patches sharing an edge of which one changed
  /// after `changed_after` (a value of changes_; -1: every pair).
  void push_neighbour_pairs(long changed_after);
  /// Empties every patch it can into the patches around its faces; returns
  /// how many were emptied.
  int dissolve_patches();
  /// Moves each face of patch `h` into a patch across one of its edges or
  /// within the near-merge distance of it (`near_tree`: patch boxes grown by
  /// half that distance, to find candidates), the first that stays valid;
  /// when one face finds none, puts everything back and returns false.
  /// `lone`: as in face_fits.
  bool dissolve(int h, const AabbTree& near_tree, int lone);
  /// The candidate for face `f` joining patch `q`, if valid; patch slot
  /// `lone` holds the face alone (single_face_patch) meanwhile.
  std::optional<Candidate> face_fits(int f, int q, int lone);
  /// Moves face `f` into patch `q` whose union with it is `candidate`;
  /// patch slot `lone` holds the face alone.
  void move_face(int f, int q, int lone, Candidate&& candidate);
  /// The patches face `f` of patch `h` may move to: across its edges, the
  /// longest shared first, then those within the near-merge distance
  /// (candidates from `near_tree`).
  std::vector<int> receivers_of(int f, int h, const AabbTree& near_tree) const;
  /// Exact mode: condition 4 of a flat polygon for a solid hull of patches
  /// a and b (`ids` their hull corners' mesh vertex ids) no wider than
  /// kThinHullSlabInTolerances tol across one of its facets.
  Validity check_thin_hull(int a, int b, const ConvexPolytope& hull, const std::vector<int>& ids);
  /// hull(base + other) grown from base's known hull, when other adds few
  /// points; nothing when that does not apply or fails (then Qhull runs).
  std::optional<ConvexPolytope> grow_known_hull(const Patch& base, const Patch& other);
  /// Beyond this many new points a rebuild is as cheap as growing.
  static constexpr int kMostPointsToAddIncrementally = 6;
  void merge(int a, int b, Candidate&& candidate);
  /// Queues the pair at its cost (shared length 0 for a near pair).
  void push_pair(int a, int b);
  /// Takes pairs off the queue until it is empty.
  void run_pairs();
  /// Queues every pair of patches sharing no edge whose boxes, grown by half
  /// the near-merge distance, overlap, whose faces come within that distance
  /// (patches_near), and that pass condition 2, unless listed before as
  /// they are; returns how many.
  int push_near_pairs();

  struct QueueEntry {
    double cost;
    int a, b;
    int version_a, version_b;
    bool operator>(const QueueEntry& o) const {
      if (cost != o.cost) return cost > o.cost;
      if (a != o.a) return a > o.a;
      return b > o.b;
    }
  };

  /// The patch entry of face `f`, which must be in this cell.
  int& patch_entry(int f) { return face_patch_[cells_.slot_in_cell[f]]; }

  const SceneIndex& index_;
  const DecomposeOptions& options_;
  const CellLayout& cells_;
  int cell_;
  CoveringStatistics& statistics_;
  std::vector<Patch> patches_;
  std::vector<int> face_patch_;   // per face of the cell (by CellLayout::slot_in_cell)
  std::vector<QueueEntry> queue_; // a min-heap by QueueEntry::operator>
  ConvexHullBuilder hull_builder_;
  RecentRejections recent_rejections_; // judged first in each candidate's exact checks
  std::vector<int> scratch_;
  double near_merge_distance_;
  /// changes_ when push_near_pairs last listed pairs; -1 before the first.
  /// A pair of which one patch changed since was never listed as it is now
  /// (push_near_pairs), so no set of the pairs tried is kept: on a dense
  /// cell it grew to tens of millions of entries, gigabytes, and never
  /// turned a pair away.
  long near_pairs_listed_at_ = -1;
  long changes_ = 0;               // counts changes to patches, for Patch::changed_at
  std::vector<int> cell_of_patch_; // seam pass: the cell each starting patch came from
};

} // namespace hullcover::detail
