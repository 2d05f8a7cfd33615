#pragma once
// The audit's figures as JSON: what `audit --json` writes, the HTML report
// shows and the Python module returns.

#include "hullcover/mesh/prepared_mesh.h"
#include "hullcover/validate/audit.h"

#include <nlohmann/json.hpp>

namespace hullcover::app {

/// Every figure of `report` (the scene's tolerance from `prepared`): verdict,
/// findings, ray tallies, re-check counts, allowance and behaviour figures.
nlohmann::json audit_report_json(const PreparedMesh& prepared, const validate::AuditReport& report);

} // namespace hullcover::app
