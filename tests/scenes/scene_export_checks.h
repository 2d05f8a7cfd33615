#pragma once
// The engine exports' checks on one shared scene's covering
// (test_scene_exports.cpp), called by the covering test of that scene so
// that each scene is decomposed once per test run.

#include "hullcover/covering/covering.h"
#include "hullcover/mesh/prepared_mesh.h"

#include <string>

namespace hullcover {

/// Exports `covering` of `scene` (a file name in ../shared/data/scenes) as
/// a .glb and as Unreal and Godot OBJs, reads each back, validates the .glb
/// (Khronos validator when installed) and audits it; records GoogleTest
/// failures.
void check_engine_exports(const std::string& scene, const PreparedMesh& prepared, const Covering& covering);

} // namespace hullcover
