#pragma once
/// \file covering_hulls.h
/// The adapter from the decomposer's output to the runtime: a Covering's
/// hulls as RuntimeHulls, or a HullWorld built from them. It lives in its own
/// target, hullcover::bvh_covering, so the runtime (hullcover::bvh) links no
/// part of the decomposer; a game server loads a runtime file instead.

#include "hullcover/bvh/hull_world.h"
#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/covering/covering.h"

#include <memory>
#include <vector>

namespace hullcover::bvh {

/// The runtime form of every hull of a covering, in its order.
std::vector<RuntimeHull> runtime_hulls(const Covering& covering);

/// A HullWorld of a covering's hulls, in its order (hull i of the covering
/// is hull i in every query result). Fails as HullWorld::build does.
Result<std::shared_ptr<const HullWorld>> build_hull_world(const Covering& covering);

} // namespace hullcover::bvh
