#pragma once
// What an edit changed since the cell cache's last bake, so a re-bake
// re-checks only the kept hulls the edit can reach (cell_cache.h).
//
// A hull's checks read (validity_conditions.h, exact_conditions.h) the
// vertices, edges, faces and bars near it, and the free-space sweeps that
// meet it, each ray followed to its first mesh hit (witness_rays.h: past
// the stand-off of the hull's view, so beyond the sweep's reach when that
// view's tolerance is coarser than the sweep's own, or a finer view passes
// between faces; first_hit_bound_in_every_view bounds how far).
// So an edit of faces C (those added and those removed) can change a check
// only if the hull lies near C (within the longest bar, plus the
// tolerances), or meets a sweep of this scene whose rays, followed as far
// as any view follows them, cross C: a sweep whose reach grew passes where its old blocker was,
// one whose reach shrank ends on a new face in C, and one whose rays run
// through C may be decided differently. A sweep that vanished (a removed
// face's, a closed edge's) or only shrank away from a hull tests it no more,
// which only relaxes a check made of such tests. Every other kept hull
// passes its checks as it did. (Its hull made anew may differ where such a
// relaxation frees room, a prism that could now be thicker: the kept one
// stays valid, and a re-bake that re-checks everything may then merge that
// cell again and differ.) A user's free-space cap is not such a bound (rays
// run on past it): with one, every kept hull is re-checked.
//
// Faces are told apart by a hash of their corners' exact bits, material,
// and every per-island length their checks use; a cell's bytes are known to
// have held against the last bake's scene by their checksum, recorded with
// it. An allowance (agent radius, max deviation) is judged by proofs that
// are not such a conjunction: with one, every kept hull is re-checked.
//
// Snapshot layout (integers little-endian, reals IEEE-754 binary64
// little-endian): magic "HCSCENE\0", u32 version, u64 settings hash, u32
// cells + per cell (u64 key, u64 FNV-1a-64 of its bytes), u32 faces + per
// face (u64 hash, 6 f64 box), u64 FNV-1a-64 of everything before it.

#include "hullcover/geometry/aabb_tree.h"
#include "hullcover/geometry/status.h"

#include "validity/free_space_sweep.h"
#include "merging/patch_hulls.h"

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace hullcover::detail {

struct DecompositionStages;

/// The last bake's scene, as the cell cache keeps it.
struct SceneSnapshot {
  std::uint64_t settings = 0; ///< hash of the options and scene-wide lengths
  /// Per cell key: FNV-1a-64 of the bytes that bake used for it.
  std::unordered_map<std::uint64_t, std::uint64_t> cell_checksums;
  std::vector<std::uint64_t> face_hashes; ///< per face: corners' bits, material, its island's lengths
  std::vector<Aabb> face_boxes;           ///< per face, scene units
};

/// Per face of this scene, the hash a snapshot records (corners' bits,
/// material, its island's lengths).
std::vector<std::uint64_t> face_hashes_of(const DecompositionStages& stages);

/// The snapshot of this bake: its settings, its faces (`face_hashes`, from
/// face_hashes_of), and per cell (index = cell) its key (cell_key) and the
/// bytes used.
std::string scene_snapshot_bytes(const DecompositionStages& stages, const std::vector<std::uint64_t>& face_hashes,
                                 const std::vector<std::uint64_t>& cell_keys, const std::vector<std::string>& cells);

/// Reads a snapshot. Fails with `unknown_format` (not one, another
/// version) or `unreadable_file` (truncated, checksum, bad values).
Result<SceneSnapshot> read_scene_snapshot(const std::string& bytes);

/// Where this scene differs from a snapshot's.
struct SceneChange {
  bool everything = true;             ///< no bound: every kept hull may be touched
  std::vector<Aabb> near_boxes;       ///< changed faces' boxes grown by how far a check looks around a hull
  AabbTree near_tree;                 ///< over `near_boxes`
  std::vector<FreeSpaceSweep> sweeps; ///< this scene's sweeps that cross a changed face
  AabbTree sweep_tree;                ///< over their boxes
  int changed_faces = 0;              ///< added plus removed
  double slack = 0.0;                 ///< scene units, added to every test
};

/// The change from `before` to this scene, whose faces hash to
/// `face_hashes` (face_hashes_of); `everything` when the settings differ, a
/// free-space cap or an allowance is set.
SceneChange scene_change_since(const DecompositionStages& stages, const std::vector<std::uint64_t>& face_hashes,
                               const SceneSnapshot& before);

/// Whether the checks of `patch` (and the making of its hull `made`) may
/// read something `change` changed.
bool patch_may_be_touched(const DecompositionStages& stages, const SceneChange& change, const Patch& patch,
                          const PatchHull& made);

} // namespace hullcover::detail
