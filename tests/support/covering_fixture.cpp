#include "covering_fixture.h"

#include "temp_dir.h"

#include "hullcover/covering/covering_export.h"
#include "hullcover/mesh/scene_builder.h"

#include <Eigen/Geometry>

#include <algorithm>

namespace hullcover::test {

int Decomposed::hull_of_face(int f) const {
  for (size_t h = 0; h < covering.hulls.size(); ++h)
    if (std::binary_search(covering.hulls[h].faces.begin(), covering.hulls[h].faces.end(), f))
      return static_cast<int>(h);
  return -1;
}

std::optional<Decomposed> decompose_and_check(const Mesh& mesh, const DecomposeOptions& options,
                                              std::optional<double> tolerance) {
  Result<PreparedMesh> prepared = prepare_mesh(mesh, tolerance);
  if (!prepared.ok()) {
    ADD_FAILURE() << prepared.status().message();
    return std::nullopt;
  }
  Result<Covering> covering = decompose(prepared.value(), options);
  if (!covering.ok()) {
    ADD_FAILURE() << covering.status().message();
    return std::nullopt;
  }
  // With an allowance, faces may lie inside their hulls (README, "Agent-exact coverings").
  const validate::CheckReport report =
      validate::check_covering_independently(prepared.value(), covering.value(), has_allowance(options));
  // Exact mode guards open edges with sheets (whole-edge bars whose touching
  // rule differs at the tolerance) and the openings themselves, not with the
  // paper's midpoint bars: those are re-checked for paper mode only.
  const bool paper = options.conditions == ValidityMode::paper;
  EXPECT_EQ(paper ? report.total() : report.violations(), 0) << report.summary();
  return Decomposed{std::move(prepared).value(), std::move(covering).value()};
}

void add_quad_facing(Mesh& mesh, const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                     const Eigen::Vector3d& d, const Eigen::Vector3d& front, int material) {
  if ((b - a).cross(c - a).dot(front) >= 0.0)
    add_quad(mesh, a, b, c, d, material);
  else
    add_quad(mesh, a, d, c, b, material);
}

std::unique_ptr<StagedDecomposition> staged_decomposition(const Mesh& mesh, const DecomposeOptions& options) {
  Result<PreparedMesh> prepared = prepare_mesh(mesh, std::nullopt);
  if (!prepared.ok()) return nullptr;
  Result<std::unique_ptr<StagedDecomposition>> s = StagedDecomposition::prepare(std::move(prepared).value(), options);
  return s.ok() ? std::move(s).value() : nullptr;
}

std::string covering_obj_bytes(const Covering& covering) {
  TempDir dir;
  const std::string path = dir.path("hulls.obj");
  EXPECT_TRUE(write_covering_obj(covering, path).ok());
  return slurp(path);
}

Mesh grooved_floor() {
  using V = Eigen::Vector3d;
  Mesh m;
  const double d = kGrooveDepth;
  add_quad_facing(m, V(0, 0, 0), V(1, 0, 0), V(1, 0, 1), V(0, 0, 1), V(0, 1, 0));
  add_quad_facing(m, V(1, 0, 0), V(1.1, -d, 0), V(1.1, -d, 1), V(1, 0, 1), V(d, 0.1, 0));
  add_quad_facing(m, V(1.1, -d, 0), V(1.2, 0, 0), V(1.2, 0, 1), V(1.1, -d, 1), V(-d, 0.1, 0));
  add_quad_facing(m, V(1.2, 0, 0), V(2.2, 0, 0), V(2.2, 0, 1), V(1.2, 0, 1), V(0, 1, 0));
  return m;
}

DecomposeOptions options_with_small_cells(const Mesh& mesh) {
  DecomposeOptions o;
  o.cell_size = prepare_mesh(mesh, std::nullopt).value().tolerance.local_extent / 6.0;
  return o;
}

std::string finding_names(const std::vector<validate::AuditFinding>& findings) {
  std::string s;
  for (validate::AuditFinding f : findings) s += std::string(validate::audit_finding_name(f)) + " ";
  return s;
}

bool has_finding(const validate::AuditReport& report, validate::AuditFinding finding) {
  return std::find(report.findings.begin(), report.findings.end(), finding) != report.findings.end();
}

} // namespace hullcover::test
