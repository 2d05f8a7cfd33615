#pragma once
/// \file covering_hulls.h
/// The adapter from the decomposer's output to the runtime: a Covering's
/// hulls as RuntimeHulls, or a HullWorld built from them. It lives in its own
/// target, hullcover::bvh_covering, so the runtime (hullcover::bvh) links no
/// part of the decomposer; a game server loads a runtime file instead.

#include "hullcover/bvh/hull_world.h"
#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/covering/covering_types.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace hullcover::bvh {

/// The runtime form of every hull of a covering, in its order.
std::vector<RuntimeHull> runtime_hulls(const Covering& covering);

/// The runtime file's section of each hull: its cell (CoveringHull::cell),
/// so a server can stream a world cell by cell (streamed_world.h).
std::vector<std::uint32_t> runtime_sections(const Covering& covering);

/// Writes the covering's runtime file, each hull in its cell's section.
/// Fails as write_runtime_file does.
[[nodiscard]] Status write_covering_runtime_file(const Covering& covering, const std::string& path);

/// A HullWorld of a covering's hulls, in its order (hull i of the covering
/// is hull i in every query result). Fails as HullWorld::build does.
Result<std::shared_ptr<const HullWorld>> build_hull_world(const Covering& covering);

} // namespace hullcover::bvh
