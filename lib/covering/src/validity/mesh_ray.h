#pragma once
/// \file mesh_ray.h
/// The first mesh faces a ray meets, as the accessible-space probe of
/// the strict definition (docs/definitions-and-proofs.md) sees them: a ray that first meets the BACK of a face
/// runs through enclosed space.

#include "validity/scene_index.h"

#include <optional>

namespace hullcover {

/// Where a ray first meets the mesh.
struct MeshRayHit {
  double t = 0.0;           ///< distance along the ray, scene units
  int face = -1;            ///< a face met there
  bool from_behind = false; ///< every face met there (within tol) is met from its back: enclosed space
};

/// The first face the ray `origin + t dir` (unit `dir`) meets for t in
/// [min_t, max_t], a face counting where the ray crosses its plane within
/// the triangle with its edges pushed out by tol, and within its box grown
/// by kFaceBoxMarginInTolerances x tol (past a sharp corner the pushed edges
/// reach further).
/// Faces met within tol of the first hit all decide `from_behind`: one met
/// from the front among them (a ceiling coincident with the floor above)
/// makes the ray end on a front, as the strict definition (docs/definitions-and-proofs.md) says.
/// Nothing when the ray meets no face; faces the ray runs along
/// (|normal.dir| x (max_t - min_t) <= tol) are not met.
std::optional<MeshRayHit> first_mesh_hit(const SceneIndex& index, const Eigen::Vector3d& origin,
                                         const Eigen::Vector3d& dir, double min_t, double max_t,
                                         std::vector<int>& scratch);

/// As above, but faces the ray runs along are told by `parallel_tol`
/// (scene units, >= index.tol()) in place of tol: the hits of a ray as no
/// view of a tolerance up to parallel_tol misses them (scene_change.h).
std::optional<MeshRayHit> first_mesh_hit(const SceneIndex& index, const Eigen::Vector3d& origin,
                                         const Eigen::Vector3d& dir, double min_t, double max_t,
                                         std::vector<int>& scratch, double parallel_tol);

} // namespace hullcover
