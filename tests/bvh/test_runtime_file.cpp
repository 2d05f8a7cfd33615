#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/bvh/hull_world.h"
#include "hullcover/bvh/runtime_file.h"

#include "covering_fixture.h"
#include "temp_dir.h"

#include "hullcover/mesh/scene_builder.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <random>

namespace hullcover::bvh {
namespace {

using test::TempDir;

std::vector<RuntimeHull> demo_hulls() {
  const auto d = test::decompose_and_check(demo_building());
  EXPECT_TRUE(d);
  return runtime_hulls(d->covering);
}

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(RuntimeFile, ReloadedWorldAnswersExactlyLikeTheBuiltOne) {
  TempDir dir;
  const std::vector<RuntimeHull> hulls = demo_hulls();
  ASSERT_TRUE(write_runtime_file(hulls, dir.path("w.hcw")).ok());
  const Result<std::vector<RuntimeHull>> loaded = read_runtime_file(dir.path("w.hcw"));
  ASSERT_TRUE(loaded.ok()) << loaded.status().message();
  // The surface flags come back as written (seams turn contact normals).
  int planes_off_surface = 0;
  for (size_t h = 0; h < hulls.size(); ++h) {
    ASSERT_EQ(loaded.value()[h].surface_planes, hulls[h].surface_planes) << h;
    for (bool on_surface : hulls[h].surface_planes) planes_off_surface += !on_surface;
  }
  EXPECT_GT(planes_off_surface, 0) << "the demo building has seams";
  const auto built = HullWorld::build(hulls).value();
  const auto reloaded = HullWorld::build(loaded.value()).value();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> x(-15, 5), y(-0.5, 3.5), z(-6, 6);
  int touching = 0;
  for (int i = 0; i < 300; ++i) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = Eigen::Vector3d(x(rng), y(rng), z(rng));
    const ContactRequest request{i % 2 ? QueryShape::sphere(0.4) : QueryShape::capsule(0.3, 0.5), pose, 8};
    ContactResult a, b;
    ASSERT_TRUE(built->contacts(request, a).ok());
    ASSERT_TRUE(reloaded->contacts(request, b).ok());
    ASSERT_EQ(a.contacts.size(), b.contacts.size());
    for (size_t k = 0; k < a.contacts.size(); ++k) {
      EXPECT_EQ(a.contacts[k].hull, b.contacts[k].hull);
      EXPECT_EQ(a.contacts[k].depth, b.contacts[k].depth);
      EXPECT_EQ(a.contacts[k].normal, b.contacts[k].normal);
    }
    touching += !a.contacts.empty();
    RayResult ra, rb;
    const RayRequest ray{pose.translation(), Eigen::Vector3d(z(rng), -3, x(rng)), 50};
    ASSERT_TRUE(built->ray_cast(ray, ra).ok());
    ASSERT_TRUE(reloaded->ray_cast(ray, rb).ok());
    EXPECT_EQ(ra.hit, rb.hit);
    if (ra.hit) {
      EXPECT_EQ(ra.first.t, rb.first.t);
    }
  }
  EXPECT_GT(touching, 30);
}

// Little-endian fields of the layout in runtime_file.h, for building files
// by hand.
std::uint64_t field(const std::string& bytes, size_t at, int size) {
  std::uint64_t v = 0;
  for (int k = 0; k < size; ++k) v |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes[at + k])) << (8 * k);
  return v;
}
void put(std::string& bytes, size_t at, std::uint64_t v, int size) {
  for (int k = 0; k < size; ++k) bytes[at + k] = static_cast<char>((v >> (8 * k)) & 0xff);
}

// A version 1 file (no surface flags, no sections) still loads: the same hulls, every
// plane counted as the surface's.
TEST(RuntimeFile, VersionOneFilesStillLoad) {
  TempDir dir;
  const std::vector<RuntimeHull> hulls = demo_hulls();
  ASSERT_TRUE(write_runtime_file(hulls, dir.path("v2.hcw")).ok());
  const std::string v2 = bytes_of(dir.path("v2.hcw"));
  constexpr size_t kHeader = 40;
  std::string payload;
  size_t at = kHeader;
  for (size_t h = 0; h < hulls.size(); ++h) {
    const std::uint64_t vertices = field(v2, at + 4, 4), facets = field(v2, at + 8, 4), planes = field(v2, at + 12, 4),
                        indices = field(v2, at + 16, 4);
    const size_t hull_bytes = 20 + 48 + vertices * 24 + planes * 32 + facets * 4 + indices * 4;
    payload += v2.substr(at, hull_bytes);
    at += hull_bytes;
    at += 4 + field(v2, at, 4); // version 2's surface flags, dropped
  }
  // Version 3's section table, dropped: one section 0 of every hull.
  ASSERT_EQ(at + 4 + 8 + 4 * hulls.size(), v2.size());
  std::string v1 = v2.substr(0, kHeader) + payload;
  put(v1, 8, 1, 4);               // version
  put(v1, 24, payload.size(), 8); // payload bytes
  std::uint64_t fnv = 0xcbf29ce484222325ull;
  for (char c : payload) fnv = (fnv ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
  put(v1, 32, fnv, 8);
  {
    std::ofstream out(dir.path("v1.hcw"), std::ios::binary);
    out.write(v1.data(), static_cast<std::streamsize>(v1.size()));
  }
  const Result<std::vector<RuntimeHull>> loaded = read_runtime_file(dir.path("v1.hcw"));
  ASSERT_TRUE(loaded.ok()) << loaded.status().message();
  ASSERT_EQ(loaded.value().size(), hulls.size());
  for (size_t h = 0; h < hulls.size(); ++h) {
    EXPECT_EQ(loaded.value()[h].shape.vertices, hulls[h].shape.vertices);
    EXPECT_TRUE(loaded.value()[h].surface_planes.empty());
  }
  // A damaged version 2 flag (neither 0 nor 1), checksum fixed up, is refused.
  std::string bad = v2;
  const size_t first_flags = kHeader + 20 + 48 + field(v2, kHeader + 4, 4) * 24 + field(v2, kHeader + 12, 4) * 32 +
                             field(v2, kHeader + 8, 4) * 4 + field(v2, kHeader + 16, 4) * 4;
  ASSERT_EQ(field(v2, first_flags, 4), field(v2, kHeader + 12, 4)) << "the first hull carries a flag per plane";
  bad[first_flags + 4] = 2;
  std::uint64_t bad_sum = 0xcbf29ce484222325ull;
  for (size_t i = kHeader; i < bad.size(); ++i)
    bad_sum = (bad_sum ^ static_cast<unsigned char>(bad[i])) * 0x100000001b3ull;
  put(bad, 32, bad_sum, 8);
  {
    std::ofstream out(dir.path("bad.hcw"), std::ios::binary);
    out.write(bad.data(), static_cast<std::streamsize>(bad.size()));
  }
  const Result<std::vector<RuntimeHull>> damaged = read_runtime_file(dir.path("bad.hcw"));
  EXPECT_EQ(damaged.status().code(), StatusCode::unreadable_file);
  EXPECT_NE(damaged.status().message().find("surface flag"), std::string::npos) << damaged.status().message();
  // A version beyond this build's is refused by name.
  put(v1, 8, kRuntimeFileVersion + 1, 4);
  {
    std::ofstream out(dir.path("v9.hcw"), std::ios::binary);
    out.write(v1.data(), static_cast<std::streamsize>(v1.size()));
  }
  const Result<std::vector<RuntimeHull>> newer = read_runtime_file(dir.path("v9.hcw"));
  EXPECT_EQ(newer.status().code(), StatusCode::unknown_format);
  EXPECT_NE(newer.status().message().find("version"), std::string::npos) << newer.status().message();
}

// Every kind of damage is refused with a message naming the file.
TEST(RuntimeFile, DamagedFilesAreRefusedWithAReason) {
  TempDir dir;
  const std::vector<RuntimeHull> hulls = demo_hulls();
  ASSERT_TRUE(write_runtime_file(hulls, dir.path("good.hcw")).ok());
  const std::string good = bytes_of(dir.path("good.hcw"));
  const auto refuse = [&](const std::string& name, const std::string& content, StatusCode code) {
    const std::string path = dir.write(name, content);
    const Result<std::vector<RuntimeHull>> r = read_runtime_file(path);
    ASSERT_FALSE(r.ok()) << name;
    EXPECT_EQ(r.status().code(), code) << name << ": " << r.status().message();
    EXPECT_EQ(r.status().message().rfind(path, 0), 0u) << r.status().message();
  };
  refuse("truncated.hcw", good.substr(0, good.size() - 7), StatusCode::unreadable_file);
  std::string flipped = good;
  flipped[good.size() / 2] ^= 0x10;
  refuse("flipped.hcw", flipped, StatusCode::unreadable_file);
  std::string magic = good;
  magic[0] = 'X';
  refuse("magic.hcw", magic, StatusCode::unknown_format);
  std::string newer = good;
  newer[8] = 9;
  refuse("newer.hcw", newer, StatusCode::unknown_format);
  refuse("empty.hcw", "", StatusCode::unknown_format);
  refuse("extra.hcw", good + "x", StatusCode::unreadable_file);
  EXPECT_EQ(read_runtime_file(dir.path("missing.hcw")).status().code(), StatusCode::file_not_found);

  // Well-formed files with bad content (the checksum is right for them).
  std::vector<RuntimeHull> bad = hulls;
  bad[3].shape.facets[0][1] = 9999;
  ASSERT_TRUE(write_runtime_file(bad, dir.path("index.hcw")).ok());
  EXPECT_NE(read_runtime_file(dir.path("index.hcw")).status().message().find("out of range"), std::string::npos);
  bad = hulls;
  bad[2].shape.vertices[1].x() = std::numeric_limits<double>::quiet_NaN();
  ASSERT_TRUE(write_runtime_file(bad, dir.path("nan.hcw")).ok());
  EXPECT_EQ(read_runtime_file(dir.path("nan.hcw")).status().code(), StatusCode::unreadable_file);
  bad = hulls;
  bad[1].shape.planes[0].normal *= 2.0;
  ASSERT_TRUE(write_runtime_file(bad, dir.path("normal.hcw")).ok());
  EXPECT_EQ(read_runtime_file(dir.path("normal.hcw")).status().code(), StatusCode::unreadable_file);
}

// A file of `version` around `payload`, its header's sizes and checksum right.
std::string runtime_file_bytes(std::uint32_t version, std::uint64_t hulls, const std::string& payload) {
  std::string bytes("HCWORLD\0", 8);
  bytes.resize(40 + payload.size());
  put(bytes, 8, version, 4);
  put(bytes, 12, 0, 4);
  put(bytes, 16, hulls, 8);
  put(bytes, 24, payload.size(), 8);
  std::uint64_t fnv = 0xcbf29ce484222325ull;
  for (char c : payload) fnv = (fnv ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
  put(bytes, 32, fnv, 8);
  bytes.replace(40, payload.size(), payload);
  return bytes;
}

// A section table: per section its id and hull indices, as written.
std::string section_table(const std::vector<std::pair<std::uint32_t, std::vector<std::uint32_t>>>& sections) {
  std::string t(4, '\0');
  put(t, 0, sections.size(), 4);
  for (const auto& [id, hulls] : sections) {
    std::string s(8 + 4 * hulls.size(), '\0');
    put(s, 0, id, 4);
    put(s, 4, hulls.size(), 4);
    for (size_t k = 0; k < hulls.size(); ++k) put(s, 8 + 4 * k, hulls[k], 4);
    t += s;
  }
  return t;
}

TEST(RuntimeFile, SectionsRoundTripAndOldFilesAreOneSection) {
  TempDir dir;
  const std::vector<RuntimeHull> hulls = demo_hulls();
  std::vector<std::uint32_t> section_of_hull;
  for (size_t h = 0; h < hulls.size(); ++h) section_of_hull.push_back(std::vector<std::uint32_t>{7, 3, 42}[h % 3]);
  ASSERT_TRUE(write_runtime_file(hulls, dir.path("cells.hcw"), &section_of_hull).ok());
  const Result<std::vector<RuntimeSection>> table = read_runtime_sections(dir.path("cells.hcw"));
  ASSERT_TRUE(table.ok()) << table.status().message();
  ASSERT_EQ(table.value().size(), 3u);
  for (const RuntimeSection& s : table.value()) {
    std::vector<int> expected;
    for (size_t h = 0; h < hulls.size(); ++h)
      if (section_of_hull[h] == s.id) expected.push_back(static_cast<int>(h));
    EXPECT_EQ(s.hulls, expected) << s.id;
    const Result<SectionHulls> section = read_runtime_section(dir.path("cells.hcw"), s.id);
    ASSERT_TRUE(section.ok()) << section.status().message();
    EXPECT_EQ(section.value().id, s.id);
    ASSERT_EQ(section.value().indices, expected);
    ASSERT_EQ(section.value().hulls.size(), expected.size());
    for (size_t k = 0; k < expected.size(); ++k) {
      EXPECT_EQ(section.value().hulls[k].shape.vertices, hulls[expected[k]].shape.vertices);
      EXPECT_EQ(section.value().hulls[k].surface_planes, hulls[expected[k]].surface_planes);
    }
  }
  EXPECT_EQ(table.value()[0].id, 3u) << "ascending ids";
  const Result<std::vector<RuntimeHull>> whole = read_runtime_file(dir.path("cells.hcw"));
  ASSERT_TRUE(whole.ok()) << whole.status().message();
  EXPECT_EQ(whole.value().size(), hulls.size());
  const Result<SectionHulls> missing = read_runtime_section(dir.path("cells.hcw"), 5);
  EXPECT_EQ(missing.status().code(), StatusCode::invalid_argument);
  EXPECT_NE(missing.status().message().find("no section 5"), std::string::npos) << missing.status().message();
  section_of_hull.pop_back();
  EXPECT_EQ(write_runtime_file(hulls, dir.path("short.hcw"), &section_of_hull).code(), StatusCode::invalid_argument);

  // Without sections: one section 0. A version 2 file (the same hulls, no
  // table) reads the same way.
  ASSERT_TRUE(write_runtime_file(hulls, dir.path("one.hcw")).ok());
  const std::string one = bytes_of(dir.path("one.hcw"));
  const std::string v2 = runtime_file_bytes(2, hulls.size(), one.substr(40, one.size() - 40 - (12 + 4 * hulls.size())));
  for (const std::string& path : {dir.path("one.hcw"), dir.write("v2.hcw", v2)}) {
    const Result<std::vector<RuntimeSection>> single = read_runtime_sections(path);
    ASSERT_TRUE(single.ok()) << single.status().message();
    ASSERT_EQ(single.value().size(), 1u);
    EXPECT_EQ(single.value()[0].id, 0u);
    EXPECT_EQ(single.value()[0].hulls.size(), hulls.size());
    const Result<SectionHulls> all = read_runtime_section(path, 0);
    ASSERT_TRUE(all.ok()) << all.status().message();
    EXPECT_EQ(all.value().hulls.size(), hulls.size());
  }
}

// A damaged section table (checksum right) is refused by every reader,
// saying what is wrong.
TEST(RuntimeFile, DamagedSectionTablesAreRefusedWithAReason) {
  TempDir dir;
  std::vector<RuntimeHull> hulls = demo_hulls();
  hulls.resize(4);
  ASSERT_TRUE(write_runtime_file(hulls, dir.path("good.hcw")).ok());
  const std::string good = bytes_of(dir.path("good.hcw"));
  const std::string hull_bytes = good.substr(40, good.size() - 40 - (12 + 4 * hulls.size()));
  ASSERT_EQ(runtime_file_bytes(3, 4, hull_bytes + section_table({{0, {0, 1, 2, 3}}})), good);
  const auto refused = [&](const std::string& name, const std::string& table, const std::string& words) {
    const std::string path = dir.write(name, runtime_file_bytes(3, 4, hull_bytes + table));
    for (const Status& s : {read_runtime_file(path).status(), read_runtime_sections(path).status(),
                            read_runtime_section(path, 0).status()}) {
      EXPECT_EQ(s.code(), StatusCode::unreadable_file) << name << ": " << s.message();
      EXPECT_NE(s.message().find(words), std::string::npos) << name << ": " << s.message();
      EXPECT_EQ(s.message().rfind(path, 0), 0u) << s.message();
    }
  };
  refused("twice.hcw", section_table({{0, {0, 1, 2}}, {1, {2, 3}}}), "hull 2 is in two sections");
  refused("none.hcw", section_table({{0, {0, 1}}, {1, {3}}}), "hull 2 is in no section");
  refused("range.hcw", section_table({{0, {0, 1, 2, 3, 4}}}), "hull index 4 out of range");
  refused("order.hcw", section_table({{0, {0, 2, 1, 3}}}), "not ascending");
  refused("ids.hcw", section_table({{5, {0, 1}}, {2, {2, 3}}}), "section ids not ascending");
  refused("empty.hcw", section_table({{0, {0, 1, 2, 3}}, {1, {}}}), "holds no hull");
  std::string truncated = section_table({{0, {0, 1}}, {1, {2, 3}}});
  truncated.resize(truncated.size() - 4);
  refused("truncated.hcw", truncated, "past the end");
  refused("count.hcw", std::string("\xff\xff\xff\x00", 4), "section count larger");
  refused("extra.hcw", section_table({{0, {0, 1, 2, 3}}}) + "x", "bytes left after the section table");
  refused("no-table.hcw", "", "section table truncated");
}

} // namespace
} // namespace hullcover::bvh
