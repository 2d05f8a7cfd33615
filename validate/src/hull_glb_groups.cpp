#include "hull_groups.h"

#include "hullcover/mesh/json_nesting.h"

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <optional>
#include <cstring>
#include <limits>
#include <set>
#include <utility>

namespace hullcover::validate::detail {
namespace {

using Json = nlohmann::json;

constexpr std::uint32_t kGlbMagic = 0x46546C67; // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;
constexpr std::uint32_t kChunkBin = 0x004E4942;
constexpr std::uint64_t kGlbHeaderBytes = 12;
constexpr std::uint64_t kChunkHeaderBytes = 8;
constexpr int kComponentFloat = 5126;
constexpr int kComponentUnsignedByte = 5121;
constexpr int kComponentUnsignedShort = 5123;
constexpr int kComponentUnsignedInt = 5125;
constexpr int kModeTriangles = 4;
// Scenes are float32; beyond that range no hull stands for one.
constexpr double kLargestHullCoordinate = std::numeric_limits<float>::max();

std::uint32_t word_at(const std::string& bytes, std::uint64_t at) {
  std::uint32_t word = 0;
  std::memcpy(&word, bytes.data() + at, 4); // GLB is little-endian, as every platform hullcover builds on
  return word;
}

// A non-negative integer member (or `fallback` when absent); nothing when
// present but not one.
std::optional<std::uint64_t> count_of(const Json& object, const char* key, std::uint64_t fallback) {
  if (!object.is_object() || !object.contains(key)) return fallback;
  const Json& value = object[key];
  if (!value.is_number_unsigned()) return std::nullopt;
  return value.get<std::uint64_t>();
}

// The index member `key` of `object` when it names an element of
// top-level array `kind`, or nothing.
std::optional<std::uint64_t> index_into(const Json& gltf, const char* kind, const Json& object, const char* key) {
  const std::optional<std::uint64_t> index = count_of(object, key, std::numeric_limits<std::uint64_t>::max());
  if (!index || !gltf.is_object() || !gltf.contains(kind) || !gltf[kind].is_array() || *index >= gltf[kind].size())
    return std::nullopt;
  return index;
}

// The element index_into names, or nothing.
const Json* element(const Json& gltf, const char* kind, const Json& object, const char* key) {
  const std::optional<std::uint64_t> index = index_into(gltf, kind, object, key);
  return index ? &gltf[kind][*index] : nullptr;
}

// Whether member `key` of object `object` is the boolean true.
bool is_true(const Json& object, const char* key) {
  return object.is_object() && object.contains(key) && object[key].is_boolean() && object[key].get<bool>();
}

// Member `key` of `object` when both are objects, else an empty object.
const Json& object_member(const Json& object, const char* key) {
  static const Json kEmpty = Json::object();
  if (!object.is_object() || !object.contains(key) || !object[key].is_object()) return kEmpty;
  return object[key];
}

class GlbHullReader {
public:
  GlbHullReader(const std::string& path, const Json& gltf, const std::string& bin)
      : path_(path), gltf_(gltf), bin_(bin) {}

  Status damaged(const std::string& why) const { return {StatusCode::unreadable_file, path_ + ": glTF: " + why}; }

  // World transforms of every node; fails unless the nodes form a forest.
  Status place_nodes() {
    const Json empty = Json::array();
    const Json& nodes = gltf_.contains("nodes") && gltf_["nodes"].is_array() ? gltf_["nodes"] : empty;
    const size_t n = nodes.size();
    std::vector<long> parent(n, -1);
    for (size_t i = 0; i < n; ++i) {
      if (!nodes[i].is_object()) return damaged("node " + std::to_string(i) + " is not an object");
      if (!nodes[i].contains("children")) continue;
      if (!nodes[i]["children"].is_array()) return damaged("node " + std::to_string(i) + ": children is not a list");
      for (const Json& child : nodes[i]["children"]) {
        if (!child.is_number_unsigned() || child.get<std::uint64_t>() >= n || parent[child.get<size_t>()] != -1 ||
            child.get<size_t>() == i)
          return damaged("node " + std::to_string(i) + ": the node graph is not a forest");
        parent[child.get<size_t>()] = static_cast<long>(i);
      }
    }
    world_.assign(n, Eigen::Affine3d::Identity());
    for (size_t i = 0; i < n; ++i) {
      // Walk up; a forest reaches a root within n steps, a cycle never does.
      std::vector<size_t> chain = {i};
      while (parent[chain.back()] != -1) {
        if (chain.size() > n) return damaged("the node graph has a cycle");
        chain.push_back(static_cast<size_t>(parent[chain.back()]));
      }
      Eigen::Affine3d world = Eigen::Affine3d::Identity();
      for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
        std::optional<Eigen::Affine3d> local = local_transform(nodes[*it]);
        if (!local) return damaged("node " + std::to_string(*it) + ": bad matrix, translation, rotation or scale");
        world = world * *local;
      }
      world_[i] = world;
    }
    return Status::success();
  }

  // Adds node `node`'s placement of mesh `mesh` as one group.
  Status add_group(size_t node, const Json& mesh, HullGroups& out) {
    HullGroup group;
    const Json& nodes = gltf_["nodes"];
    if (nodes[node].contains("name") && nodes[node]["name"].is_string()) group.name = nodes[node]["name"];
    if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array())
      return damaged("node " + std::to_string(node) + ": its mesh has no primitives");
    for (const Json& primitive : mesh["primitives"]) {
      if (count_of(primitive, "mode", kModeTriangles) != std::optional<std::uint64_t>(kModeTriangles))
        return damaged("node " + std::to_string(node) + ": a primitive that is not triangles");
      const Json* attributes =
          primitive.is_object() && primitive.contains("attributes") ? &primitive["attributes"] : nullptr;
      const Json* position = attributes ? element(gltf_, "accessors", *attributes, "POSITION") : nullptr;
      if (!position) return damaged("node " + std::to_string(node) + ": a primitive without positions");
      const size_t first = out.positions.size();
      if (Status s = read_positions(*position, node, out.positions); !s.ok()) return s;
      const size_t count = out.positions.size() - first;
      std::vector<std::uint64_t> corners;
      if (primitive.contains("indices")) {
        const Json* indices = element(gltf_, "accessors", primitive, "indices");
        if (!indices) return damaged("node " + std::to_string(node) + ": indices name no accessor");
        if (Status s = read_indices(*indices, count, corners); !s.ok()) return s;
      } else {
        for (size_t k = 0; k < count; ++k) corners.push_back(k);
      }
      if (corners.size() % 3 != 0) return damaged("node " + std::to_string(node) + ": a triangle cut short");
      for (size_t k = 0; k < corners.size(); k += 3) {
        const Eigen::Vector3d& a = out.positions[first + corners[k]];
        const Eigen::Vector3d& b = out.positions[first + corners[k + 1]];
        const Eigen::Vector3d& c = out.positions[first + corners[k + 2]];
        group.winding += (b - a).cross(c - a);
      }
      for (std::uint64_t v : corners) group.vertices.push_back(static_cast<int>(first + v));
    }
    out.groups.push_back(std::move(group));
    return Status::success();
  }

private:
  static std::optional<Eigen::Affine3d> local_transform(const Json& node) {
    const auto numbers = [&](const char* key, size_t count, std::vector<double>& out) {
      if (!node.contains(key)) return true;
      const Json& list = node[key];
      if (!list.is_array() || list.size() != count) return false;
      for (const Json& x : list) {
        if (!x.is_number() || !std::isfinite(x.get<double>())) return false;
        out.push_back(x.get<double>());
      }
      return true;
    };
    std::vector<double> matrix, t, r, s;
    if (!numbers("matrix", 16, matrix) || !numbers("translation", 3, t) || !numbers("rotation", 4, r) ||
        !numbers("scale", 3, s))
      return std::nullopt;
    Eigen::Affine3d local = Eigen::Affine3d::Identity();
    if (!matrix.empty()) {
      local.matrix() = Eigen::Map<const Eigen::Matrix4d>(matrix.data()); // column-major, as glTF
      return local;
    }
    if (!t.empty()) local.translate(Eigen::Vector3d(t[0], t[1], t[2]));
    if (!r.empty()) local.rotate(Eigen::Quaterniond(r[3], r[0], r[1], r[2]).normalized());
    if (!s.empty()) local.scale(Eigen::Vector3d(s[0], s[1], s[2]));
    return local;
  }

  // The bytes of accessor `accessor`: `count` elements of `size` bytes,
  // checked to lie in the binary chunk.
  Status locate(const Json& accessor, std::uint64_t size, std::uint64_t& start, std::uint64_t& stride,
                std::uint64_t& count) const {
    if (accessor.contains("sparse")) return damaged("sparse accessors are not read in hull files");
    const Json* view = element(gltf_, "bufferViews", accessor, "bufferView");
    if (!view) return damaged("an accessor without a buffer view");
    const Json* buffer = element(gltf_, "buffers", *view, "buffer");
    if (!buffer || (buffer->is_object() && buffer->contains("uri")))
      return damaged("hull data must lie in the GLB's own binary chunk");
    const std::optional<std::uint64_t> accessor_offset = count_of(accessor, "byteOffset", 0);
    const std::optional<std::uint64_t> elements = count_of(accessor, "count", 0);
    const std::optional<std::uint64_t> view_offset = count_of(*view, "byteOffset", 0);
    const std::optional<std::uint64_t> view_length = count_of(*view, "byteLength", 0);
    const std::optional<std::uint64_t> view_stride = count_of(*view, "byteStride", size);
    if (!accessor_offset || !elements || !view_offset || !view_length || !view_stride || *view_stride < size)
      return damaged("a buffer view or accessor with a bad offset, length, stride or count");
    const std::uint64_t chunk = bin_.size();
    // Each bound below is tested before the next sum can overflow.
    if (*view_offset > chunk || *view_length > chunk - *view_offset || *accessor_offset > *view_length ||
        *elements > chunk || *view_stride > chunk)
      return damaged("a buffer view or accessor past the binary chunk");
    if (*elements > 0 && (*elements - 1) * *view_stride + size > *view_length - *accessor_offset)
      return damaged("an accessor past its buffer view");
    start = *view_offset + *accessor_offset;
    stride = *view_stride;
    count = *elements;
    return Status::success();
  }

  Status read_positions(const Json& accessor, size_t node, std::vector<Eigen::Vector3d>& out) const {
    if (count_of(accessor, "componentType", 0) != std::optional<std::uint64_t>(kComponentFloat) ||
        !accessor.contains("type") || accessor["type"] != "VEC3")
      return damaged("positions must be float VEC3");
    std::uint64_t start = 0, stride = 0, count = 0;
    if (Status s = locate(accessor, 3 * sizeof(float), start, stride, count); !s.ok()) return s;
    for (std::uint64_t k = 0; k < count; ++k) {
      float xyz[3];
      std::memcpy(xyz, bin_.data() + start + k * stride, sizeof xyz);
      const Eigen::Vector3d p = world_[node] * Eigen::Vector3d(xyz[0], xyz[1], xyz[2]);
      if (!p.allFinite() || p.cwiseAbs().maxCoeff() > kLargestHullCoordinate)
        return damaged("a position beyond the float32 range a scene can have");
      out.push_back(p);
    }
    return Status::success();
  }

  Status read_indices(const Json& accessor, size_t vertex_count, std::vector<std::uint64_t>& out) const {
    const std::optional<std::uint64_t> type = count_of(accessor, "componentType", 0);
    std::uint64_t size = 0;
    if (type == std::optional<std::uint64_t>(kComponentUnsignedByte)) size = 1;
    if (type == std::optional<std::uint64_t>(kComponentUnsignedShort)) size = 2;
    if (type == std::optional<std::uint64_t>(kComponentUnsignedInt)) size = 4;
    if (size == 0 || !accessor.contains("type") || accessor["type"] != "SCALAR")
      return damaged("indices must be unsigned byte, short or int scalars");
    std::uint64_t start = 0, stride = 0, count = 0;
    if (Status s = locate(accessor, size, start, stride, count); !s.ok()) return s;
    for (std::uint64_t k = 0; k < count; ++k) {
      std::uint32_t index = 0;
      std::memcpy(&index, bin_.data() + start + k * stride, size); // little-endian: the low bytes come first
      if (index >= vertex_count) return damaged("an index names no vertex");
      out.push_back(index);
    }
    return Status::success();
  }

  const std::string& path_;
  const Json& gltf_;
  const std::string& bin_;
  std::vector<Eigen::Affine3d> world_;
};

} // namespace

Result<HullGroups> read_glb_hull_groups(const std::string& path, const std::string& bytes) {
  const auto damaged = [&](const std::string& why) {
    return Status{StatusCode::unreadable_file, path + ": GLB: " + why};
  };
  if (bytes.size() < kGlbHeaderBytes + kChunkHeaderBytes || word_at(bytes, 0) != kGlbMagic || word_at(bytes, 4) != 2)
    return damaged("not a glTF 2 binary");
  const std::uint64_t json_bytes = word_at(bytes, 12);
  if (word_at(bytes, 16) != kChunkJson || json_bytes > bytes.size() - kGlbHeaderBytes - kChunkHeaderBytes)
    return damaged("the JSON chunk runs past the file");
  const std::string text = bytes.substr(kGlbHeaderBytes + kChunkHeaderBytes, json_bytes);
  std::string bin;
  const std::uint64_t bin_header = kGlbHeaderBytes + kChunkHeaderBytes + json_bytes;
  if (bytes.size() >= bin_header + kChunkHeaderBytes && word_at(bytes, bin_header + 4) == kChunkBin) {
    const std::uint64_t bin_bytes = word_at(bytes, bin_header);
    if (bin_bytes > bytes.size() - bin_header - kChunkHeaderBytes)
      return damaged("the binary chunk runs past the file");
    bin = bytes.substr(bin_header + kChunkHeaderBytes, bin_bytes);
  }
  if (json_nesting_depth(text) > kMaxHullGltfNesting)
    return Status{StatusCode::limit_exceeded,
                  path + ": GLB: JSON nested deeper than " + std::to_string(kMaxHullGltfNesting) + " levels"};
  const Json gltf = Json::parse(text, nullptr, false);
  if (gltf.is_discarded() || !gltf.is_object()) return damaged("the JSON chunk is not a JSON object");
  GlbHullReader reader(path, gltf, bin);
  if (Status s = reader.place_nodes(); !s.ok()) return s;
  // (node whose transform places it, mesh index) of every declared collider.
  std::set<std::pair<size_t, std::uint64_t>> colliders;
  const Json empty = Json::array();
  const Json& nodes = gltf.contains("nodes") && gltf["nodes"].is_array() ? gltf["nodes"] : empty;
  const Json& omi_shapes = object_member(object_member(gltf, "extensions"), "OMI_physics_shape");
  for (size_t i = 0; i < nodes.size(); ++i) {
    const Json& extensions = object_member(nodes[i], "extensions");
    const Json& geometry =
        object_member(object_member(object_member(extensions, "KHR_physics_rigid_bodies"), "collider"), "geometry");
    if (is_true(geometry, "convexHull")) {
      const std::optional<std::uint64_t> node = index_into(gltf, "nodes", geometry, "node");
      const std::optional<std::uint64_t> mesh = node ? index_into(gltf, "meshes", nodes[*node], "mesh") : std::nullopt;
      if (!mesh) return reader.damaged("node " + std::to_string(i) + ": its convex collider names no node with a mesh");
      colliders.insert({*node, *mesh});
    }
    const Json& body_collider = object_member(object_member(extensions, "OMI_physics_body"), "collider");
    if (const Json* shape = element(omi_shapes, "shapes", body_collider, "shape");
        shape && shape->is_object() && shape->contains("type") && (*shape)["type"] == "convex") {
      const std::optional<std::uint64_t> mesh = index_into(gltf, "meshes", object_member(*shape, "convex"), "mesh");
      if (!mesh) return reader.damaged("node " + std::to_string(i) + ": its convex shape names no mesh");
      colliders.insert({i, *mesh});
    }
  }
  if (colliders.empty())
    for (size_t i = 0; i < nodes.size(); ++i)
      if (const std::optional<std::uint64_t> mesh = index_into(gltf, "meshes", nodes[i], "mesh"))
        colliders.insert({i, *mesh});
  HullGroups out;
  for (const auto& [node, mesh] : colliders)
    if (Status s = reader.add_group(node, gltf["meshes"][mesh], out); !s.ok()) return s;
  return out;
}

} // namespace hullcover::validate::detail
