#pragma once
/// \file movement_context.h
/// What the movement proofs read (movement_validity.h, within_slop.h): the
/// scene, its clearance, the reach grid and the agent. Shared read-only by
/// every merger.

#include "movement/reach_grid.h"
#include "movement/scene_clearance.h"

#include "hullcover/covering/movement_options.h"
#include "hullcover/geometry/mesh.h"

namespace hullcover::detail {

struct MovementContext {
  const Mesh& mesh;
  const SceneClearance& clearance;
  const ReachGrid& grid;
  const AgentShape& agent;
  double tol = 0.0; ///< the scene's tolerance (the largest place's): coincidence of faces and facets
};

} // namespace hullcover::detail
