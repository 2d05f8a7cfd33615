#pragma once
// The second half of the hostile corpus (hostile_corpus.h): runtime files
// (.hcw) cut short, bit-flipped and lying about their counts, for `query`;
// hull OBJ files for `audit`; and command-line values (non-numbers, signs,
// extremes, paths that are not files or not writable).

#include "hostile_corpus.h"

#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace hullcover::test {

inline const char* const kQuadObj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";

/// Devices and special files given where a file to read is expected. The
/// FIFO and the folder are made in the case's own scene folder (nothing ever
/// writes to the FIFO: a reader that opens it waits forever).
inline const std::vector<std::string>& special_kinds() {
  static const std::vector<std::string> kinds = {"dev-zero", "dev-urandom", "fifo", "directory", "missing"};
  return kinds;
}
inline std::string special_input(const HostileCase& c, const std::string& kind, const std::string& ext) {
  if (kind == "dev-zero") return "/dev/zero";
  if (kind == "dev-urandom") return "/dev/urandom";
  const std::string path = c.scene() + "/" + kind + "." + ext;
  if (kind == "fifo") mkfifo(path.c_str(), 0644);
  if (kind == "directory") std::filesystem::create_directories(path);
  return path;
}

inline void add_hcw_cases(HostileCorpus& corpus) {
  const std::string cat = "hcw";
  const std::string one = hcw_boxes({{0.0, 1.0}});
  const std::string two = hcw_boxes({{0.0, 1.0}, {2.0, 3.0}});
  const auto query = [&](const std::string& name, const std::string& bytes) -> HostileCase& {
    HostileCase& c = corpus.add(cat, name);
    c.args = {"query", HostileCorpus::input(c, "w.hcw", bytes), "--sphere", "0.5,0.5,0.5,0.25"};
    return c;
  };
  query("control-one-box", one).expected_exit = 0;
  query("control-two-boxes", two).expected_exit = 0;
  // Cut short, at the header's fields and inside the payload.
  for (std::size_t size : {std::size_t{0}, std::size_t{7}, std::size_t{8}, hcw::kHeader - 1, hcw::kHeader,
                           hcw::kVertices, one.size() / 2, one.size() - 1})
    query("truncated-" + std::to_string(size), one.substr(0, size));
  // Bit flips: the stale checksum catches those in the payload; with the
  // checksum made to match, the checks behind it must.
  for (std::size_t at :
       {std::size_t{0}, hcw::kVersion, hcw::kHullCount, hcw::kPayloadBytes + 7, hcw::kChecksum + 1, std::size_t{200}}) {
    std::string flipped = one;
    flipped[at] = static_cast<char>(flipped[at] ^ 0x10);
    query("flip-stale-" + std::to_string(at), flipped);
  }
  for (int k = 0; k < 12; ++k) {
    // Spread over the payload: fixed part, vertices, planes, facet sizes, indices, flags.
    const std::size_t at = hcw::kHeader + (static_cast<std::size_t>(k) * 53) % (one.size() - hcw::kHeader);
    std::string flipped = one;
    flipped[at] = static_cast<char>(flipped[at] ^ (1 << (k % 8)));
    query("flip-fixed-" + std::to_string(at) + "-bit" + std::to_string(k % 8), with_valid_checksum(flipped));
  }
  // Header fields that lie (the checksum still matches the payload).
  const auto header = [&](const std::string& name, std::size_t at, std::uint64_t value, bool wide) {
    std::string bytes = one;
    wide ? set_u64(bytes, at, value) : set_u32(bytes, at, static_cast<std::uint32_t>(value));
    query("header-" + name, bytes);
  };
  header("count-0", hcw::kHullCount, 0, true);
  header("count-2", hcw::kHullCount, 2, true);
  header("count-2pow63", hcw::kHullCount, 1ull << 63, true);
  header("count-max", hcw::kHullCount, ~0ull, true);
  header("payload-max", hcw::kPayloadBytes, ~0ull, true);
  header("version-0", hcw::kVersion, 0, false);
  header("version-3", hcw::kVersion, 3, false);
  header("version-max", hcw::kVersion, 0xffffffffu, false);
  // Counts and values inside the payload that lie, checksum made to match.
  constexpr std::size_t kPlanes = hcw::kVertices + 8 * 24, kSizes = kPlanes + 6 * 32, kIndices = kSizes + 6 * 4;
  constexpr std::size_t kFlags = kIndices + 24 * 4;
  const auto payload = [&](const std::string& name, auto change) {
    std::string bytes = one;
    change(bytes);
    query("payload-" + name, with_valid_checksum(bytes));
  };
  for (const auto& [name, at] :
       std::vector<std::pair<std::string, std::size_t>>{{"V", hcw::kV}, {"F", hcw::kF}, {"P", hcw::kP}, {"I", hcw::kI}})
    payload(name + "-max", [at = at](std::string& b) { set_u32(b, at, 0xffffffffu); });
  payload("V-2", [](std::string& b) { set_u32(b, hcw::kV, 2); });
  payload("P-below-F", [](std::string& b) { set_u32(b, hcw::kP, 5); });
  payload("facet-size-max", [](std::string& b) { set_u32(b, kSizes, 0xffffffffu); });
  payload("facet-size-0", [](std::string& b) { set_u32(b, kSizes, 0); });
  payload("facet-size-2pow28", [](std::string& b) { set_u32(b, kSizes, 1u << 28); });
  payload("facet-index-8", [](std::string& b) { set_u32(b, kIndices, 8); });
  payload("facet-index-max", [](std::string& b) { set_u32(b, kIndices, 0xffffffffu); });
  payload("flags-count-5", [](std::string& b) { set_u32(b, kFlags, 5); });
  payload("flag-value-7", [](std::string& b) { b[kFlags + 4] = 7; });
  payload("vertex-nan", [](std::string& b) { set_f64(b, hcw::kVertices, std::nan("")); });
  payload("plane-nan", [](std::string& b) { set_f64(b, kPlanes, std::nan("")); });
  payload("normal-not-unit", [](std::string& b) { set_f64(b, kPlanes, -2.0); });
  payload("box-mismatch", [](std::string& b) { set_f64(b, hcw::kBox, -5.0); });
  // Consistent files of hostile shape: a box at the edge of double range, a
  // box shrunk to one point, a box whose planes all face the same way.
  query("huge-box-1e307", hcw_boxes({{-1e307, 1e307}}));
  query("point-box", hcw_boxes({{0.5, 0.5}}));
  payload("planes-all-plus-x", [](std::string& b) {
    for (int p = 0; p < 6; ++p) {
      set_f64(b, kPlanes + 32 * p, 1.0), set_f64(b, kPlanes + 32 * p + 8, 0.0), set_f64(b, kPlanes + 32 * p + 16, 0.0);
    }
  });
  query("many-boxes-5000", hcw_boxes(std::vector<std::pair<double, double>>(5000, {0.0, 1.0})));
  {
    HostileCase& c = corpus.add(cat, "ray-into-huge-box");
    c.args = {"query", HostileCorpus::input(c, "w.hcw", hcw_boxes({{-1e307, 1e307}})), "--ray", "0,0,0,1,1,1"};
  }
  for (const std::string& kind : special_kinds()) {
    HostileCase& c = corpus.add(cat, "special-" + kind);
    c.args = {"query", special_input(c, kind, "hcw"), "--sphere", "0.5,0.5,0.5,0.25"};
  }
}

inline void add_audit_hull_cases(HostileCorpus& corpus) {
  const std::string cat = "audit";
  // Fast settings (a few hundred rays and proxies on a unit quad): the
  // hostile part is the hull file, not the work asked for.
  const auto audit = [&](const std::string& name, const std::string& hulls_name,
                         const std::string& hulls) -> HostileCase& {
    HostileCase& c = corpus.add(cat, name);
    const std::string scene = HostileCorpus::input(c, "s.obj", kQuadObj);
    const std::string path = hulls_name.empty() ? hulls : HostileCorpus::input(c, hulls_name, hulls);
    c.args = {"audit",          scene, path,     "--resolution",      "0.1",
              "--proxies",      "50",  "--json", c.out() + "/a.json", "--octree",
              c.out() + "/a.bt"};
    c.allowed_exits = {0, 1, 2}; // 1: the verdict "space lost", documented for audit
    return c;
  };
  audit("control-flat-hull", "h.obj", "o h\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n").expected_exit = 0;
  audit("control-box-hcw", "h.hcw", hcw_boxes({{0.0, 1.0}})).expected_exit = 1; // fills the quad's front space
  {
    HostileCase& c = audit("control-default-settings", "h.obj", "o h\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
    c.args.resize(3);
    c.expected_exit = 0;
  }
  std::string coplanar = "o h\n", duplicates = "o h\n", cloud = "o h\n", groups;
  std::mt19937 generator(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 1000; ++i)
    coplanar += "v " + std::to_string(unit(generator)) + " " + std::to_string(unit(generator)) + " 0.5\n";
  coplanar += "f 1 2 3\n";
  for (int i = 0; i < 1000; ++i) duplicates += "v 0.25 0.25 0.25\n";
  duplicates += "v 0.5 0.5 0.5\nf 1 2 1001\n";
  for (int i = 0; i < 20000; ++i)
    cloud += "v " + std::to_string(unit(generator)) + " " + std::to_string(unit(generator)) + " " +
             std::to_string(unit(generator)) + "\n";
  cloud += "f 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20\nf";
  for (int i = 1; i <= 20000; ++i) cloud += " " + std::to_string(i);
  cloud += "\n";
  for (int g = 0; g < 3000; ++g) {
    const std::string x = std::to_string(g % 60 / 60.0), y = std::to_string(g / 60 / 50.0);
    groups += "o g" + std::to_string(g) + "\nv " + x + " " + y + " 0.1\nv " + x + " " + y + " 0.2\nv 0.9 " + y +
              " 0.1\nv " + x + " 0.9 0.3\nf -4 -3 -2\nf -4 -2 -1\n";
  }
  const std::vector<std::pair<std::string, std::string>> files = {
      {"one-point", "o h\nv 0.5 0.5 0.5\nf 1 1 1\n"},
      {"two-points", "o h\nv 0 0 0\nv 1 1 1\nf 1 2 2\n"},
      {"collinear", "o h\nv 0 0 0\nv 0.5 0.5 0.5\nv 1 1 1\nf 1 2 3\n"},
      {"coplanar-1000", coplanar},
      {"duplicates-1000", duplicates},
      {"cloud-20000", cloud},
      {"groups-3000", groups},
      {"nan", "o h\nv nan 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3 4\n"},
      {"inf", "o h\nv inf 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3 4\n"},
      {"huge-1e308", "o h\nv -1e308 -1e308 -1e308\nv 1e308 -1e308 -1e308\nv 0 1e308 -1e308\nv 0 0 1e308\nf 1 2 3 4\n"},
      {"huge-1e38", "o h\nv -1e38 -1e38 -1e38\nv 1e38 -1e38 -1e38\nv 0 1e38 -1e38\nv 0 0 1e38\nf 1 2 3 4\n"},
      {"tiny-1e-300", "o h\nv 0 0 0\nv 1e-300 0 0\nv 0 1e-300 0\nv 0 0 1e-300\nf 1 2 3 4\n"},
      {"index-out-of-range", "o h\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"},
      {"index-negative-huge", "o h\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -99999999999\n"},
      {"index-zero", "o h\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"},
      {"groups-only", "o a\no b\ng c\n"},
      {"empty", ""},
      {"binary-garbage", random_bytes(4096, 23)},
      {"vertex-words", "o h\nv a b c\nf 1 1 1\n"},
      {"long-line-900k", "# " + std::string(900000, 'x') + "\no h\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3 4\n"},
  };
  for (const auto& [name, content] : files) audit(name, "h.obj", content);
  for (const std::string& kind : special_kinds()) {
    HostileCase& c = audit("special-" + kind, "", "");
    c.args[2] = special_input(c, kind, "obj");
  }
}

/// `command QUAD args...`: a valid scene with one hostile value.
inline void add_command_line_cases(HostileCorpus& corpus) {
  const std::string cat = "cli";
  const auto on_quad = [&](const std::string& name, std::vector<std::string> args) -> HostileCase& {
    HostileCase& c = corpus.add(cat, name);
    const std::string quad = HostileCorpus::input(c, "s.obj", kQuadObj);
    for (std::string& a : args) {
      if (a.compare(0, 4, "QUAD") == 0) a = quad + a.substr(4);
      if (a.compare(0, 4, "OUT/") == 0) a = c.out() + a.substr(3);
      if (a.compare(0, 6, "SCENE/") == 0) a = c.scene() + a.substr(5);
    }
    c.args = args;
    if (args[0] == "audit" || args[0] == "bench") c.allowed_exits = {0, 1, 2};
    return c;
  };
  const std::vector<std::string> decompose = {"decompose", "QUAD", "-o", "OUT/h.obj", "-q"};
  const auto plus = [](std::vector<std::string> base, const std::vector<std::string>& more) {
    base.insert(base.end(), more.begin(), more.end());
    return base;
  };
  for (const char* v : {"-1", "0", "nan", "inf", "-inf", "1e400", "1e-300", "1e300", "banana", "", "0x10"})
    on_quad(std::string("tol-") + (*v ? v : "empty"), {"info", "QUAD", "--tol", v});
  for (const char* option : {"--agent-radius", "--max-deviation"})
    for (const char* v : {"-1", "nan", "inf", "1e308", "1e-300"})
      on_quad(std::string("decompose") + option + "-" + v, plus(decompose, {option, v}));
  for (const char* option : {"--agent-radius", "--max-deviation"})
    for (const char* v : {"nan", "1e308", "-1"})
      on_quad(std::string("audit") + option + "-" + v,
              {"audit", "QUAD", "SCENE/s.obj", "--resolution", "0.1", "--proxies", "50", option, v});
  const std::vector<std::pair<std::string, std::vector<std::string>>> decompose_values = {
      {"threads-4", {"--threads", "4"}},
      {"tries-0", {"--tries", "0"}},
      {"tries-65537", {"--tries", "65537"}},
      {"max-hull-vertices-7", {"--max-hull-vertices", "7"}},
      {"max-hull-vertices-2e9", {"--max-hull-vertices", "2000000000"}},
      {"seed-minus-1", {"--seed", "-1"}},
      {"seed-2pow64", {"--seed", "18446744073709551616"}},
      {"reach-nan", {"--reach", "nan"}},
      {"reach-1e-300", {"--reach", "1e-300"}},
      {"bar-length-1e-300", {"--bar-length", "1e-300"}},
      {"prism-cap-1e308", {"--prism-cap", "1e308"}},
      {"near-merge-inf", {"--near-merge", "inf"}},
      {"max-file-size-10", {"--max-file-size", "10"}},
      {"max-file-size-max", {"--max-file-size", "18446744073709551615"}},
      {"max-file-size-2pow64", {"--max-file-size", "18446744073709551616"}},
      {"max-node-depth-0", {"--max-node-depth", "0"}},
      {"max-node-depth-1", {"--max-node-depth", "1"}},
      {"max-triangles-1", {"--max-triangles", "1"}},
  };
  for (const auto& [name, more] : decompose_values) on_quad("decompose-" + name, plus(decompose, more));
  // Paths.
  on_quad("input-missing", {"info", "SCENE/missing.obj"});
  on_quad("input-directory", {"info", "SCENE/"});
  on_quad("input-trailing-slash", {"info", "QUAD/"});
  on_quad("input-empty-string", {"info", ""});
  on_quad("input-dev-stdin", {"info", "/dev/stdin"});
  on_quad("input-100k-name", {"info", "SCENE/" + std::string(100000, 'a') + ".obj"});
  on_quad("output-missing-folder", {"decompose", "QUAD", "-o", "OUT/no/such/folder/h.obj", "-q"});
  on_quad("output-is-directory", {"decompose", "QUAD", "-o", "OUT/", "-q"});
  on_quad("output-under-proc", {"decompose", "QUAD", "-o", "/proc/self/hullcover-h.obj", "-q"});
  on_quad("output-empty-string", {"decompose", "QUAD", "-o", "", "-q"});
  on_quad("json-missing-folder", plus(decompose, {"--json", "OUT/no/such/h.json"}));
  on_quad("world-is-directory", plus(decompose, {"--world", "OUT/"}));
  {
    // A read-only folder (root, which runs CI, may write there anyway).
    HostileCase& c = on_quad("output-read-only-folder", {"decompose", "QUAD", "-o", "OUT/ro/h.obj", "-q"});
    std::filesystem::create_directories(c.out() + "/ro");
    std::filesystem::permissions(c.out() + "/ro",
                                 std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
  }
  // query values on a valid runtime file.
  const std::vector<std::pair<std::string, std::vector<std::string>>> queries = {
      {"capsule-axis-zero", {"--capsule", "0.5,0.5,0.5,0.2,0.3,0,0,0"}},
      {"capsule-axis-nan", {"--capsule", "0.5,0.5,0.5,0.2,0.3,nan,0,0"}},
      {"sphere-radius-1e308", {"--sphere", "0,0,0,1e308"}},
      {"sphere-centre-inf", {"--sphere", "inf,0,0,1"}},
      {"sphere-three-values", {"--sphere", "0,0,0"}},
      {"ray-max-nan", {"--ray", "0,0,0,1,0,0,nan"}},
      {"ray-direction-denormal", {"--ray", "-1,0.5,0.5,1e-320,0,0"}},
      {"box-extents-1e308", {"--box", "0,0,0,1e308,1e308,1e308"}},
      {"max-contacts-0", {"--sphere", "0.5,0.5,0.5,1", "--max-contacts", "0"}},
      {"two-shapes", {"--sphere", "0,0,0,1", "--ray", "0,0,0,1,0,0"}},
  };
  for (const auto& [name, more] : queries) {
    HostileCase& c = corpus.add(cat, "query-" + name);
    c.args = plus({"query", HostileCorpus::input(c, "w.hcw", hcw_boxes({{0.0, 1.0}}))}, more);
  }
  // bench and demo.
  for (const char* units : {"nan", "-5", "0", "1e400"})
    on_quad(std::string("bench-units-") + units, {"bench", "QUAD@" + std::string(units), "--out", "OUT/b", "-q"});
  on_quad("bench-missing-scene", {"bench", "SCENE/missing.obj", "--out", "OUT/b", "-q"});
  on_quad("bench-agent-radius-1e400", {"bench", "QUAD", "--agent-radius", "1e400", "--out", "OUT/b", "-q"});
  on_quad("bench-out-under-proc", {"bench", "QUAD", "--out", "/proc/self/hullcover-bench", "-q", "--query-poses", "1",
                                   "--query-seconds", "0.001"});
  on_quad("demo-out-under-proc", {"demo", "--out", "/proc/self/hullcover-demo"});
  on_quad("demo-out-is-file", {"demo", "--out", "QUAD"});
}

} // namespace hullcover::test
