#pragma once
/// \file fuzz_targets.h
/// The bodies of hullcover's fuzz targets, one per reader of files from
/// anyone. Each libFuzzer entry point (fuzz_<target>.cpp, built with
/// HULLCOVER_FUZZ) calls its body, and so does the corpus replay test
/// (test_fuzz_corpus.cpp, in every build): a crasher saved in
/// tests/fuzz/regressions/<target>/ is replayed by every test run through
/// exactly the code the fuzzer ran.
///
/// A body never fails on bad input: a reader refusing a file is the
/// expected outcome. What counts is a crash, a sanitizer report or a hang.
/// Each returns 0, as libFuzzer wants.

#include <cstddef>
#include <cstdint>

namespace hullcover::fuzz {

/// The targets, by the name of their corpus folder.
inline constexpr const char* kMeshImport = "mesh_import";
inline constexpr const char* kRuntimeFile = "runtime_file";
inline constexpr const char* kHullObj = "hull_obj";
inline constexpr const char* kCellResult = "cell_result";
inline constexpr const char* kSceneSnapshot = "scene_snapshot";
inline constexpr const char* kPreparedScene = "prepared_scene";

/// Mesh import (mesh_import.h), then prepare_mesh as every command does.
/// The first byte picks the extension (.obj .ply .stl .gltf .glb, modulo
/// 5); the rest is the file, written alone into a per-process folder, so
/// confinement applies and no other input's file is ever beside it.
int fuzz_one_mesh_import(const std::uint8_t* data, std::size_t size);

/// The `.hcw` reader (runtime_file.h); hulls it accepts are built into a
/// HullWorld and queried, since the reader promises checked hulls. A file
/// with the HCWORLD header is read a second time with its payload size and
/// checksum made right, so the fuzzer reaches the payload's checks.
int fuzz_one_runtime_file(const std::uint8_t* data, std::size_t size);

/// The hull-OBJ reader (validate's load_hull_set on an `.obj`); hulls it
/// accepts are built into a HullWorld and queried.
int fuzz_one_hull_obj(const std::uint8_t* data, std::size_t size);

/// A cell's result as bytes (StagedDecomposition: what a distributed bake's
/// worker returns, what the cell cache reads), given to still_valid and
/// finish for cell 0 of a small scene cut into cells: as they come,
/// and as edits (a u16 position and a byte, each) to the valid bytes with
/// the key and checksum made right afterwards.
int fuzz_one_cell_result(const std::uint8_t* data, std::size_t size);

/// The cell cache's record of the last bake (`last-bake.scene`), read by a
/// re-bake of a small scene in cells with one face added: as it comes, and
/// as edits (a u16 position and a byte, each) to the valid record with its
/// checksum made right afterwards.
int fuzz_one_scene_snapshot(const std::uint8_t* data, std::size_t size);

/// The prepared scene file (StagedDecomposition::map_prepared) of a small
/// scene in cells: the input as the file, and as edits (u16 position,
/// byte) to the valid file with every checksum made right.
int fuzz_one_prepared_scene(const std::uint8_t* data, std::size_t size);

} // namespace hullcover::fuzz
