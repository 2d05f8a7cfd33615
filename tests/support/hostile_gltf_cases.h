#pragma once
// The glTF/GLB part of the hostile corpus (hostile_corpus.h): node
// hierarchies that are deep, cyclic or shared, JSON nested past any stack,
// buffers and images named outside the folder, data URIs that are not,
// sizes and GLB chunk lengths that lie, and a small file that places
// millions of triangles by instancing one mesh.

#include "hostile_scene_cases.h"

#include <string>
#include <utility>
#include <vector>

namespace hullcover::test {

inline void add_gltf_cases(HostileCorpus& corpus) {
  const std::string cat = "gltf";
  const auto with = [](auto change) {
    GltfParts p;
    change(p);
    return gltf_json(p);
  };
  info_case(corpus, cat, "control-data-uri", "s.gltf", gltf_json({})).expected_exit = 0;
  {
    HostileCase& c = corpus.add(cat, "control-buffer-beside");
    HostileCorpus::input(c, "bin/t.bin", HostileCorpus::triangle_bytes(1));
    c.args = {"info", HostileCorpus::input(c, "s.gltf", with([](GltfParts& p) { p.uri = "bin/t.bin"; }))};
    c.expected_exit = 0;
  }
  {
    // The limit binds the files a scene refers to as well as the scene.
    HostileCase& c = corpus.add(cat, "buffer-beside-over-max-file-size");
    HostileCorpus::input(c, "t.bin", HostileCorpus::triangle_bytes(1000));
    const std::string scene = HostileCorpus::input(c, "s.gltf", with([](GltfParts& p) {
                                                     p.uri = "t.bin";
                                                     p.buffer_bytes = 36000;
                                                   }));
    c.args = {"info", scene, "--max-file-size", "10000"};
  }
  const std::string glb_json = with([](GltfParts& p) { p.uri.clear(); });
  const std::string good_glb = glb(glb_json, HostileCorpus::triangle_bytes(1));
  info_case(corpus, cat, "control-glb", "s.glb", good_glb).expected_exit = 0;
  decompose_case(corpus, cat, "control-decompose-glb", "s.glb", good_glb).expected_exit = 0;

  add_reference_cases(corpus, cat, "buffer-", "s.gltf", "bin", true, false, [&](const std::string& ref) {
    std::string escaped; // a JSON string: '\\' stands for one backslash
    for (char ch : ref) escaped += ch == '\\' ? std::string("\\\\") : std::string(1, ch);
    return with([&](GltfParts& p) { p.uri = escaped; });
  });
  // Images: '..' and absolute paths are refused on the text; a link is left
  // unread (Assimp's glTF reader opens no external image), which the watch
  // on the canary folder confirms.
  for (const char* kind : {"dotdot", "absolute", "symlink-file"}) {
    HostileCase& c = corpus.add(cat, std::string("image-") + kind);
    const std::string images = R"(,"images":[{"uri":")" + reference_text(c, kind, "txt") + R"("}])";
    c.args = {"info", HostileCorpus::input(c, "s.gltf", with([&](GltfParts& p) { p.extra = images; }))};
    c.must_refuse_outside = std::string(kind) != "symlink-file";
  }
  {
    HostileCase& c = corpus.add(cat, "glb-buffer-dotdot");
    c.args = {"info", HostileCorpus::input(
                          c, "s.glb", glb(with([](GltfParts& p) { p.uri = "../outside/canary.bin"; }), std::string()))};
    c.must_refuse_outside = true;
  }

  // Node hierarchies.
  const auto chain = [](int depth) {
    std::string nodes = "[";
    for (int i = 0; i < depth; ++i)
      nodes += i + 1 < depth ? R"({"children":[)" + std::to_string(i + 1) + "]}," : R"({"mesh":0}])";
    return nodes;
  };
  const std::vector<std::pair<std::string, GltfParts>> hierarchies = {
      {"nodes-chain-100k", {data_uri(HostileCorpus::triangle_bytes(1)), 36, chain(100000), "[0]", "3", ""}},
      {"nodes-chain-300", {data_uri(HostileCorpus::triangle_bytes(1)), 36, chain(300), "[0]", "3", ""}},
      {"nodes-cycle",
       {data_uri(HostileCorpus::triangle_bytes(1)), 36, R"([{"children":[1],"mesh":0},{"children":[0]}])", "[0]", "3",
        ""}},
      {"node-own-child",
       {data_uri(HostileCorpus::triangle_bytes(1)), 36, R"([{"children":[0],"mesh":0}])", "[0]", "3", ""}},
      {"node-two-parents",
       {data_uri(HostileCorpus::triangle_bytes(1)), 36, R"([{"children":[2]},{"children":[2]},{"mesh":0}])", "[0,1]",
        "3", ""}},
      {"node-child-out-of-range",
       {data_uri(HostileCorpus::triangle_bytes(1)), 36, R"([{"children":[7],"mesh":0}])", "[0]", "3", ""}},
      {"node-child-negative",
       {data_uri(HostileCorpus::triangle_bytes(1)), 36, R"([{"children":[-1],"mesh":0}])", "[0]", "3", ""}},
      {"node-mesh-out-of-range", {data_uri(HostileCorpus::triangle_bytes(1)), 36, R"([{"mesh":99}])", "[0]", "3", ""}},
      {"scene-root-out-of-range", {data_uri(HostileCorpus::triangle_bytes(1)), 36, R"([{"mesh":0}])", "[5]", "3", ""}},
      {"nodes-not-array", {data_uri(HostileCorpus::triangle_bytes(1)), 36, R"({"0":{"mesh":0}})", "[0]", "3", ""}},
  };
  for (const auto& [name, parts] : hierarchies) info_case(corpus, cat, name, "s.gltf", gltf_json(parts));

  // JSON itself.
  std::string in_string = gltf_json({});
  in_string.insert(1, R"("extras_text":")" + std::string(100000, '[') + R"(",)");
  const std::vector<std::pair<std::string, std::string>> texts = {
      {"json-nesting-100k", std::string(100000, '[') + std::string(100000, ']')},
      {"json-nesting-100k-unclosed", "{\"a\":" + std::string(100000, '[')},
      {"json-brackets-in-string", in_string},
      {"json-truncated", gltf_json({}).substr(0, 200)},
      {"json-array", "[]"},
      {"json-null", "null"},
      {"json-invalid-utf8", "{\"asset\":{\"version\":\"2.0\xff\xfe\"}}"},
      {"json-binary-garbage", random_bytes(4096, 7)},
  };
  for (const auto& [name, content] : texts) info_case(corpus, cat, name, "s.gltf", content);

  // Data URIs and declared sizes.
  const std::vector<std::pair<std::string, std::string>> sizes = {
      {"data-uri-no-comma", with([](GltfParts& p) { p.uri = "data:application/octet-stream;base64"; })},
      {"data-uri-bad-chars",
       with([](GltfParts& p) { p.uri = "data:application/octet-stream;base64,@@@@!!!!" + std::string(44, '*'); })},
      {"data-uri-short", with([](GltfParts& p) { p.uri = data_uri(std::string(12, '\0')); })},
      {"data-uri-empty", with([](GltfParts& p) { p.uri = "data:;base64,"; })},
      {"data-uri-not-base64",
       with([](GltfParts& p) { p.uri = "data:application/octet-stream," + std::string(48, 'A'); })},
      {"data-uri-length-huge", with([](GltfParts& p) { p.buffer_bytes = 1ull << 40; })},
      {"accessor-count-beyond-buffer", with([](GltfParts& p) { p.count = "1000"; })},
      {"accessor-count-3e9", with([](GltfParts& p) { p.count = "3000000000"; })},
      {"accessor-count-negative", with([](GltfParts& p) { p.count = "-3"; })},
      {"accessor-count-float", with([](GltfParts& p) { p.count = "3.5"; })},
      {"buffer-without-uri", with([](GltfParts& p) { p.uri.clear(); })},
  };
  for (const auto& [name, content] : sizes) info_case(corpus, cat, name, "s.gltf", content);
  std::string component = gltf_json({});
  component.replace(component.find("5126"), 4, "9999");
  info_case(corpus, cat, "accessor-component-bogus", "s.gltf", component);
  std::string scalar = gltf_json({});
  scalar.replace(scalar.find("\"VEC3\""), 6, "\"SCALAR\"");
  info_case(corpus, cat, "accessor-position-scalar", "s.gltf", scalar);
  std::string no_view = with([](GltfParts& p) { p.count = "300000000"; });
  no_view.replace(no_view.find("\"bufferView\":0,"), 15, "");
  info_case(corpus, cat, "accessor-no-view-300m", "s.gltf", no_view);
  std::string indices = gltf_json({});
  indices.replace(indices.find(R"("attributes":{"POSITION":0}})"), 28, R"("attributes":{"POSITION":0},"indices":1})");
  indices.replace(indices.find("}],\"bufferViews\""), 3,
                  R"(},{"componentType":5125,"count":12000000,"type":"SCALAR"}],)");
  info_case(corpus, cat, "indices-no-view-12m", "s.gltf", indices);
  std::string view = gltf_json({});
  view.replace(view.find(R"("byteLength":36}],"buffers")"), 16, R"("byteLength":1000})");
  info_case(corpus, cat, "view-beyond-buffer", "s.gltf", view);
  std::string negative = gltf_json({});
  negative.replace(negative.find(R"("buffers":[{"byteLength":36)"), 27, R"("buffers":[{"byteLength":-36)");
  info_case(corpus, cat, "buffer-byte-length-negative", "s.gltf", negative);

  // GLB chunk lengths.
  const auto glb_with = [&](auto change) {
    std::string bytes = good_glb;
    change(bytes);
    return bytes;
  };
  const std::vector<std::pair<std::string, std::string>> glbs = {
      {"glb-bad-magic", glb_with([](std::string& b) { b[0] = 'X'; })},
      {"glb-total-length-lies", glb_with([](std::string& b) { set_u32(b, 8, 0x7fffffffu); })},
      {"glb-json-length-lies", glb_with([](std::string& b) { set_u32(b, 12, 0xfffffff0u); })},
      {"glb-json-length-short", glb_with([](std::string& b) { set_u32(b, 12, 16); })},
      {"glb-json-length-zero", glb_with([](std::string& b) { set_u32(b, 12, 0); })},
      {"glb-bin-length-lies", glb_with([](std::string& b) { set_u32(b, b.size() - 36 - 8, 0x7ffffff0u); })},
      {"glb-version-1", glb_with([](std::string& b) { set_u32(b, 4, 1); })},
      {"glb-truncated-12", good_glb.substr(0, 12)},
      {"glb-truncated-half", good_glb.substr(0, good_glb.size() / 2)},
  };
  for (const auto& [name, content] : glbs) info_case(corpus, cat, name, "s.glb", content);

  // A mesh of 1,000 triangles placed by 1,300 nodes: 1.3 million triangles
  // (under the default --max-triangles of 4,194,304) from a 120 kB file.
  std::string nodes = "[", roots = "[";
  for (int i = 0; i < 1300; ++i) {
    nodes += (i ? "," : "") + std::string(R"({"mesh":0,"translation":[0,)") + std::to_string(2 * i) + ",0]}";
    roots += (i ? "," : "") + std::to_string(i);
  }
  info_case(corpus, cat, "instancing-1300x1000", "s.gltf",
            gltf_json({data_uri(HostileCorpus::triangle_bytes(1000)), 36000, nodes + "]", roots + "]", "3000", ""}));
}

} // namespace hullcover::test
