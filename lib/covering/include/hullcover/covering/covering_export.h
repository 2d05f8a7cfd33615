#pragma once
/// \file covering_export.h
/// Writing a `Covering`: OBJ for viewers and engines, JSON for tools.

#include "hullcover/covering/covering_types.h"
#include "hullcover/geometry/status.h"

#include <nlohmann/json.hpp>

#include <string>

namespace hullcover {

/// Writes one `o hull_<i>` group per hull: its vertices and its facets as
/// polygons, counter-clockwise seen from outside (1-based OBJ indices).
/// A flat hull (thickness 0) is written as its front polygon only.
/// Fails with `unwritable_file`.
Status write_covering_obj(const Covering& covering, const std::string& path);

/// The JSON sidecar: per hull the faces covered, vertex and facet counts,
/// volume, planar flag and prism thickness, material; totals; the options
/// and tolerance used; timing and rejection counts.
nlohmann::json covering_json(const Covering& covering);

/// Writes `covering_json` (plus `extra` keys merged at the top level) to
/// `path`. Fails with `unwritable_file`.
Status write_covering_json(const Covering& covering, const nlohmann::json& extra, const std::string& path);

} // namespace hullcover
