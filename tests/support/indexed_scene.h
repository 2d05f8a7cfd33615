#pragma once
// A mesh built in a test, prepared and indexed as the validity checks see
// it (scene_index.h is private to lib/covering: only the covering tests, which
// have its folder on their include path, use this header).

#include "prepared_scene_view.h"
#include "validity/scene_index_build.h"

#include <gtest/gtest.h>

#include <memory>
#include <optional>

namespace hullcover::test {

/// The prepared mesh, the decomposer's view of its arrays, its index and a view of it at the scene's smallest
/// tolerance (each refers to the one before, so all live together, behind a
/// pointer that does not move).
struct IndexedScene {
  IndexedScene(PreparedMesh mesh, const BarOptions& bars)
      : prepared(std::move(mesh)), view(view_of(prepared)), data(build_scene_index(view, bars)),
        index(data, prepared.tolerance.length, prepared.tolerance.largest_island) {}
  IndexedScene(const IndexedScene&) = delete; // `index` refers to `data`, `data` to `view`, `view` to `prepared`
  IndexedScene& operator=(const IndexedScene&) = delete;
  PreparedMesh prepared;
  PreparedSceneView view;
  SceneIndexData data;
  SceneIndex index;
};

/// Prepares `mesh` at `tolerance` (default: the scene's) and indexes it with
/// `bars`; records a test failure when preparing fails.
inline std::unique_ptr<IndexedScene> index_scene(const Mesh& mesh, std::optional<double> tolerance,
                                                 const BarOptions& bars) {
  Result<PreparedMesh> prepared = prepare_mesh(mesh, tolerance);
  EXPECT_TRUE(prepared.ok()) << prepared.status().message();
  return std::make_unique<IndexedScene>(prepared.ok() ? std::move(prepared).value() : PreparedMesh{}, bars);
}

} // namespace hullcover::test
