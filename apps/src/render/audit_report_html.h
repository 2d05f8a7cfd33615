#pragma once
// `hullcover audit --html`: the audit as one self-contained HTML file (no
// external resource: pictures are PNGs in data: URIs, the style is inline),
// for a reviewer with nothing but a browser. It holds the verdict in a
// banner (green CLEAN, red VIOLATION with the findings' names), every
// figure of the audit's JSON, and pictures drawn by scene_picture.h: the
// scene with its hulls, and the lost places as red balls (radius the depth
// lost there, never under kMinMarkerPixels) over pale, cut-away hulls.

#include "facet_painter.h"
#include "scene_camera.h"

#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/geometry/mesh.h"
#include "hullcover/geometry/status.h"
#include "hullcover/validate/audit.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace hullcover::app::render {

/// Banner colours, as CSS hex, chosen apart from every hull colour so a
/// reader (or a test looking at a screenshot) finds the verdict by colour.
inline constexpr const char* kCleanBannerColour = "#1e8e3e";
inline constexpr const char* kViolationBannerColour = "#c5221f";

/// Everything the report shows.
struct AuditHtmlInput {
  const Mesh* scene = nullptr;                          ///< the audited scene (required)
  const std::vector<bvh::RuntimeHull>* hulls = nullptr; ///< the audited hulls (required)
  const validate::AuditReport* report = nullptr;        ///< the audit (required)
  nlohmann::json figures;                               ///< the audit's figures as `--json` writes them: shown in full
  std::string mesh_path, hulls_path;
  UpAxis up = UpAxis::y; ///< the scene's up axis, for the pictures
};

/// One place the audit located lost space, for the pictures and the table.
struct LostSpacePlace {
  std::string kind; ///< which figure found it ("front rays", "opening rays", "false contact", ...)
  Eigen::Vector3d point = Eigen::Vector3d::Zero(); ///< scene coordinates
  double depth = 0.0;                              ///< how deep it lies in the hull, scene units (0 with no hull)
  int hull = -1;                                   ///< the hull it lies in; -1 where the audit gave up a ray undecided
  int face = -1;                                   ///< the face whose ray or proxy found it (-1 unknown)
};

/// Every located place of the report: the deepest lost point per hull, the
/// deepest of front and opening rays, the allowance's farthest point and
/// deepest reachable ball, the deepest false contact, the first ray the
/// allowance audit left undecided. Each place once.
std::vector<LostSpacePlace> lost_space_places(const validate::AuditReport& report);

/// "CLEAN", or "VIOLATION: " and the findings' names joined by ", ".
std::string audit_verdict(const validate::AuditReport& report);

/// The whole HTML document. Fails with `invalid_argument` when a required
/// input is missing, or with the pictures' failure.
[[nodiscard]] Result<std::string> audit_report_html(const AuditHtmlInput& input);

/// Writes the document to `path`, atomically; fails as audit_report_html
/// does, or with `unwritable_file` naming `path`.
[[nodiscard]] Status write_audit_report_html(const std::string& path, const AuditHtmlInput& input);

} // namespace hullcover::app::render
