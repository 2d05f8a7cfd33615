#pragma once
// One cell of `hullcover bench`: a scene decomposed at one setting, its
// runtime file written, timed against the triangles and audited.

#include "bench_settings.h"
#include "query_timing.h"

#include "hullcover/bvh/triangle_world.h"
#include "hullcover/mesh/prepared_mesh.h"

#include <string>
#include <vector>

namespace hullcover::app::bench {

/// Everything measured for one scene at one setting.
struct BenchRow {
  std::string scene;                              ///< the file's name, without folders
  std::string setting;                            ///< Setting::label()
  double agent_radius = 0.0, max_deviation = 0.0; ///< resolved, scene units (0 = off)
  std::string reach;                              ///< "" (the exact covering), "walk" or "fly"
  double slop = 0.0;                              ///< movement coverings: resolved, scene units
  double max_deviation_percent = 0.0;             ///< max_deviation as % of the diagonal
  double tolerance = 0.0, diagonal = 0.0;         ///< scene units
  int faces = 0;
  // The covering.
  double decompose_seconds = 0.0; ///< decompose() alone, not the import
  long hulls = 0;
  double hulls_per_face = 0.0;
  double facets_per_hull = 0.0, vertices_per_hull = 0.0; ///< means
  long runtime_bytes = 0;                                ///< size of the .hcw written
  std::string runtime_path;
  // The runtime against the triangles, on the same poses.
  double query_radius = 0.0, query_half_height = 0.0; ///< the capsule, scene units
  QueryTimings queries;
  // The audit (hullcover audit on the .hcw, with the setting's allowance).
  double audit_seconds = 0.0;
  bool clean = false;
  std::string findings; ///< space-separated finding names; empty when clean
  long front_rays = 0, front_lost = 0, opening_rays = 0, opening_lost = 0; ///< strict definition
  double max_lost_depth = 0.0;          ///< strict definition: deepest lost point, scene units
  double max_lost_deviation = 0.0;      ///< farthest lost point from the mesh (allowance audit; 0 without one)
  long centre_rays = 0, reach_lost = 0; ///< agent radius only
  /// Agent radius: the allowance audit's undecided centres; a movement
  /// covering: hulls its decomposer refused as undecided.
  long long undecided = 0;
  long proxies = 0, missed_contacts = 0, false_contacts = 0; ///< false: deeper than tol (boxes included)
  double coverage_percent = 0.0; ///< of the mesh's area on or (with an allowance) inside a hull
  // Movement coverings: the movement audit (hullcover audit --agent-reach).
  long long reachable_centres = 0, sinking = 0, touching_poses = 0, contacts_lost = 0;
  double deepest_sinking = 0.0; ///< scene units; within the slop when clean
};

/// How every cell is run.
struct BenchRunOptions {
  std::string out_dir;        ///< where the .hcw files go (exists)
  int query_poses = 512;      ///< capsule poses (and rays) per scene
  double query_seconds = 0.2; ///< least time per query kind and world
};

/// Decomposes `prepared` at `setting`, writes `<out_dir>/<scene>.<setting>.hcw`,
/// times `poses` on its HullWorld against `triangles`, and audits the file
/// as `hullcover audit` does with the setting's allowance (a movement
/// covering: with its agent). Fails with the
/// first failing step's status (decompose's, the file's, the audit's).
[[nodiscard]] Result<BenchRow> bench_setting(const PreparedMesh& prepared, const SceneSpec& scene,
                                             const Setting& setting, const bvh::TriangleWorld& triangles,
                                             const QueryPoses& poses, const BenchRunOptions& options);

} // namespace hullcover::app::bench
