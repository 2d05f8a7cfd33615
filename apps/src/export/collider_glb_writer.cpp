#include "export/collider_glb_writer.h"

#include "hullcover/geometry/atomic_file.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <limits>

namespace hullcover::app {
namespace {

// glTF's numbers for what the accessors hold.
constexpr int kComponentFloat = 5126;
constexpr int kComponentUnsignedInt = 5125;
constexpr int kTargetArrayBuffer = 34962;
constexpr int kTargetElementArrayBuffer = 34963;
constexpr int kModeTriangles = 4;
// GLB header words: magic "glTF", version 2, and the two chunk types.
constexpr std::uint32_t kGlbMagic = 0x46546C67;
constexpr std::uint32_t kGlbVersion = 2;
constexpr std::uint32_t kChunkJson = 0x4E4F534A;
constexpr std::uint32_t kChunkBin = 0x004E4942;
// glTF offsets are 32-bit: a GLB holds at most 4 GiB.
constexpr std::uint64_t kLargestGlb = std::numeric_limits<std::uint32_t>::max();

// The binary chunk and the JSON that describes it, built together.
class GlbBuilder {
public:
  // Adds a mesh of `positions` and `triangles` and returns its index.
  int add_mesh(const std::vector<Eigen::Vector3f>& positions, const std::vector<std::uint32_t>& triangles,
               const std::string& name) {
    Eigen::Vector3f low = positions.front(), high = positions.front();
    for (const Eigen::Vector3f& p : positions) {
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
    const int position_view =
        add_view(positions.data(), positions.size() * sizeof(Eigen::Vector3f), kTargetArrayBuffer);
    const int index_view =
        add_view(triangles.data(), triangles.size() * sizeof(std::uint32_t), kTargetElementArrayBuffer);
    const int position_accessor = static_cast<int>(accessors_.size());
    accessors_.push_back({{"bufferView", position_view},
                          {"componentType", kComponentFloat},
                          {"count", positions.size()},
                          {"type", "VEC3"},
                          {"min", {low.x(), low.y(), low.z()}},
                          {"max", {high.x(), high.y(), high.z()}}});
    accessors_.push_back({{"bufferView", index_view},
                          {"componentType", kComponentUnsignedInt},
                          {"count", triangles.size()},
                          {"type", "SCALAR"}});
    meshes_.push_back({{"name", name},
                       {"primitives",
                        {{{"attributes", {{"POSITION", position_accessor}}},
                          {"indices", position_accessor + 1},
                          {"mode", kModeTriangles}}}}});
    return static_cast<int>(meshes_.size()) - 1;
  }

  nlohmann::json accessors() const { return accessors_; }
  nlohmann::json buffer_views() const { return views_; }
  nlohmann::json meshes() const { return meshes_; }
  const std::string& bin() const { return bin_; }

private:
  int add_view(const void* data, size_t bytes, int target) {
    views_.push_back({{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", bytes}, {"target", target}});
    bin_.append(static_cast<const char*>(data), bytes);
    bin_.resize((bin_.size() + 3) / 4 * 4, '\0'); // every view starts 4-byte aligned
    return static_cast<int>(views_.size()) - 1;
  }

  std::string bin_;
  nlohmann::json views_ = nlohmann::json::array();
  nlohmann::json accessors_ = nlohmann::json::array();
  nlohmann::json meshes_ = nlohmann::json::array();
};

void append_word(std::string& out, std::uint32_t word) {
  char bytes[4];
  std::memcpy(bytes, &word, 4); // GLB is little-endian, as every platform hullcover builds on
  out.append(bytes, 4);
}

} // namespace

Status write_collider_glb(const std::vector<ConvexPolytope>& hulls, const std::vector<std::string>& names,
                          const RenderMesh& render, const std::string& path) {
  if (names.size() != hulls.size()) return {StatusCode::invalid_argument, "one name per hull is needed"};
  GlbBuilder builder;
  nlohmann::json nodes = nlohmann::json::array();
  nlohmann::json shapes = nlohmann::json::array();
  for (size_t h = 0; h < hulls.size(); ++h) {
    const ConvexPolytope& hull = hulls[h];
    std::vector<Eigen::Vector3f> positions;
    for (const Eigen::Vector3d& v : hull.vertices) positions.push_back(v.cast<float>());
    std::vector<std::uint32_t> triangles;
    for (const std::vector<int>& facet : hull.facets)
      for (size_t k = 1; k + 1 < facet.size(); ++k)
        for (int v : {facet[0], facet[k], facet[k + 1]}) triangles.push_back(static_cast<std::uint32_t>(v));
    if (positions.empty() || triangles.empty())
      return {StatusCode::invalid_argument, "hull " + std::to_string(h) + " has no facet"};
    const int mesh = builder.add_mesh(positions, triangles, names[h]);
    const int node = static_cast<int>(nodes.size());
    shapes.push_back({{"type", "convex"}, {"convex", {{"mesh", mesh}}}});
    nodes.push_back(
        {{"name", names[h]},
         {"mesh", mesh},
         {"extensions",
          {{"KHR_physics_rigid_bodies", {{"collider", {{"geometry", {{"node", node}, {"convexHull", true}}}}}}},
           {"OMI_physics_body", {{"collider", {{"shape", static_cast<int>(shapes.size()) - 1}}}}}}}});
  }
  if (render.mesh && !render.mesh->triangles.empty()) {
    std::vector<Eigen::Vector3f> positions;
    for (const Eigen::Vector3d& v : render.mesh->positions) positions.push_back(v.cast<float>());
    std::vector<std::uint32_t> triangles;
    for (const Eigen::Vector3i& t : render.mesh->triangles)
      for (int k = 0; k < 3; ++k) triangles.push_back(static_cast<std::uint32_t>(t[k]));
    nodes.push_back({{"name", render.name}, {"mesh", builder.add_mesh(positions, triangles, render.name)}});
  }
  nlohmann::json scene_nodes = nlohmann::json::array();
  for (size_t n = 0; n < nodes.size(); ++n) scene_nodes.push_back(n);
  const nlohmann::json document = {
      {"asset", {{"version", "2.0"}, {"generator", "hullcover"}}},
      {"extensionsUsed", {"KHR_physics_rigid_bodies", "OMI_physics_body", "OMI_physics_shape"}},
      {"extensions", {{"OMI_physics_shape", {{"shapes", shapes}}}}},
      {"scene", 0},
      {"scenes", {{{"nodes", scene_nodes}}}},
      {"nodes", nodes},
      {"meshes", builder.meshes()},
      {"accessors", builder.accessors()},
      {"bufferViews", builder.buffer_views()},
      {"buffers", {{{"byteLength", builder.bin().size()}}}},
  };
  std::string json = document.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  json.resize((json.size() + 3) / 4 * 4, ' '); // the JSON chunk is padded with spaces
  const std::uint64_t total = 12 + 8 + json.size() + 8 + builder.bin().size();
  if (total > kLargestGlb) return {StatusCode::invalid_argument, "the hulls need more than glTF's 4 GiB"};
  std::string glb;
  glb.reserve(total);
  append_word(glb, kGlbMagic);
  append_word(glb, kGlbVersion);
  append_word(glb, static_cast<std::uint32_t>(total));
  append_word(glb, static_cast<std::uint32_t>(json.size()));
  append_word(glb, kChunkJson);
  glb += json;
  append_word(glb, static_cast<std::uint32_t>(builder.bin().size()));
  append_word(glb, kChunkBin);
  glb += builder.bin();
  return write_file_atomically(path, glb);
}

} // namespace hullcover::app
