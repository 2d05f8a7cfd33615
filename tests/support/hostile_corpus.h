#pragma once
// A hostile corpus for the `hullcover` command line, generated in code
// (deterministic: fixed seeds, no clock): each case is one command on files
// written into its own folder,
//
//   ROOT/CATEGORY/NAME/scene/    the files the case names (what it may read)
//   ROOT/CATEGORY/NAME/out/      what it is told to write
//   ROOT/CATEGORY/NAME/outside/  canaries holding kCanarySecret, which no case
//                                may read (scene files refer to them by '..',
//                                absolute paths, symlinks, URIs)
//
// hostile_scene_cases.h and hostile_run_cases.h fill it; the encoders here
// (base64, glTF, GLB, the runtime file) are what they share.

#include <sys/stat.h>

#include <cstdint>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace hullcover::test {

/// In every canary and in the environment of every run (so a read of
/// /proc/self/environ would show it too); in no file a case may read.
inline constexpr const char* kCanarySecret = "HULLCOVER-CANARY-5c1e9b27d04a";
/// The variable carrying the secret in the children's environment.
inline constexpr const char* kCanaryEnvironmentName = "HULLCOVER_HOSTILE_CANARY";

struct HostileCase {
  std::string category, name;
  std::string folder;
  std::vector<std::string> args; ///< hullcover's arguments
  std::uint64_t input_bytes = 0; ///< bytes of the files the case names as input
  std::vector<int> allowed_exits{0, 2};
  std::optional<int> expected_exit; ///< controls: valid input must still work
  bool must_refuse_outside = false; ///< exit 2 with the "outside the scene file's folder" line

  std::string scene() const { return folder + "/scene"; }
  std::string out() const { return folder + "/out"; }
  std::string outside() const { return folder + "/outside"; }
};

inline void write_file(const std::string& path, const std::string& content) {
  std::ofstream(path, std::ios::binary) << content;
}

inline std::uint64_t file_bytes(const std::string& path) {
  std::error_code error;
  const std::uintmax_t n = std::filesystem::file_size(path, error);
  return error ? 0 : static_cast<std::uint64_t>(n);
}

class HostileCorpus {
public:
  explicit HostileCorpus(std::string root) : root_(std::move(root)) {}

  /// A new case with its folders and canaries. References stay valid: cases
  /// live in a deque.
  HostileCase& add(const std::string& category, const std::string& name, const std::vector<std::string>& args = {}) {
    HostileCase c;
    c.category = category;
    c.name = name;
    c.folder = root_ + "/" + category + "/" + name;
    c.args = args;
    for (const std::string& d : {c.scene(), c.out(), c.outside()}) std::filesystem::create_directories(d);
    const std::string secret = kCanarySecret;
    write_file(c.outside() + "/canary.mtl", "newmtl " + secret + "\nKd 1 0 0\n");
    write_file(c.outside() + "/canary.bin", triangle_bytes(1) + secret);
    write_file(c.outside() + "/canary.txt", secret + "\n");
    cases_.push_back(std::move(c));
    return cases_.back();
  }

  /// Writes `name` into the case's scene folder, counts it as input, and
  /// returns its absolute path.
  static std::string input(HostileCase& c, const std::string& name, const std::string& content) {
    const std::string path = c.scene() + "/" + name;
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    write_file(path, content);
    c.input_bytes += content.size();
    return path;
  }

  const std::deque<HostileCase>& cases() const { return cases_; }

  /// `count` triangles (the i-th at x = i) as float32 positions, 36 bytes each.
  static std::string triangle_bytes(int count) {
    std::string bytes;
    for (int i = 0; i < count; ++i) {
      const float x = static_cast<float>(i);
      const float corners[9] = {x, 0, 0, x + 1, 0, 0, x, 1, 0};
      bytes.append(reinterpret_cast<const char*>(corners), sizeof corners);
    }
    return bytes;
  }

private:
  std::string root_;
  std::deque<HostileCase> cases_;
};

// ---- references out of the folder ----------------------------------------

/// The ways a scene file may name a file outside its folder. `encoded` ones
/// leave the folder only once decoded (glTF URIs are percent-encoded; '\' is
/// a separator only on Windows), so a reader that takes them literally finds
/// no such file inside the folder. `absolute` ones a reader may instead take
/// relative to the folder (Assimp's OBJ reader joins the folder and the
/// mtllib text, so "/etc/passwd" names FOLDER//etc/passwd): no read outside
/// either. Both must then merely not be read; every other kind refused.
struct ReferenceKind {
  const char* name;
  bool encoded, absolute;
};
inline const std::vector<ReferenceKind>& reference_kinds() {
  static const std::vector<ReferenceKind> kinds = {
      {"dotdot", false, false},         {"absolute", false, true},           {"absolute-climbing", false, false},
      {"file-uri", false, false},       {"http-uri", false, false},          {"proc-environ", false, true},
      {"dev-zero", false, true},        {"dev-urandom", false, true},        {"etc-passwd", false, true},
      {"fifo", false, false},           {"symlink-file", false, false},      {"symlink-dir", false, false},
      {"symlink-chain", false, false},  {"climb-through-sub", false, false}, {"percent-dotdot", true, false},
      {"backslash-dotdot", true, false}};
  return kinds;
}

/// The text a scene file in `c` uses to name the canary `canary.EXT` (or the
/// system file) the `kind` way, with whatever links, FIFOs and folders that
/// takes made in the scene folder.
inline std::string reference_text(const HostileCase& c, const std::string& kind, const std::string& ext) {
  namespace fs = std::filesystem;
  const std::string canary = "canary." + ext;
  const std::string target = c.outside() + "/" + canary;
  if (kind == "dotdot") return "../outside/" + canary;
  if (kind == "absolute") return target;
  if (kind == "absolute-climbing") return "/../outside/" + canary; // climbs even when joined to the folder
  if (kind == "file-uri") return "file://" + target;
  if (kind == "http-uri") return "http://127.0.0.1:9/" + canary; // the discard port: refused at once if tried
  if (kind == "proc-environ") return "/proc/self/environ";
  if (kind == "dev-zero") return "/dev/zero";
  if (kind == "dev-urandom") return "/dev/urandom";
  if (kind == "etc-passwd") return "/etc/passwd";
  if (kind == "fifo") {
    mkfifo((c.scene() + "/fifo." + ext).c_str(), 0644); // inside the folder, but a read would block forever
    return "fifo." + ext;
  }
  if (kind == "symlink-file") {
    fs::create_symlink(target, c.scene() + "/link." + ext);
    return "link." + ext;
  }
  if (kind == "symlink-dir") {
    fs::create_directory_symlink(c.outside(), c.scene() + "/linkdir");
    return "linkdir/" + canary;
  }
  if (kind == "symlink-chain") {
    fs::create_symlink("../outside/" + canary, c.scene() + "/hop2." + ext);
    fs::create_symlink("hop2." + ext, c.scene() + "/hop1." + ext);
    return "hop1." + ext;
  }
  if (kind == "climb-through-sub") {
    fs::create_directories(c.scene() + "/sub");
    return "sub/../../outside/" + canary;
  }
  if (kind == "percent-dotdot") return "%2e%2e/outside/" + canary;
  return "..\\outside\\" + canary; // backslash-dotdot
}

// ---- encoders ------------------------------------------------------------

/// Deterministic bytes (std::mt19937's sequence is fixed by the standard).
inline std::string random_bytes(std::size_t n, std::uint32_t seed) {
  std::mt19937 generator(seed);
  std::string bytes(n, '\0');
  for (char& b : bytes) b = static_cast<char>(generator() & 0xffu);
  return bytes;
}

inline void put_u32(std::string& out, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xffu));
}
inline void put_u64(std::string& out, std::uint64_t v) {
  for (int k = 0; k < 8; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xffu));
}
inline void put_f64(std::string& out, double d) {
  std::uint64_t v;
  std::memcpy(&v, &d, 8);
  put_u64(out, v);
}
inline void set_u32(std::string& bytes, std::size_t at, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) bytes[at + k] = static_cast<char>((v >> (8 * k)) & 0xffu);
}
inline void set_u64(std::string& bytes, std::size_t at, std::uint64_t v) {
  for (int k = 0; k < 8; ++k) bytes[at + k] = static_cast<char>((v >> (8 * k)) & 0xffu);
}
inline void set_f64(std::string& bytes, std::size_t at, double d) {
  std::uint64_t v;
  std::memcpy(&v, &d, 8);
  set_u64(bytes, at, v);
}

inline std::string base64(const std::string& bytes) {
  static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t v = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 2]);
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? alphabet[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? alphabet[v & 63] : '=';
  }
  return out;
}

inline std::string data_uri(const std::string& bytes) {
  return "data:application/octet-stream;base64," + base64(bytes);
}

/// The pieces of a one-mesh glTF that cases replace: the buffer's uri (and
/// declared length), the nodes and the scene's roots, the POSITION
/// accessor's count, and anything appended to the top-level object.
struct GltfParts {
  std::string uri = data_uri(HostileCorpus::triangle_bytes(1));
  std::uint64_t buffer_bytes = 36;
  std::string nodes = R"([{"mesh":0}])";
  std::string roots = "[0]";
  std::string count = "3";
  std::string extra; ///< e.g. `,"images":[...]`
};

inline std::string gltf_json(const GltfParts& p) {
  const std::string length = std::to_string(p.buffer_bytes);
  return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":)" + p.roots + R"(}],"nodes":)" + p.nodes +
         R"(,"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
         R"("accessors":[{"bufferView":0,"componentType":5126,"count":)" +
         p.count +
         R"(,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],)"
         R"("bufferViews":[{"buffer":0,"byteLength":)" +
         length + R"(}],"buffers":[{"byteLength":)" + length +
         (p.uri.empty() ? std::string() : R"(,"uri":")" + p.uri + "\"") + "}]" + p.extra + "}";
}

/// A GLB: 12-byte header, the JSON chunk (padded with spaces) and, when
/// `binary` is not empty, the BIN chunk (padded with zeros).
inline std::string glb(std::string json, std::string binary) {
  while (json.size() % 4 != 0) json += ' ';
  while (binary.size() % 4 != 0) binary += '\0';
  std::string out = "glTF";
  put_u32(out, 2);
  put_u32(out, static_cast<std::uint32_t>(12 + 8 + json.size() + (binary.empty() ? 0 : 8 + binary.size())));
  put_u32(out, static_cast<std::uint32_t>(json.size()));
  out += "JSON";
  out += json;
  if (!binary.empty()) {
    put_u32(out, static_cast<std::uint32_t>(binary.size()));
    out += std::string("BIN\0", 4);
    out += binary;
  }
  return out;
}

// ---- the runtime file (bvh/include/hullcover/bvh/runtime_file.h) ----------

/// Header offsets: magic 0, version 8, reserved 12, hull count 16, payload
/// bytes 24, checksum 32; the first hull's fixed part follows at 40.
namespace hcw {
inline constexpr std::size_t kVersion = 8, kHullCount = 16, kPayloadBytes = 24, kChecksum = 32, kHeader = 40;
inline constexpr std::size_t kMaterial = 40, kV = 44, kF = 48, kP = 52, kI = 56, kBox = 60, kVertices = 108;
} // namespace hcw

inline std::uint64_t fnv1a(const std::string& bytes, std::size_t from) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (std::size_t i = from; i < bytes.size(); ++i) h = (h ^ static_cast<unsigned char>(bytes[i])) * 0x100000001b3ull;
  return h;
}

/// Sets the header's payload size and checksum to match the bytes, so a
/// lie told inside the payload gets past them to the checks behind.
inline std::string with_valid_checksum(std::string bytes) {
  set_u64(bytes, hcw::kPayloadBytes, bytes.size() - hcw::kHeader);
  set_u64(bytes, hcw::kChecksum, fnv1a(bytes, hcw::kHeader));
  return bytes;
}

/// One axis-aligned box hull [lo, hi]^3 per entry, version 2 with surface
/// flags: 8 vertices, 6 quads wound counter-clockwise from outside.
inline std::string hcw_boxes(const std::vector<std::pair<double, double>>& boxes) {
  std::string payload;
  for (const auto& [lo, hi] : boxes) {
    put_u32(payload, 0);
    put_u32(payload, 8);
    put_u32(payload, 6);
    put_u32(payload, 6);
    put_u32(payload, 24);
    for (int k = 0; k < 3; ++k) put_f64(payload, lo);
    for (int k = 0; k < 3; ++k) put_f64(payload, hi);
    for (int v = 0; v < 8; ++v)
      for (int k = 0; k < 3; ++k) put_f64(payload, (v >> k) & 1 ? hi : lo);
    // Planes n.x = offset: -x, +x, -y, +y, -z, +z.
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side) {
        for (int k = 0; k < 3; ++k) put_f64(payload, k == axis ? (side ? 1.0 : -1.0) : 0.0);
        put_f64(payload, side ? hi : -lo);
      }
    for (int f = 0; f < 6; ++f) put_u32(payload, 4);
    const std::uint32_t quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (const auto& q : quads)
      for (std::uint32_t v : q) put_u32(payload, v);
    put_u32(payload, 6);
    for (int p = 0; p < 6; ++p) payload.push_back('\1');
  }
  std::string file("HCWORLD\0", 8);
  put_u32(file, 2);
  put_u32(file, 0);
  put_u64(file, boxes.size());
  put_u64(file, 0);
  put_u64(file, 0);
  return with_valid_checksum(file + payload);
}

} // namespace hullcover::test
