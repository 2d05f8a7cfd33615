#include "audit_report_html.h"

#include "scene_picture.h"

#include "hullcover/geometry/atomic_file.h"

#include <algorithm>
#include <cstdio>

namespace hullcover::app::render {
namespace {

// A marker's ball is as large as the depth lost there, but no larger than
// this fraction of the scene's diagonal: one deep place must not hide the
// scene.
constexpr double kMaxMarkerFraction = 0.03;
// A place with no depth (a ray the audit could not decide) still needs a
// ball to be seen: this fraction of the diagonal.
constexpr double kUndecidedMarkerFraction = 0.01;
constexpr ImageSize kPictureSize{960, 720};
// The cut-away from above shows lost places inside closed rooms that the
// oblique view hides behind the back walls.
constexpr ViewAngles kTopView{0.0, 90.0};

std::string escaped(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  return out;
}

std::string base64(const std::string& bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const size_t left = std::min<size_t>(3, bytes.size() - i);
    unsigned group = 0;
    for (size_t k = 0; k < 3; ++k) group = (group << 8) | (k < left ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for (size_t k = 0; k < 4; ++k) out += k <= left ? kAlphabet[(group >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

std::string point_text(const Eigen::Vector3d& p) {
  return "(" + number(p.x()) + ", " + number(p.y()) + ", " + number(p.z()) + ")";
}

// A JSON value as HTML: objects as two-column tables, arrays of plain
// values on one line, other arrays as numbered lists; null as a dash.
void append_json(std::string& out, const nlohmann::json& value) {
  if (value.is_object()) {
    out += "<table class=\"figures\">";
    for (const auto& [key, item] : value.items()) {
      out += "<tr><th>" + escaped(key) + "</th><td>";
      append_json(out, item);
      out += "</td></tr>";
    }
    out += "</table>";
  } else if (value.is_array()) {
    const bool plain =
        std::none_of(value.begin(), value.end(), [](const nlohmann::json& v) { return v.is_structured(); });
    if (value.empty())
      out += "none";
    else if (plain) {
      for (size_t i = 0; i < value.size(); ++i) {
        if (i > 0) out += ", ";
        append_json(out, value[i]);
      }
    } else {
      out += "<ol>";
      for (const nlohmann::json& item : value) {
        out += "<li>";
        append_json(out, item);
        out += "</li>";
      }
      out += "</ol>";
    }
  } else if (value.is_null()) {
    out += "&mdash;";
  } else if (value.is_string()) {
    out += escaped(value.get<std::string>());
  } else if (value.is_number_float()) {
    out += number(value.get<double>());
  } else {
    out += escaped(value.dump());
  }
}

constexpr const char* kStyle =
    "body{font-family:sans-serif;margin:0 auto;max-width:1100px;padding:16px;color:#202124;background:#fff}"
    "#verdict{color:#fff;font-size:44px;font-weight:bold;padding:28px 32px;border-radius:10px;margin:8px 0 16px}"
    "#verdict .why{font-size:18px;font-weight:normal;margin-top:6px}"
    "table{border-collapse:collapse;margin:2px 0}th,td{border:1px solid #dadce0;padding:3px 8px;text-align:left;"
    "vertical-align:top;font-size:13px}th{background:#f1f3f4;font-weight:600}"
    "figure{margin:12px 0}img{max-width:100%;border:1px solid #dadce0}figcaption{font-size:13px;color:#5f6368}"
    "code{font-size:13px}";

Status picture(std::string& out, const PictureContent& content, const PictureOptions& options, const std::string& alt,
               const std::string& caption) {
  Result<std::string> png = scene_picture_png(content, options);
  if (!png.ok()) return png.status();
  out += "<figure><img alt=\"" + escaped(alt) + "\" width=\"" + std::to_string(options.size.width) + "\" height=\"" +
         std::to_string(options.size.height) + "\" src=\"data:image/png;base64," + base64(png.value()) +
         "\"><figcaption>" + escaped(caption) + "</figcaption></figure>\n";
  return Status::success();
}

void append_places_table(std::string& out, const std::vector<LostSpacePlace>& places) {
  if (places.empty()) {
    out += "<p>The audit located no lost space.</p>\n";
    return;
  }
  out +=
      "<table id=\"places\"><tr><th>#</th><th>found by</th><th>point</th><th>depth or distance</th>"
      "<th>hull</th><th>face</th></tr>";
  for (size_t i = 0; i < places.size(); ++i) {
    const LostSpacePlace& p = places[i];
    out += "<tr><td>" + std::to_string(i + 1) + "</td><td>" + escaped(p.kind) + "</td><td>" + point_text(p.point) +
           "</td><td>" + (p.hull >= 0 ? number(p.depth) : std::string("&mdash;")) + "</td><td>" +
           (p.hull >= 0 ? std::to_string(p.hull) : std::string("&mdash;")) + "</td><td>" +
           (p.face >= 0 ? std::to_string(p.face) : std::string("&mdash;")) + "</td></tr>";
  }
  out += "</table>\n";
}

} // namespace

std::vector<LostSpacePlace> lost_space_places(const validate::AuditReport& report) {
  std::vector<LostSpacePlace> places;
  const auto add = [&](const std::string& kind, const Eigen::Vector3d& point, double depth, int hull, int face) {
    if (hull < 0) return;
    const bool seen = std::any_of(places.begin(), places.end(),
                                  [&](const LostSpacePlace& p) { return p.point == point && p.hull == hull; });
    if (!seen) places.push_back({kind, point, depth, hull, face});
  };
  const validate::ProbeReport& probe = report.probe;
  for (const validate::LostPlace& p : probe.worst)
    add(p.opening ? "opening ray (deepest in its hull)" : "front ray (deepest in its hull)", p.point, p.depth, p.hull,
        p.face);
  add("front rays' deepest", probe.front.deepest.point, probe.front.deepest.depth, probe.front.deepest.hull,
      probe.front.deepest.face);
  add("opening rays' deepest", probe.opening.deepest.point, probe.opening.deepest.depth, probe.opening.deepest.hull,
      probe.opening.deepest.face);
  const validate::AllowanceReport& a = probe.allowance;
  add("farthest lost point from the mesh (distance)", a.farthest_point, a.max_lost_deviation, a.farthest_hull,
      a.farthest_face);
  add("deepest reachable ball (centre)", a.deepest_reach.centre, a.deepest_reach.depth, a.deepest_reach.hull,
      a.deepest_reach.face);
  // Undecided is a violation with no hull to name: the place it was given up.
  if (a.undecided > 0 && a.first_undecided.face >= 0)
    places.push_back(
        {"first ray out of evaluations (undecided)", a.first_undecided.point, 0.0, -1, a.first_undecided.face});
  const validate::FalseContactPlace& f = report.behaviour.deepest_false;
  add("deepest false contact", f.point, f.depth, f.hull, f.face);
  return places;
}

std::string audit_verdict(const validate::AuditReport& report) {
  if (report.clean()) return "CLEAN";
  std::string verdict = "VIOLATION: ";
  for (size_t i = 0; i < report.findings.size(); ++i)
    verdict += (i > 0 ? ", " : "") + std::string(validate::audit_finding_name(report.findings[i]));
  return verdict;
}

Result<std::string> audit_report_html(const AuditHtmlInput& input) {
  if (input.scene == nullptr || input.hulls == nullptr || input.report == nullptr)
    return Status{StatusCode::invalid_argument, "the HTML report needs the scene, the hulls and the audit"};
  try {
    const validate::AuditReport& report = *input.report;
    const bool allowance = report.probe.allowance.options.any();
    const std::string verdict = audit_verdict(report);
    const std::string why = report.clean()
                                ? (allowance ? "nothing taken beyond the allowance" : "no accessible space lost")
                                : (allowance ? "more taken than the allowance" : "accessible space lost");
    const std::vector<LostSpacePlace> places = lost_space_places(report);

    std::string out =
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>hullcover audit: " + escaped(verdict) +
        "</title><style>" + kStyle + "</style></head><body>\n";
    out += "<div id=\"verdict\" class=\"" + std::string(report.clean() ? "clean" : "violation") +
           "\" style=\"background:" + (report.clean() ? kCleanBannerColour : kViolationBannerColour) + "\">" +
           escaped(verdict) + "<div class=\"why\">" + escaped(why) + "</div></div>\n";
    out += "<p>Hulls <code>" + escaped(input.hulls_path) + "</code> (" + std::to_string(report.hull_count) +
           ") against the scene <code>" + escaped(input.mesh_path) + "</code> (" +
           std::to_string(input.scene->triangles.size()) + " faces).</p>\n";

    PictureContent content;
    content.scene = input.scene;
    content.hulls = input.hulls;
    PictureOptions options;
    options.size = kPictureSize;
    options.up = input.up;
    out += "<h2>The scene and its hulls</h2>\n";
    if (Status s = picture(out, content, options, "the scene and its hulls",
                           "Each hull in a colour of its own over the scene's faces (grey); oblique view.");
        !s.ok())
      return s;

    const double diagonal = referenced_bounding_box(*input.scene).diagonal();
    for (size_t i = 0; i < places.size(); ++i) { // numbered as the table's rows
      const double radius = places[i].hull >= 0 ? std::min(places[i].depth, kMaxMarkerFraction * diagonal)
                                                : kUndecidedMarkerFraction * diagonal;
      content.markers.push_back({places[i].point, radius, Marker{}.colour, std::to_string(i + 1)});
    }
    content.pale_hulls = true;
    bool any_undecided = false;
    for (const LostSpacePlace& p : places) {
      if (p.hull >= 0) content.highlighted.push_back(p.hull);
      any_undecided |= p.hull < 0;
    }
    options.cut = true;
    out += "<h2>Lost space</h2>\n";
    const std::string undecided_size =
        any_undecided ? "; " + number(100.0 * kUndecidedMarkerFraction) + "% where a ray was undecided" : "";
    const std::string marked =
        places.empty() ? "No place was located: nothing is marked."
                       : std::to_string(places.size()) + (places.size() == 1 ? " located place" : " located places") +
                             " in red, numbered as in the table below (ball radius: the depth lost there, at most " +
                             number(100.0 * kMaxMarkerFraction) + "% of the scene's diagonal" + undecided_size +
                             "); the hulls holding them in full colour.";
    if (Status s = picture(out, content, options, "lost space, cut away", "Cut away, other hulls pale. " + marked);
        !s.ok())
      return s;
    options.view = kTopView;
    if (Status s = picture(out, content, options, "lost space from above", "From above, roofs cut away. " + marked);
        !s.ok())
      return s;
    append_places_table(out, places);

    out += "<h2>Figures</h2>\n";
    append_json(out, input.figures);
    out += "\n</body></html>\n";
    return out;
  } catch (const std::exception& e) { // out of memory, or a figure of an unexpected type
    return Status{StatusCode::internal_error, std::string("could not write the HTML report: ") + e.what()};
  }
}

Status write_audit_report_html(const std::string& path, const AuditHtmlInput& input) {
  Result<std::string> html = audit_report_html(input);
  if (!html.ok()) return Status{html.status().code(), path + ": " + html.status().message()};
  return write_file_atomically(path, html.value());
}

} // namespace hullcover::app::render
