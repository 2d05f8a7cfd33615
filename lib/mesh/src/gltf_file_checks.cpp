#include "gltf_file_checks.h"

#include "hullcover/mesh/json_nesting.h"

#include "scene_file_rules.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <vector>

namespace hullcover::detail {
namespace {

using Json = nlohmann::json;

Status damaged_gltf(const std::string& why) { return damaged_file("glTF: " + why); }

// A non-negative integer member, or `fallback` when absent; false when
// present but not one.
bool count_member(const Json& object, const char* key, std::uint64_t fallback, std::uint64_t& out) {
  const auto it = object.find(key);
  if (it == object.end()) {
    out = fallback;
    return true;
  }
  if (!it->is_number_unsigned()) return false;
  out = it->get<std::uint64_t>();
  return true;
}

// A URI with its %XX escapes decoded (glTF URIs are percent-encoded).
std::string percent_decoded(const std::string& uri) {
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
      out += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

// Buffers and images refer to files by relative path inside the scene's
// folder, or carry their bytes as data URIs. Judged on the text first (the
// IO system judges the path Assimp makes of it as well): no scheme, no
// absolute path, no '..'.
Status check_references(const Json& gltf) {
  for (const char* list : {"buffers", "images"}) {
    const auto items = gltf.find(list);
    if (items == gltf.end() || !items->is_array()) continue;
    for (const Json& item : *items) {
      if (!item.is_object()) continue;
      const auto uri = item.find("uri");
      if (uri == item.end() || !uri->is_string()) continue;
      const std::string text = uri->get<std::string>();
      if (text.compare(0, 5, "data:") == 0) continue;
      if (reference_text_leaves_folder(percent_decoded(text)))
        return {StatusCode::reference_outside_folder,
                std::string("refers to '") + text + "' (" + list +
                    "), outside the scene file's folder (references are read only inside it: no absolute paths, "
                    "no '..', no URLs)"};
    }
  }
  return Status::success();
}

// glTF nodes form a forest: each node has at most one parent and none is its
// own ancestor; its depth is walked with an explicit stack.
Status check_nodes(const Json& gltf, const ImportLimits& limits) {
  const auto nodes = gltf.find("nodes");
  if (nodes == gltf.end()) return Status::success();
  if (!nodes->is_array()) return damaged_gltf("'nodes' is not an array");
  const std::size_t n = nodes->size();
  std::vector<int> parents(n, 0);
  std::vector<std::vector<std::size_t>> children(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Json& node = (*nodes)[i];
    if (!node.is_object()) return damaged_gltf("node " + std::to_string(i) + " is not an object");
    const auto list = node.find("children");
    if (list == node.end()) continue;
    if (!list->is_array()) return damaged_gltf("node " + std::to_string(i) + "'s children are not an array");
    for (const Json& c : *list) {
      if (!c.is_number_unsigned() || c.get<std::uint64_t>() >= n)
        return damaged_gltf("node " + std::to_string(i) + " names a child that does not exist");
      const std::size_t child = static_cast<std::size_t>(c.get<std::uint64_t>());
      if (++parents[child] > 1) return damaged_gltf("node " + std::to_string(child) + " has two parents");
      children[i].push_back(child);
    }
  }
  std::size_t reached = 0;
  std::vector<std::pair<std::size_t, int>> pending;
  for (std::size_t i = 0; i < n; ++i)
    if (parents[i] == 0) pending.push_back({i, 1});
  while (!pending.empty()) {
    const auto [node, depth] = pending.back();
    pending.pop_back();
    ++reached;
    if (depth > limits.max_node_depth) return deeper_than_limit("glTF node hierarchy", limits);
    for (const std::size_t c : children[node]) pending.push_back({c, depth + 1});
  }
  if (reached != n) return damaged_gltf("the node hierarchy has a cycle");
  return Status::success();
}

// Buffers hold no more than their bytes; views lie inside their buffers;
// accessors inside their views (or, with no view, are zeros: bounded by the
// triangle limit through the counts that index them).
Status check_data(const Json& gltf, const std::string& path, std::uint64_t glb_binary_bytes) {
  std::vector<std::uint64_t> buffer_bytes;
  if (const auto buffers = gltf.find("buffers"); buffers != gltf.end() && buffers->is_array())
    for (std::size_t i = 0; i < buffers->size(); ++i) {
      const Json& b = (*buffers)[i];
      std::uint64_t declared = 0;
      if (!b.is_object() || !count_member(b, "byteLength", 0, declared))
        return damaged_gltf("buffer " + std::to_string(i) + " has no valid byteLength");
      std::uint64_t present = 0;
      const auto uri = b.find("uri");
      if (uri == b.end()) {
        present = i == 0 ? glb_binary_bytes : 0;
      } else if (!uri->is_string()) {
        return damaged_gltf("buffer " + std::to_string(i) + "'s uri is not a string");
      } else if (uri->get<std::string>().compare(0, 5, "data:") == 0) {
        const std::string& text = uri->get_ref<const std::string&>();
        const std::size_t comma = text.find(',');
        present = comma == std::string::npos ? 0 : (text.size() - comma - 1) / 4 * 3 + 3;
      } else {
        // Confinement is the IO system's; here only the size matters.
        std::error_code error;
        const auto file = std::filesystem::path(path).parent_path() / uri->get<std::string>();
        present = std::filesystem::is_regular_file(file, error) ? std::filesystem::file_size(file, error) : declared;
      }
      if (declared > present)
        return damaged_gltf("buffer " + std::to_string(i) + " declares " + std::to_string(declared) +
                            " bytes but holds " + std::to_string(present));
      buffer_bytes.push_back(declared);
    }
  std::vector<std::uint64_t> view_bytes;
  if (const auto views = gltf.find("bufferViews"); views != gltf.end() && views->is_array())
    for (std::size_t i = 0; i < views->size(); ++i) {
      const Json& v = (*views)[i];
      std::uint64_t buffer = 0, offset = 0, length = 0;
      if (!v.is_object() || !count_member(v, "buffer", ~std::uint64_t{0}, buffer) ||
          !count_member(v, "byteOffset", 0, offset) || !count_member(v, "byteLength", 0, length) ||
          buffer >= buffer_bytes.size() || offset > buffer_bytes[buffer] || length > buffer_bytes[buffer] - offset)
        return damaged_gltf("buffer view " + std::to_string(i) + " lies outside its buffer");
      view_bytes.push_back(length);
    }
  if (const auto accessors = gltf.find("accessors"); accessors != gltf.end() && accessors->is_array())
    for (std::size_t i = 0; i < accessors->size(); ++i) {
      const Json& a = (*accessors)[i];
      std::uint64_t view = 0, count = 0, offset = 0;
      if (!a.is_object() || !count_member(a, "count", 0, count) || !count_member(a, "byteOffset", 0, offset) ||
          !count_member(a, "bufferView", ~std::uint64_t{0}, view))
        return damaged_gltf("accessor " + std::to_string(i) + " has a malformed count, offset or view");
      if (view == ~std::uint64_t{0}) continue;
      if (view >= view_bytes.size()) return damaged_gltf("accessor " + std::to_string(i) + " names a missing view");
      // Each element takes at least one byte (the smallest component type,
      // scalar): the count can be no larger than the view's bytes.
      if (offset > view_bytes[view] || count > view_bytes[view] - offset)
        return damaged_gltf("accessor " + std::to_string(i) + " declares " + std::to_string(count) +
                            " elements, more than its view's " + std::to_string(view_bytes[view]) + " bytes hold");
    }
  return Status::success();
}

} // namespace

Status check_gltf(const std::string& path, std::ifstream& in, std::uint64_t file_bytes, bool binary,
                  const ImportLimits& limits) {
  std::string text;
  std::uint64_t glb_binary_bytes = 0;
  if (binary) {
    unsigned char header[20] = {};
    in.read(reinterpret_cast<char*>(header), sizeof header);
    if (in.gcount() != sizeof header || std::string(reinterpret_cast<char*>(header), 4) != "glTF")
      return damaged_gltf("not a GLB file (no 'glTF' magic)");
    const std::uint32_t json_bytes = little_endian_u32(header + 12);
    if (std::string(reinterpret_cast<char*>(header + 16), 4) != "JSON" || 20 + std::uint64_t{json_bytes} > file_bytes)
      return damaged_gltf("GLB's JSON chunk runs past the end of the file");
    text.resize(json_bytes);
    in.read(text.data(), json_bytes);
    const std::uint64_t after = 20 + std::uint64_t{json_bytes} + 8;
    if (after <= file_bytes) {
      unsigned char chunk[8] = {};
      in.read(reinterpret_cast<char*>(chunk), sizeof chunk);
      glb_binary_bytes = std::min<std::uint64_t>(little_endian_u32(chunk), file_bytes - after);
    }
  } else {
    text.resize(static_cast<std::size_t>(file_bytes));
    in.read(text.data(), static_cast<std::streamsize>(file_bytes));
  }
  if (json_nesting_depth(text) > limits.max_node_depth) return deeper_than_limit("glTF JSON nested", limits);
  const Json gltf = Json::parse(text, nullptr, false);
  if (gltf.is_discarded() || !gltf.is_object()) return damaged_gltf("the JSON does not parse to an object");
  if (Status references = check_references(gltf); !references.ok()) return references;
  if (Status nodes = check_nodes(gltf, limits); !nodes.ok()) return nodes;
  return check_data(gltf, path, glb_binary_bytes);
}

} // namespace hullcover::detail
