#pragma once
// The scene-file half of the hostile corpus (hostile_corpus.h): OBJ, PLY,
// STL and glTF/GLB files that lie about their sizes, nest without end, hold
// non-numbers, or name files outside their folder. Each runs `hullcover
// info` (every command imports the same way); a few run `decompose` too, so
// the whole pipeline meets the survivors.

#include "hostile_corpus.h"

#include <array>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace hullcover::test {

inline const char* const kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

inline HostileCase& info_case(HostileCorpus& corpus, const std::string& category, const std::string& name,
                              const std::string& file, const std::string& content) {
  HostileCase& c = corpus.add(category, name);
  c.args = {"info", HostileCorpus::input(c, file, content)};
  return c;
}

inline HostileCase& decompose_case(HostileCorpus& corpus, const std::string& category, const std::string& name,
                                   const std::string& file, const std::string& content) {
  HostileCase& c = corpus.add(category, name);
  c.args = {"decompose", HostileCorpus::input(c, file, content),
            "-o",        c.out() + "/h.obj",
            "--json",    c.out() + "/h.json",
            "--world",   c.out() + "/w.hcw",
            "-q"};
  return c;
}

/// One case per reference kind: the file `make(reference)` names the canary
/// that way. Encoded kinds must be refused only where the format `decodes`
/// them, absolute ones only where it does not `rebase` them on the folder
/// (see ReferenceKind); the rest always. None may be read.
template <class Make>
void add_reference_cases(HostileCorpus& corpus, const std::string& category, const std::string& prefix,
                         const std::string& file, const std::string& ext, bool decodes, bool rebases,
                         const Make& make) {
  for (const ReferenceKind& kind : reference_kinds()) {
    HostileCase& c = corpus.add(category, prefix + kind.name);
    c.args = {"info", HostileCorpus::input(c, file, make(reference_text(c, kind.name, ext)))};
    c.must_refuse_outside = !(kind.encoded && !decodes) && !(kind.absolute && rebases);
  }
}

inline void add_obj_cases(HostileCorpus& corpus) {
  const std::string cat = "obj";
  const std::string tri = kTriangleObj;
  info_case(corpus, cat, "control-quad", "s.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n").expected_exit = 0;
  decompose_case(corpus, cat, "control-decompose", "s.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n")
      .expected_exit = 0;
  {
    HostileCase& c = corpus.add(cat, "control-mtllib-beside");
    HostileCorpus::input(c, "m.mtl", "newmtl red\nKd 1 0 0\n");
    c.args = {"info", HostileCorpus::input(c, "s.obj", "mtllib m.mtl\nusemtl red\n" + tri)};
    c.expected_exit = 0;
  }
  const std::vector<std::pair<std::string, std::string>> files = {
      {"vertex-words", "v a b c\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"},
      {"vertex-two-coords", "v 0 0\nv 1 0\nv 0 1\nf 1 2 3\n"},
      {"face-one-corner", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1\n"},
      {"face-no-corner", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf\n"},
      {"face-index-zero", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"},
      {"face-slash-junk", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/x/y 2//9 3/-5\n"},
      {"face-index-4e9", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4000000000\n"},
      {"face-index-1e20", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 100000000000000000000\n"},
      {"face-index-minus-1e6", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -1000000\n"},
      {"face-index-int-min", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -2147483648\n"},
      {"nan", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"},
      {"inf", "v inf 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"},
      {"minus-inf", "v 0 -inf 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"},
      {"coords-1e308", "v 1e308 0 0\nv -1e308 0 0\nv 0 1e308 0\nf 1 2 3\n"},
      {"coords-1e39", "v 1e39 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n"},
      {"coords-1e38", "v 1e38 0 0\nv -1e38 0 0\nv 0 3e38 0\nf 1 2 3\n"},
      {"coords-denormal", "v 0 0 0\nv 1e-320 0 0\nv 0 1e-320 0\nf 1 2 3\n"},
      {"only-vertices", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"},
      {"empty", ""},
      {"whitespace-only", "   \n\t\n \r\n  "},
      {"comments-only", "# nothing\n# at all\n"},
      {"binary-garbage", random_bytes(4096, 16)},
      {"nul-bytes", std::string("v 0 0 0\0\0\0\nv 1 0\0 0\nv 0 1 0\nf 1 2\0 3\n", 36)},
      {"cr-line-ends", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r"},
      {"backslash-continuation", "v 0 \\\n0 0\nv 1 0 0\nv 0 1 0\nf 1 \\\n2 3\n"},
      {"long-comment-900k", tri + "# " + std::string(900000, 'x') + "\n"},
      {"long-object-name-500k", "o " + std::string(500000, 'n') + "\n" + tri},
  };
  for (const auto& [name, content] : files) info_case(corpus, cat, name, "s.obj", content);
  std::string corners = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3";
  for (int i = 0; i < 300000; ++i) corners += " 1";
  info_case(corpus, cat, "face-300k-corners", "s.obj", corners + "\n");
  std::string numbers = "v 0 0 0";
  for (int i = 0; i < 300000; ++i) numbers += " 1";
  info_case(corpus, cat, "vertex-300k-numbers", "s.obj", numbers + "\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  std::string usemtl = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  for (int i = 0; i < 100000; ++i) usemtl += "usemtl m\n";
  info_case(corpus, cat, "usemtl-spam-100k", "s.obj", usemtl + "f 1 2 3\n");
  std::string usemtl_faces = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  for (int i = 0; i < 40000; ++i) usemtl_faces += "usemtl m" + std::to_string(i) + "\nf 1 2 3\n";
  info_case(corpus, cat, "usemtl-distinct-40k", "s.obj", usemtl_faces);
  std::string objects = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  for (int i = 0; i < 20000; ++i) objects += "o g" + std::to_string(i) + "\nf 1 2 3\n";
  info_case(corpus, cat, "object-spam-20k", "s.obj", objects);
  decompose_case(corpus, cat, "decompose-coords-1e38", "s.obj", "v 1e38 0 0\nv -1e38 0 0\nv 0 3e38 0\nf 1 2 3\n");
  decompose_case(corpus, cat, "decompose-all-degenerate", "s.obj",
                 "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nf 1 2 3\nf 2 3 4\nf 1 1 1\n");
  {
    // decompose imports as info does; with --materials the library matters.
    HostileCase& c = decompose_case(corpus, cat, "decompose-materials-mtllib-dotdot", "s.obj",
                                    "mtllib ../outside/canary.mtl\nusemtl stolen\n" + tri);
    c.args.push_back("--materials");
    c.must_refuse_outside = true;
  }
  add_reference_cases(corpus, cat, "mtllib-", "s.obj", "mtl", false, true,
                      [&](const std::string& ref) { return "mtllib " + ref + "\nusemtl stolen\n" + tri; });
}

inline std::string ply_header(const std::string& format, const std::string& elements) {
  return "ply\nformat " + format + " 1.0\n" + elements + "end_header\n";
}

inline void add_ply_cases(HostileCorpus& corpus) {
  const std::string cat = "ply";
  const std::string vertex = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
  const std::string face = "element face 1\nproperty list uchar int vertex_indices\n";
  const std::string ascii_body = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  std::string le_body = HostileCorpus::triangle_bytes(1) + std::string("\3", 1);
  for (std::uint32_t i : {0u, 1u, 2u}) put_u32(le_body, i);
  std::string be_body = le_body; // every 4-byte word reversed; the list's count byte (at 36) stays
  for (std::size_t at = 0; at + 4 <= be_body.size(); at += at == 32 ? 5 : 4) {
    std::swap(be_body[at], be_body[at + 3]);
    std::swap(be_body[at + 1], be_body[at + 2]);
  }
  info_case(corpus, cat, "control-ascii", "s.ply", ply_header("ascii", vertex + face) + ascii_body).expected_exit = 0;
  info_case(corpus, cat, "control-binary-le", "s.ply", ply_header("binary_little_endian", vertex + face) + le_body)
      .expected_exit = 0;
  info_case(corpus, cat, "control-binary-be", "s.ply", ply_header("binary_big_endian", vertex + face) + be_body)
      .expected_exit = 0;
  std::string comments = "ply\nformat ascii 1.0\n";
  while (comments.size() < 200000) comments += "comment no end of the header in sight\n";
  std::string huge_list = ply_header("binary_little_endian", vertex + "element face 1\nproperty list uint int vi\n") +
                          HostileCorpus::triangle_bytes(1);
  put_u32(huge_list, 0xffffffffu);
  put_u32(huge_list, 0);
  std::string list_count_2pow27 =
      ply_header("binary_little_endian", vertex + "element face 1\nproperty list uint int vi\n") +
      HostileCorpus::triangle_bytes(1);
  put_u32(list_count_2pow27, 1u << 27);
  for (std::uint32_t i : {0u, 1u, 2u}) put_u32(list_count_2pow27, i);
  std::string nan_body;
  for (int i = 0; i < 9; ++i) put_u32(nan_body, 0x7fc00000u); // float32 quiet NaN
  nan_body += le_body.substr(36);
  const std::vector<std::pair<std::string, std::string>> files = {
      {"header-cut", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nprop"},
      {"no-end-header-200k", comments},
      {"no-format", "ply\n" + vertex + face + "end_header\n" + ascii_body},
      {"format-unknown", ply_header("binary_middle_endian", vertex + face) + ascii_body},
      {"magic-only", "ply\n"},
      {"not-ply-magic", "plx\nformat ascii 1.0\nend_header\n"},
      {"vertex-count-4e9-ascii", ply_header("ascii", "element vertex 4000000000\nproperty float x\n") + "0\n"},
      {"vertex-count-20-digits",
       ply_header("ascii", "element vertex 99999999999999999999\nproperty float x\n") + "0\n"},
      {"vertex-count-negative", ply_header("ascii", "element vertex -3\nproperty float x\n") + "0\n"},
      {"property-unknown-type", ply_header("ascii", "element vertex 3\nproperty banana x\n") + "0\n0\n0\n"},
      {"list-float-count", ply_header("ascii", vertex + "element face 1\nproperty list float int vi\n") + ascii_body},
      {"property-before-element", ply_header("ascii", "property float x\n" + vertex) + ascii_body},
      {"binary-short-data", ply_header("binary_little_endian", vertex + face) + le_body.substr(0, 24)},
      {"binary-list-count-4e9", huge_list},
      {"ascii-list-count-4e9", ply_header("ascii", vertex + face) + "0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n"},
      // Counts that fit a 4 GiB address space: what a list of them costs shows.
      {"binary-list-count-2pow27", list_count_2pow27},
      {"ascii-list-count-2pow26", ply_header("ascii", vertex + "element face 1\nproperty list uint int vi\n") +
                                      "0 0 0\n1 0 0\n0 1 0\n67108864 0 1 2\n"},
      {"face-index-out-of-range", ply_header("ascii", vertex + face) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 99999\n"},
      {"face-index-negative", ply_header("ascii", vertex + face) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 -7\n"},
      {"binary-nan-vertices", ply_header("binary_little_endian", vertex + face) + nan_body},
      {"faces-without-vertices", ply_header("ascii", face) + "3 0 1 2\n"},
      {"ascii-vertex-words", ply_header("ascii", vertex + face) + "a b c\nd e f\ng h i\n3 0 1 2\n"},
  };
  for (const auto& [name, content] : files) info_case(corpus, cat, name, "s.ply", content);
}

inline std::string binary_stl(std::uint32_t declared, const std::vector<std::array<float, 12>>& facets,
                              const std::string& header = std::string(80, ' ')) {
  std::string out = header.substr(0, 80);
  out.resize(80, ' ');
  put_u32(out, declared);
  for (const auto& f : facets) {
    out.append(reinterpret_cast<const char*>(f.data()), 48);
    out += std::string(2, '\0');
  }
  return out;
}

inline void add_stl_cases(HostileCorpus& corpus) {
  const std::string cat = "stl";
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const std::array<float, 12> good = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::array<float, 12> nan_normal = {nan, nan, nan, 0, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::array<float, 12> nan_vertex = {0, 0, 1, nan, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::array<float, 12> inf_vertex = {0, 0, 1, 0, 0, 0, inf, 0, 0, 0, 1, 0};
  const std::string facet =
      "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n";
  info_case(corpus, cat, "control-binary", "s.stl", binary_stl(1, {good})).expected_exit = 0;
  info_case(corpus, cat, "control-ascii", "s.stl", "solid s\n" + facet + "endsolid s\n").expected_exit = 0;
  const std::vector<std::pair<std::string, std::string>> files = {
      {"count-larger", binary_stl(5, {good})},
      {"count-smaller", binary_stl(1, {good, good, good})},
      {"count-zero", binary_stl(0, {})},
      {"count-max", binary_stl(0xffffffffu, {good})},
      {"shorter-than-header", std::string(40, 'x')},
      {"solid-header-count-lies", binary_stl(1000000, {good, good}, "solid but binary")},
      {"ascii-truncated", "solid s\n" + facet.substr(0, 50)},
      {"ascii-solid-only", "solid"},
      {"ascii-no-endsolid", "solid s\n" + facet + facet},
      {"ascii-coords-1e39",
       "solid s\nfacet normal 0 0 1\nouter loop\nvertex 1e39 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
       "endloop\nendfacet\nendsolid s\n"},
      {"ascii-vertex-outside-facet", "solid s\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendsolid s\n"},
      {"ascii-five-vertex-loop",
       "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
       "vertex 1 1 0\nvertex 2 2 0\nendloop\nendfacet\nendsolid s\n"},
      {"nan-normals", binary_stl(1, {nan_normal})},
      {"nan-vertex", binary_stl(1, {nan_vertex})},
      {"inf-vertex", binary_stl(1, {inf_vertex})},
  };
  for (const auto& [name, content] : files) info_case(corpus, cat, name, "s.stl", content);
}

} // namespace hullcover::test
