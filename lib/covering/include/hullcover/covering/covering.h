#pragma once
/// \file covering.h
/// Convex hull covering of a scene: the paper's algorithm (sections 3-4)
/// and what it produces.
///
/// Every face starts as its own patch. Two patches sharing a manifold,
/// consistently oriented edge are mergeable when their union is valid
/// (lib/covering/src/validity/validity_conditions.h); the cheapest mergeable pair, cost = 1 /
/// compactness = boundary length / sqrt(area), is merged until none is
/// left. Beyond the paper, a near-merge pass then tries patches that share
/// no edge but lie close (DecomposeOptions::near_merge_distance). Planar
/// patches become prisms (lib/covering/src/validity/planar_prism.h).

#include "hullcover/covering/covering_types.h"
#include "hullcover/covering/decompose_options.h"
#include "hullcover/geometry/status.h"
#include "hullcover/mesh/prepared_mesh.h"

namespace hullcover {

/// Decomposes the prepared mesh, cell by cell (merge_cells.h) on
/// DecomposeOptions::threads threads. Deterministic: the same mesh and
/// options give the same hulls in the same order, whatever the thread count.
/// Fails with `invalid_argument` for options out of range.
Result<Covering> decompose(const PreparedMesh& prepared, const DecomposeOptions& options);

} // namespace hullcover
