// The audit's reader of engine exports (.glb): the colliders an engine
// builds, read back exactly, and every damaged or hostile file refused with
// a message, never a crash or a read past the bytes.

#include "temp_dir.h"

#include "hullcover/validate/hull_set.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>

namespace {

using hullcover::test::TempDir;
using Json = nlohmann::json;

void append_word(std::string& out, std::uint32_t word) {
  char bytes[4];
  std::memcpy(bytes, &word, 4);
  out.append(bytes, 4);
}

// A GLB of JSON text `json` and binary chunk `bin`.
std::string glb_of_text(std::string json, const std::string& bin) {
  json.resize((json.size() + 3) / 4 * 4, ' ');
  std::string out;
  append_word(out, 0x46546C67);
  append_word(out, 2);
  append_word(out, static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
  append_word(out, static_cast<std::uint32_t>(json.size()));
  append_word(out, 0x4E4F534A);
  out += json;
  append_word(out, static_cast<std::uint32_t>(bin.size()));
  append_word(out, 0x004E4942);
  out += bin;
  return out;
}

std::string glb_of(const Json& gltf, const std::string& bin) { return glb_of_text(gltf.dump(), bin); }

// Two unit tetrahedra, the second declared a collider by both extensions
// and placed by its node's translation (4, 0, 0); the first is a render
// mesh (no collider), which the reader must leave out.
struct TwoTetrahedra {
  Json gltf;
  std::string bin;
  TwoTetrahedra() {
    const float positions[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    const std::uint32_t indices[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    bin.append(reinterpret_cast<const char*>(positions), sizeof positions);
    bin.append(reinterpret_cast<const char*>(indices), sizeof indices);
    gltf = Json::parse(R"({
      "asset": {"version": "2.0"},
      "extensionsUsed": ["KHR_physics_rigid_bodies", "OMI_physics_body", "OMI_physics_shape"],
      "extensions": {"OMI_physics_shape": {"shapes": [{"type": "convex", "convex": {"mesh": 0}}]}},
      "scene": 0, "scenes": [{"nodes": [0, 1]}],
      "nodes": [
        {"name": "render", "mesh": 0},
        {"name": "hull", "mesh": 0, "translation": [4, 0, 0],
         "extensions": {"KHR_physics_rigid_bodies": {"collider": {"geometry": {"node": 1, "convexHull": true}}},
                        "OMI_physics_body": {"collider": {"shape": 0}}}}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
      "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0,0,0], "max": [1,1,1]},
        {"bufferView": 1, "componentType": 5125, "count": 12, "type": "SCALAR"}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 48}],
      "buffers": [{"byteLength": 96}]
    })");
  }
};

hullcover::Result<hullcover::validate::HullSet> read_bytes(const TempDir& dir, const std::string& bytes) {
  const std::string path = dir.path("hulls.glb");
  std::ofstream(path, std::ios::binary) << bytes;
  return hullcover::validate::load_hull_set(path);
}

TEST(HullSetGlb, ReadsTheDeclaredColliderOncePlacedByItsNode) {
  TempDir dir;
  const TwoTetrahedra t;
  const auto set = read_bytes(dir, glb_of(t.gltf, t.bin));
  ASSERT_TRUE(set.ok()) << set.status().message();
  ASSERT_EQ(set.value().hulls.size(), 1u); // declared twice, one collider; the render node is not a hull
  EXPECT_NEAR(set.value().hulls[0].box.min.x(), 4.0, 1e-12);
  EXPECT_NEAR(set.value().hulls[0].box.max.x(), 5.0, 1e-12);
}

TEST(HullSetGlb, WithoutDeclaredCollidersEveryMeshNodeIsAHull) {
  TempDir dir;
  TwoTetrahedra t;
  t.gltf["nodes"][1].erase("extensions");
  const auto set = read_bytes(dir, glb_of(t.gltf, t.bin));
  ASSERT_TRUE(set.ok()) << set.status().message();
  EXPECT_EQ(set.value().hulls.size(), 2u);
}

TEST(HullSetGlb, DamagedFilesAreRefusedWithAMessage) {
  TempDir dir;
  const std::vector<std::pair<const char*, std::function<void(TwoTetrahedra&)>>> cases =
      {
          {"accessor past its view", [](TwoTetrahedra& t) { t.gltf["accessors"][0]["count"] = 5; }},
          {"huge count", [](TwoTetrahedra& t) { t.gltf["accessors"][0]["count"] = 4000000000u; }},
          {"view past the chunk", [](TwoTetrahedra& t) { t.gltf["bufferViews"][1]["byteLength"] = 49; }},
          {"offset overflow", [](TwoTetrahedra& t) { t.gltf["bufferViews"][0]["byteOffset"] = 18446744073709551615u; }},
          {"index past the vertices", [](TwoTetrahedra& t) { t.bin[48] = 9; }},
          {"external buffer", [](TwoTetrahedra& t) { t.gltf["buffers"][0]["uri"] = "../../etc/passwd"; }},
          {"node cycle",
           [](TwoTetrahedra& t) {
    t.gltf["nodes"][0]["children"] = {1};
    t.gltf["nodes"][1]["children"] = {0};
           }},
          {"child of itself", [](TwoTetrahedra& t) { t.gltf["nodes"][1]["children"] = {1}; }},
          {"two parents",
           [](TwoTetrahedra& t) {
    t.gltf["nodes"].push_back(Json{{"children", {1}}});
    t.gltf["nodes"][0]["children"] = {1};
           }},
                                                                                 {"collider names no node",
                                                                                  [](TwoTetrahedra& t) {
    t.gltf["nodes"][1]["extensions"]["KHR_physics_rigid_bodies"]["collider"]["geometry"]["node"] = 7;
                                                                                  }},
      {"not triangles", [](TwoTetrahedra& t) { t.gltf["meshes"][0]["primitives"][0]["mode"] = 1; }},
      {"positions as shorts", [](TwoTetrahedra& t) { t.gltf["accessors"][0]["componentType"] = 5123; }},
      {"translation not numbers",
       [](TwoTetrahedra& t) {
    t.gltf["nodes"][1]["translation"] = {"a", 0, 0};
       }},
      {"beyond float range",
       [](TwoTetrahedra& t) {
    t.gltf["nodes"][1]["scale"] = {1e300, 1, 1};
       }},
      };
  for (const auto& [name, damage] : cases) {
    TwoTetrahedra t;
    damage(t);
    const auto set = read_bytes(dir, glb_of(t.gltf, t.bin));
    ASSERT_FALSE(set.ok()) << name;
    EXPECT_EQ(set.status().code(), hullcover::StatusCode::unreadable_file) << name << ": " << set.status().message();
    EXPECT_NE(set.status().message().find("hulls.glb"), std::string::npos) << name;
  }
  // Cut short anywhere: refused, never read past the end.
  const TwoTetrahedra t;
  const std::string whole = glb_of(t.gltf, t.bin);
  for (size_t size : {size_t{0}, size_t{11}, size_t{19}, size_t{40}, whole.size() - 97, whole.size() - 1})
    EXPECT_FALSE(read_bytes(dir, whole.substr(0, size)).ok()) << size;
  // JSON nested deeper than the reader's stack allows (built as text: the
  // test's own parser would overflow on it too).
  std::string json = t.gltf.dump();
  json.insert(json.size() - 1, ",\"extras\":" + std::string(100000, '[') + "0" + std::string(100000, ']'));
  const auto set = read_bytes(dir, glb_of_text(json, t.bin));
  ASSERT_FALSE(set.ok());
  EXPECT_EQ(set.status().code(), hullcover::StatusCode::limit_exceeded) << set.status().message();
}

} // namespace
