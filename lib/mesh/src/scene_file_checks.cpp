#include "scene_file_checks.h"
#include "scene_file_rules.h"

#include "gltf_file_checks.h"
#include "obj_file_checks.h"
#include "ply_file_checks.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>

namespace hullcover::detail {
namespace {

// A binary STL must be the size its count declares; an ASCII one starts
// with "solid" (stl_layout).
Status check_stl(std::ifstream& in, std::uint64_t file_bytes) {
  std::uint64_t declared = 0;
  if (stl_layout(in, file_bytes, declared) != StlLayout::neither) return Status::success();
  if (file_bytes < 84) return damaged_file("STL shorter than a binary header (84 bytes) and not ASCII ('solid')");
  return damaged_file("binary STL declares " + std::to_string(declared) + " triangles, which take " +
                      std::to_string(84 + 50 * declared) + " bytes; the file has " + std::to_string(file_bytes));
}

} // namespace

Status check_scene_file(const std::string& path, const ImportLimits& limits) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {StatusCode::unreadable_file, "cannot open"};
  in.seekg(0, std::ios::end);
  const std::uint64_t file_bytes = static_cast<std::uint64_t>(in.tellg());
  in.seekg(0);
  const std::string ext = lower_extension(path);
  if (ext == ".ply") return check_ply(in, file_bytes);
  if (ext == ".stl") return check_stl(in, file_bytes);
  if (ext == ".gltf" || ext == ".glb") return check_gltf(path, in, file_bytes, ext == ".glb", limits);
  if (ext == ".obj") return check_obj(in, limits);
  return Status::success();
}

} // namespace hullcover::detail
