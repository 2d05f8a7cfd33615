#include "bench_report.h"

#include "hullcover/geometry/atomic_file.h"

#include <cstdio>
#include <sstream>

namespace hullcover::app::bench {
namespace {

std::string format(const char* pattern, double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, x);
  return buffer;
}

// CSV quoting: a field with a comma or a quote is quoted, quotes doubled.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// "1,234" for counts people compare at a glance.
std::string grouped(long long n) {
  std::string digits = std::to_string(n < 0 ? -n : n), out;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return (n < 0 ? "-" : "") + out;
}

std::string speedup(const QueryTiming& t) { return format("%.2fx", t.speedup()); }

} // namespace

const BenchRow* exact_row_of(const std::vector<BenchRow>& rows, const std::string& scene) {
  for (const BenchRow& r : rows)
    if (r.scene == scene && r.agent_radius == 0.0 && r.max_deviation == 0.0) return &r;
  return nullptr;
}

std::optional<double> hull_change_percent(const std::vector<BenchRow>& rows, const BenchRow& row) {
  const BenchRow* exact = exact_row_of(rows, row.scene);
  if (!exact || exact->hulls == 0) return std::nullopt;
  return 100.0 * (static_cast<double>(row.hulls) / static_cast<double>(exact->hulls) - 1.0);
}

Status write_bench_csv(const std::vector<BenchRow>& rows, const std::string& path) {
  std::ostringstream out;
  out << "scene,setting,agent_radius,max_deviation,max_deviation_percent_of_diagonal,tolerance,diagonal,faces,"
         "decompose_s,hulls,hull_change_vs_exact_percent,hulls_per_face,facets_per_hull,vertices_per_hull,hcw_bytes,"
         "capsule_radius,capsule_half_height,touches_hull_us,touches_triangle_us,touches_speedup,contacts_hull_us,"
         "contacts_triangle_us,contacts_speedup,contacts_speedup_vs_exact,ray_hull_us,ray_triangle_us,ray_speedup,"
         "audit_s,clean,findings,front_rays,front_lost,opening_rays,opening_lost,max_lost_depth,max_lost_deviation,"
         "centre_rays,reach_lost,undecided,proxies,missed_contacts,false_contacts,coverage_percent,reach,slop,"
         "reachable_centres,sinking_centres,deepest_sinking,touching_poses,contacts_lost\n";
  out.precision(9);
  for (const BenchRow& r : rows) {
    const std::optional<double> change = hull_change_percent(rows, r);
    const BenchRow* exact = exact_row_of(rows, r.scene);
    const double exact_contacts = exact ? exact->queries.contacts.speedup() : 0.0;
    out << csv_field(r.scene) << ',' << csv_field(r.setting) << ',' << r.agent_radius << ',' << r.max_deviation << ','
        << r.max_deviation_percent << ',' << r.tolerance << ',' << r.diagonal << ',' << r.faces << ','
        << r.decompose_seconds << ',' << r.hulls << ',' << (change ? std::to_string(*change) : std::string()) << ','
        << r.hulls_per_face << ',' << r.facets_per_hull << ',' << r.vertices_per_hull << ',' << r.runtime_bytes << ','
        << r.query_radius << ',' << r.query_half_height << ',' << r.queries.touches.hull_us << ','
        << r.queries.touches.triangle_us << ',' << r.queries.touches.speedup() << ',' << r.queries.contacts.hull_us
        << ',' << r.queries.contacts.triangle_us << ',' << r.queries.contacts.speedup() << ','
        << (exact_contacts > 0.0 ? std::to_string(r.queries.contacts.speedup() / exact_contacts) : std::string()) << ','
        << r.queries.ray.hull_us << ',' << r.queries.ray.triangle_us << ',' << r.queries.ray.speedup() << ','
        << r.audit_seconds << ',' << (r.clean ? "yes" : "no") << ',' << csv_field(r.findings) << ',' << r.front_rays
        << ',' << r.front_lost << ',' << r.opening_rays << ',' << r.opening_lost << ',' << r.max_lost_depth << ','
        << r.max_lost_deviation << ',' << r.centre_rays << ',' << r.reach_lost << ',' << r.undecided << ',' << r.proxies
        << ',' << r.missed_contacts << ',' << r.false_contacts << ',' << r.coverage_percent << ','
        << (r.reach.empty() ? kExactReach : r.reach) << ',' << r.slop << ',' << r.reachable_centres << ',' << r.sinking
        << ',' << r.deepest_sinking << ',' << r.touching_poses << ',' << r.contacts_lost << '\n';
  }
  return write_file_atomically(path, out.str());
}

namespace {

// The audit's columns of a movement covering's row: the exact covering's
// ray, allowance and coverage figures do not apply to it.
std::string movement_audit_cells(const BenchRow& r) {
  return "- | - | - | - | - | " + grouped(r.reachable_centres) + ", " + grouped(r.sinking) +
         format(" (deepest %.3g", r.deepest_sinking) + format(", slop %.3g), ", r.slop) + grouped(r.contacts_lost) +
         " of " + grouped(r.touching_poses);
}

std::string exact_audit_cells(const BenchRow& r) {
  return grouped(r.front_lost + r.opening_lost) + ", " + format("%.3g", r.max_lost_depth) + " | " +
         (r.max_deviation > 0.0 ? format("%.3g", r.max_lost_deviation) + format(" (E %.3g)", r.max_deviation)
                                : std::string("-")) +
         " | " + (r.agent_radius > 0.0 ? grouped(r.reach_lost) : std::string("-")) + " | " +
         grouped(r.missed_contacts) + ", " + grouped(r.false_contacts) + " | " + format("%.2f%%", r.coverage_percent) +
         " | -";
}

} // namespace

std::string bench_markdown(const std::vector<BenchRow>& rows) {
  std::ostringstream out;
  out << "| scene | setting | decompose | hulls (vs exact) | hulls/face | facets, vertices/hull | .hcw | yes/no | "
         "contacts | ray | strict lost rays, deepest | farthest lost from mesh | reach lost | missed, false | "
         "coverage | movement: reachable centres, sinking past the slop, lost contacts | audit |\n"
         "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|---|\n";
  for (const BenchRow& r : rows) {
    const std::optional<double> change = hull_change_percent(rows, r);
    out << "| " << r.scene << " | " << r.setting << " | " << format("%.1f s", r.decompose_seconds) << " | "
        << grouped(r.hulls) << (change && r.setting != "exact" ? format(" (%+.0f%%)", *change) : std::string()) << " | "
        << format("%.3f", r.hulls_per_face) << " | " << format("%.1f", r.facets_per_hull) << ", "
        << format("%.1f", r.vertices_per_hull) << " | " << format("%.0f KB", r.runtime_bytes / 1024.0) << " | "
        << speedup(r.queries.touches) << " | " << speedup(r.queries.contacts) << " | " << speedup(r.queries.ray)
        << " | " << (r.reach.empty() ? exact_audit_cells(r) : movement_audit_cells(r)) << " | "
        << (r.clean ? "CLEAN" : "**" + r.findings + "**") << " |\n";
  }
  out << "\nSpeed-ups are triangles / hulls (TriangleWorld over HullWorld) per query, on the same capsule poses near "
         "the surfaces, timed side by side in one process. Strict lost rays are reported under an allowance, not "
         "judged: the allowance audit judges it (farthest lost point <= E + tol, no ball of the agent radius clear of "
         "the mesh reaching into a hull). A movement covering (walk, fly) keeps no rays: its ray speed-up is timed "
         "but promises nothing, and the movement audit judges it (no reachable centre sinking deeper than the slop, "
         "no touching pose losing its contact).\n";
  return out.str();
}

Status write_bench_markdown(const std::vector<BenchRow>& rows, const std::string& path) {
  return write_file_atomically(path, bench_markdown(rows));
}

} // namespace hullcover::app::bench
