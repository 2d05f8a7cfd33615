#pragma once
// What the checks of every scene file format share (scene_file_checks.h
// runs them): how a damaged file and a too-deep one are reported, how
// little-endian counts are read, and which reference texts could lead out
// of the scene's folder.

#include "hullcover/geometry/status.h"
#include "hullcover/mesh/import_limits.h"

#include <cctype>
#include <cstddef>
#include <cstdint>
#include <algorithm>
#include <string_view>
#include <istream>
#include <filesystem>
#include <string>

namespace hullcover::detail {

/// The extension of `path`'s file name, dot included, in lower case ("" for
/// none): what picks a format's checks and reader.
inline std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

/// A file that is not what it says: `unreadable_file` with `why`.
inline Status damaged_file(const std::string& why) { return {StatusCode::unreadable_file, why}; }

/// The unsigned 32-bit little-endian number in `bytes[0..3]` (GLB chunk
/// lengths, a binary STL's triangle count).
inline std::uint32_t little_endian_u32(const unsigned char* bytes) {
  return static_cast<std::uint32_t>(bytes[0]) | static_cast<std::uint32_t>(bytes[1]) << 8 |
         static_cast<std::uint32_t>(bytes[2]) << 16 | static_cast<std::uint32_t>(bytes[3]) << 24;
}

/// `limit_exceeded` for `what` (a hierarchy, a nesting) deeper than
/// limits.max_node_depth, naming the option that raises it.
inline Status deeper_than_limit(const std::string& what, const ImportLimits& limits) {
  return {StatusCode::limit_exceeded, what + " deeper than the limit of " + std::to_string(limits.max_node_depth) +
                                          " levels (raise it with --max-node-depth)"};
}

/// Whether the text of a reference a scene file makes (a glTF URI once
/// percent-decoded, an OBJ material library's name) could lead outside the
/// scene's folder: a scheme (`http:`, `file:`), an absolute path, a `..`
/// or a backslash. Judged on the text before any reader resolves it; the
/// confined IO system judges the path the reader makes of it as well.
inline bool reference_text_leaves_folder(const std::string& path) {
  const bool scheme = path.find(':') != std::string::npos;
  const bool absolute = !path.empty() && (path[0] == '/' || path[0] == '\\');
  bool climbs = false;
  for (const auto& part : std::filesystem::path(path)) climbs |= part == "..";
  return scheme || absolute || climbs || path.find('\\') != std::string::npos;
}

/// How an STL file is laid out, read from its first 84 bytes: binary when
/// its size is the one a binary header's count declares, ASCII when its
/// text starts with "solid" (a binary header may too, so the size decides
/// first), neither otherwise. `declared` is the binary count, when read.
enum class StlLayout { binary, ascii, neither };
inline StlLayout stl_layout(std::istream& in, std::uint64_t file_bytes, std::uint64_t& declared) {
  constexpr std::uint64_t kHeaderBytes = 84, kTriangleBytes = 50, kCountAt = 80;
  char head[kHeaderBytes] = {};
  in.read(head, sizeof head);
  const std::uint64_t got = static_cast<std::uint64_t>(in.gcount());
  declared = 0;
  if (got == kHeaderBytes) {
    declared = little_endian_u32(reinterpret_cast<const unsigned char*>(head + kCountAt));
    if (kHeaderBytes + kTriangleBytes * declared == file_bytes) return StlLayout::binary;
  }
  const std::string_view start(head, static_cast<std::size_t>(std::min(got, kCountAt)));
  const std::size_t first = start.find_first_not_of(" \t\r\n");
  return first != std::string_view::npos && start.substr(first, 5) == "solid" ? StlLayout::ascii : StlLayout::neither;
}

/// How far into a PLY file its header may run before the file is taken as
/// damaged (a header cut off would otherwise be read to the end).
inline constexpr std::size_t kMaxPlyHeaderBytes = std::size_t{1} << 20;

} // namespace hullcover::detail
