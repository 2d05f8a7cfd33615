#pragma once
// A mesh built in a test, prepared and indexed as the validity checks see
// it (scene_index.h is private to lib/covering: only the covering tests, which
// have its folder on their include path, use this header).

#include "scene_index.h"

#include "hullcover/mesh/prepared_mesh.h"

#include <gtest/gtest.h>

#include <memory>
#include <optional>

namespace hullcover::test {

/// The prepared mesh and its index (the index refers to the prepared mesh,
/// so both live together, behind a pointer that does not move).
struct IndexedScene {
  PreparedMesh prepared;
  SceneIndex index;
};

/// Prepares `mesh` at `tolerance` (default: the scene's) and indexes it with
/// `bars`; records a test failure when preparing fails.
inline std::unique_ptr<IndexedScene> index_scene(const Mesh& mesh, std::optional<double> tolerance,
                                                 const BarOptions& bars) {
  auto out = std::make_unique<IndexedScene>();
  Result<PreparedMesh> prepared = prepare_mesh(mesh, tolerance);
  EXPECT_TRUE(prepared.ok()) << prepared.status().message();
  if (prepared.ok()) out->prepared = std::move(prepared).value();
  out->index = build_scene_index(out->prepared, bars);
  return out;
}

} // namespace hullcover::test
