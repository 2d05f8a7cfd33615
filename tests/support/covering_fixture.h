#pragma once
// Decomposes a mesh built in a test and re-checks the result independently.

#include "hullcover/validate/audit.h"
#include "hullcover/validate/validity_recheck.h"

#include "hullcover/covering/covering.h"
#include "hullcover/covering/staged_decomposition.h"
#include "hullcover/mesh/prepared_mesh.h"

#include <gtest/gtest.h>

#include <optional>
#include <random>
#include <string>

namespace hullcover::test {

using validate::point_inside_covering;
using validate::segment_hits_covering;

struct Decomposed {
  PreparedMesh prepared;
  Covering covering;

  /// Index of the hull covering face f (-1 if none).
  int hull_of_face(int f) const;
  double tol() const { return prepared.tolerance.length; }
};

/// Prepares and decomposes `mesh`; records a test failure (and returns
/// nothing) if either step fails or the independent check finds a violation.
std::optional<Decomposed> decompose_and_check(const Mesh& mesh, const DecomposeOptions& options = {},
                                              std::optional<double> tolerance = std::nullopt);

/// Appends triangle a-b-c (counter-clockwise seen from its front), material 0.
inline void add_triangle(Mesh& mesh, const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const int base = static_cast<int>(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), {a, b, c});
  mesh.triangles.emplace_back(base, base + 1, base + 2);
  mesh.material_ids.push_back(0);
}

/// A uniformly random unit vector.
inline Eigen::Vector3d random_unit(std::mt19937& rng) {
  std::normal_distribution<double> gauss(0.0, 1.0);
  return Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng)).normalized();
}

/// Options putting `mesh` in cells a sixth of its extent wide: several
/// cells, so stages, caches and re-bakes have cells to carry.
DecomposeOptions options_with_small_cells(const Mesh& mesh);

/// `mesh` prepared (default tolerance) and its stage 1 made; null when
/// either fails.
std::unique_ptr<StagedDecomposition> staged_decomposition(const Mesh& mesh, const DecomposeOptions& options);

/// The audit's findings by name, for failure messages.
std::string finding_names(const std::vector<validate::AuditFinding>& findings);

/// Whether the audit reported `finding`.
bool has_finding(const validate::AuditReport& report, validate::AuditFinding finding);

/// The covering as write_covering_obj writes it, byte for byte.
std::string covering_obj_bytes(const Covering& covering);

/// Appends quad a-b-c-d, wound so its front faces along `front`.
void add_quad_facing(Mesh& mesh, const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                     const Eigen::Vector3d& d, const Eigen::Vector3d& front, int material = 0);

/// Depth of grooved_floor()'s groove, scene units.
inline constexpr double kGrooveDepth = 0.05;

/// A floor strip (z in [0, 1]) with a V groove across it: flat x in [0, 1],
/// slopes down to (1.1, -kGrooveDepth) and up to (1.2, 0), flat x in
/// [1.2, 2.2]; every face looks up, out of the groove. The allowance tests'
/// scene: the groove is free space within a small distance of the mesh.
Mesh grooved_floor();

} // namespace hullcover::test
