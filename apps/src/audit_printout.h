#pragma once
// The audit's report as text on stdout: the verdict line, then the rays,
// the re-check, the proxies and any allowance, as `hullcover audit` prints
// them. Shared by the audit and demo commands.

#include "hullcover/mesh/prepared_mesh.h"
#include "hullcover/validate/audit.h"

#include <string>

namespace hullcover::app {

/// Prints `report` on `hulls_label` (a file name, shown on the verdict line)
/// against the scene `prepared`.
void print_audit(const std::string& hulls_label, const PreparedMesh& prepared, const validate::AuditReport& report);

} // namespace hullcover::app
