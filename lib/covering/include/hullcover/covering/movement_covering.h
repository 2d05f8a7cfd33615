#pragma once
/// \file movement_covering.h
/// A covering for character movement: hulls that model only the space an
/// agent (a sphere, or an upright capsule) of radius r can occupy, each
/// agent sinking into them at most a slop E deeper than into the
/// triangles, and every face an agent can touch on or inside a hull.
/// Rays are not promised: a server that also needs hitscan keeps the exact
/// covering (covering.h) for rays. The definition, its proof and its
/// numbers: docs/definitions-and-proofs.md, "Movement coverings".

#include "hullcover/covering/covering_types.h"
#include "hullcover/covering/movement_options.h"
#include "hullcover/geometry/status.h"
#include "hullcover/mesh/prepared_mesh.h"

namespace hullcover {

/// A movement covering: the hulls, as a Covering (so every writer and the
/// runtime take it), and its own figures.
struct MovementCovering {
  Covering covering;
  MovementStatistics movement;
};

/// Decomposes `prepared` for agents as `options` says. Deterministic for
/// any thread count. Fails with `invalid_argument` for options out of range
/// or a seed where no agent fits, and with `limit_exceeded` when the reach
/// grid would exceed kMostReachCells or kMostReachCellsHeld.
Result<MovementCovering> decompose_for_movement(const PreparedMesh& prepared, const MovementOptions& options);

} // namespace hullcover
