// Drives the real `hullcover` binary as a user would and checks its exit
// status, what it prints and what it writes.

#include "command_run.h"
#include "png_pixels.h"
#include "temp_dir.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

namespace {

using hullcover::test::TempDir;

using hullcover::test::CommandRun;
using hullcover::test::slurp;

CommandRun run(const TempDir& dir, const std::string& arguments) {
  return hullcover::test::run_hullcover(dir, arguments);
}

const char* kQuadObj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";

TEST(CommandLine, HelpListsTheCommands) {
  TempDir dir;
  const CommandRun r = run(dir, "--help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("info"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("demo"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Exit status"), std::string::npos) << r.out;
}

TEST(CommandLine, InfoHelpExplainsTheTolerance) {
  TempDir dir;
  const CommandRun r = run(dir, "info --help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("--tol"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--json"), std::string::npos) << r.out;
}

TEST(CommandLine, BadUsageExitsWithTwo) {
  TempDir dir;
  EXPECT_EQ(run(dir, "").status, 2);
  EXPECT_EQ(run(dir, "frobnicate").status, 2);
  EXPECT_EQ(run(dir, "info").status, 2);
  const std::string quad = dir.write("quad.obj", kQuadObj);
  EXPECT_EQ(run(dir, "info " + quad + " --tol banana").status, 2);
  const CommandRun negative = run(dir, "info " + quad + " --tol -1");
  EXPECT_EQ(negative.status, 2);
  EXPECT_NE(negative.err.find("--tol: must be a number above 0"), std::string::npos) << negative.err;
}

TEST(CommandLine, BadInputGivesOneLineNamingTheFileAndExitsWithTwo) {
  TempDir dir;
  const std::string missing = dir.path("missing.obj");
  const std::string nan = dir.write("nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string unknown = dir.write("scene.xyz", "hello\n");
  for (const std::string& path : {missing, nan, unknown}) {
    const CommandRun r = run(dir, "info " + path);
    EXPECT_EQ(r.status, 2) << path;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_NE(r.err.find(path), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

TEST(CommandLine, InfoJsonReportsTheQuad) {
  TempDir dir;
  const std::string quad = dir.write("quad.obj", kQuadObj);
  const CommandRun r = run(dir, "info " + quad + " --json --tol 0.001");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["triangles"], 2);
  EXPECT_EQ(j["vertices_after_weld"], 4);
  EXPECT_EQ(j["components"], 1);
  EXPECT_EQ(j["boundary_edges"], 4);
  EXPECT_EQ(j["non_manifold_edges"], 0);
  EXPECT_DOUBLE_EQ(j["tolerance"]["length"].get<double>(), 0.001);
  EXPECT_TRUE(j["tolerance"]["user_given"].get<bool>());
}

TEST(CommandLine, InfoTextPrintsTheToleranceUsed) {
  TempDir dir;
  const std::string quad = dir.write("quad.obj", kQuadObj);
  const CommandRun r = run(dir, "info " + quad);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("tolerance"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1e-5 x the diagonal 1.41421"), std::string::npos) << r.out;
}

TEST(CommandLine, DemoWritesTheSceneItsFiguresAndItsHulls) {
  TempDir dir;
  const CommandRun r = run(dir, "demo --out " + dir.path("demo"));
  ASSERT_EQ(r.status, 0) << r.err;
  const CommandRun info = run(dir, "info --json " + dir.path("demo/demo-scene.obj"));
  ASSERT_EQ(info.status, 0) << info.err;
  const nlohmann::json written = nlohmann::json::parse(slurp(dir.path("demo/demo-hulls.json")));
  const nlohmann::json reread = nlohmann::json::parse(info.out);
  // The OBJ the demo wrote reads back to the figures the demo reported.
  for (const char* key : {"triangles", "vertices_after_weld", "components", "boundary_edges", "non_manifold_edges"})
    EXPECT_EQ(written["scene"][key], reread[key]) << key;
  const std::string hulls = slurp(dir.path("demo/demo-hulls.obj"));
  size_t hull_groups = 0;
  for (size_t at = hulls.find("\no hull_"); at != std::string::npos; at = hulls.find("\no hull_", at + 1))
    ++hull_groups;
  EXPECT_EQ(hull_groups, written["totals"]["hulls"].get<size_t>());
  EXPECT_LT(written["totals"]["hulls"].get<int>(), written["totals"]["faces"].get<int>());
}

TEST(CommandLine, DemoAuditsItsHullsQueriesTheRuntimeFileAndDrawsThePicture) {
  TempDir dir;
  const CommandRun r = run(dir, "demo --out " + dir.path("demo"));
  ASSERT_EQ(r.status, 0) << r.err;
  // The verdict, as `hullcover audit` gives it on the same files.
  EXPECT_NE(r.out.find("demo-hulls.obj: CLEAN: no accessible space lost"), std::string::npos) << r.out;
  const CommandRun audit =
      run(dir, "audit " + dir.path("demo/demo-scene.obj") + " " + dir.path("demo/demo-hulls.obj") + " -q");
  EXPECT_EQ(audit.status, 0) << audit.out;
  // The building's floor top is y = 0 and the interior wall's face x = -0.1:
  // a capsule sunk 1 cm into the floor touches it 0.01 deep, straight up,
  // and a ray from x = -3 along +x meets the wall 2.9 along.
  EXPECT_NE(r.out.find("1 contact(s)\n  hull "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("depth 0.01, normal (0, 1, 0)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("at distance 2.9, point (-0.1, 1.4, 0), normal (-1, 0, 0)"), std::string::npos) << r.out;
  // The same ray through `hullcover query` on the runtime file the demo wrote.
  const CommandRun ray = run(dir, "query " + dir.path("demo/demo-world.hcw") + " --ray -3 1.4 0 1 0 0");
  ASSERT_EQ(ray.status, 0) << ray.err;
  EXPECT_NE(ray.out.find("at t 2.9 "), std::string::npos) << ray.out;
  // The picture is where the demo says, a full image with many colours.
  const std::string picture = dir.path("demo/demo-hulls.png");
  EXPECT_NE(r.out.find("picture: " + picture), std::string::npos) << r.out;
  const hullcover::test::DecodedPng png = hullcover::test::decode_png(picture);
  EXPECT_EQ(png.width, 1200);
  EXPECT_EQ(png.height, 900);
  EXPECT_GT(hullcover::test::distinct_colours(png), 20u);
}

TEST(CommandLine, DecomposeWritesOneGroupPerHullAndTheSidecar) {
  TempDir dir;
  const std::string quad = dir.write("quad.obj", kQuadObj);
  const CommandRun r =
      run(dir, "decompose " + quad + " -o " + dir.path("h.obj") + " --json " + dir.path("h.json") +
                   " --order random --seed 7 --bar-length 0.5 --prism-cap 0.1 --max-hull-vertices 16 -q");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("2 faces -> 1 hulls"), std::string::npos) << r.out;
  const nlohmann::json j = nlohmann::json::parse(slurp(dir.path("h.json")));
  EXPECT_EQ(j["totals"]["hulls"], 1);
  EXPECT_EQ(j["options"]["order"], "random");
  EXPECT_EQ(j["options"]["seed"], 7);
  EXPECT_DOUBLE_EQ(j["options"]["bar_half_length"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(j["hulls"][0]["prism_thickness"].get<double>(), 0.1); // nothing behind the quad
  EXPECT_EQ(j["hulls"][0]["faces"], nlohmann::json::array({0, 1}));
  const std::string obj = slurp(dir.path("h.obj"));
  EXPECT_NE(obj.find("o hull_0\n"), std::string::npos);
}

TEST(CommandLine, DecomposeRejectsBadOptionsWithTwo) {
  TempDir dir;
  const std::string quad = dir.write("quad.obj", kQuadObj);
  const std::string base = "decompose " + quad + " -o " + dir.path("h.obj") + " ";
  for (const std::string bad :
       {"--order sideways", "--max-hull-vertices 3", "--bar-length -1", "--prism-cap -2", "--tol 0", "--seed -1"})
    EXPECT_EQ(run(dir, base + bad).status, 2) << bad;
  // The message names the text given, in a line (not the 309 digits of the
  // largest double).
  const CommandRun negative_cap = run(dir, base + "--prism-cap -2");
  EXPECT_NE(negative_cap.err.find("--prism-cap: must be a number from 0 to 1e15, not '-2'"), std::string::npos)
      << negative_cap.err;
  EXPECT_LT(negative_cap.err.size(), 160u) << negative_cap.err;
  EXPECT_EQ(run(dir, "decompose " + dir.path("missing.obj") + " -o " + dir.path("h.obj")).status, 2);
  EXPECT_EQ(run(dir, "decompose " + quad + " -o " + dir.path("no/such/dir/h.obj")).status, 2);
}

TEST(CommandLine, ACellCacheReusesEveryCellOfAnUnchangedSceneAndRefusesBadEntries) {
  TempDir dir;
  ASSERT_EQ(run(dir, "demo --out " + dir.path("demo")).status, 0);
  const std::string scene = dir.path("demo/demo-scene.obj");
  const std::string base = "decompose " + scene + " --cell-size 4 -q -o ";
  ASSERT_EQ(run(dir, base + dir.path("plain.obj")).status, 0);
  const CommandRun first = run(dir, base + dir.path("first.obj") + " --cell-cache " + dir.path("cache"));
  ASSERT_EQ(first.status, 0) << first.err;
  EXPECT_NE(first.out.find(", 0 reused"), std::string::npos) << first.out;
  const CommandRun second = run(dir, base + dir.path("second.obj") + " --cell-cache " + dir.path("cache"));
  ASSERT_EQ(second.status, 0) << second.err;
  EXPECT_NE(second.out.find(", 0 stale, 0 merged"), std::string::npos) << second.out;
  EXPECT_EQ(slurp(dir.path("first.obj")), slurp(dir.path("plain.obj")));
  EXPECT_EQ(slurp(dir.path("second.obj")), slurp(dir.path("plain.obj")));
  // Every entry spoiled: each is refused and merged again, the output unchanged.
  int spoiled = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path("cache"))) {
    std::string bytes = slurp(entry.path().string());
    bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 1);
    dir.write("cache/" + entry.path().filename().string(), bytes);
    ++spoiled;
  }
  EXPECT_GT(spoiled, 4);
  const CommandRun third = run(dir, base + dir.path("third.obj") + " --cell-cache " + dir.path("cache"));
  ASSERT_EQ(third.status, 0) << third.err;
  EXPECT_NE(third.out.find(" 0 reused"), std::string::npos) << third.out;
  EXPECT_EQ(slurp(dir.path("third.obj")), slurp(dir.path("plain.obj")));
  EXPECT_EQ(run(dir, base + dir.path("x.obj") + " --cell-cache " + scene).status, 2);
}

TEST(CommandLine, QueryAnswersFromTheRuntimeFile) {
  TempDir dir;
  ASSERT_EQ(run(dir, "demo --out " + dir.path("demo")).status, 0);
  const std::string world = dir.path("w.hcw");
  ASSERT_EQ(run(dir, "decompose " + dir.path("demo/demo-scene.obj") + " -o " + dir.path("h.obj") + " --world " + world +
                         " -q")
                .status,
            0);
  // Upright capsule in the doorway, 5 cm into the floor.
  CommandRun r = run(dir, "query " + world + " --capsule 0,0.85,3.9,0.3,0.6");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("1 contact(s)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("depth 0.05"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("normal (0, 1, 0)"), std::string::npos) << r.out;
  // Down onto the roof.
  r = run(dir, "query " + world + " --ray 0,5,0,0,-1,0");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("at t 1.8 "), std::string::npos) << r.out; // the roof at 3.2, read in double
  // Floating in a room: no contact, the floor 1.2 below.
  r = run(dir, "query " + world + " --sphere -2,1.5,-2,0.3");
  EXPECT_NE(r.out.find("distance 1.2"), std::string::npos) << r.out;
  EXPECT_EQ(run(dir, "query " + world + " --sphere 1,2").status, 2);
  EXPECT_EQ(run(dir, "query " + world).status, 2);
  EXPECT_EQ(run(dir, "query " + dir.path("h.obj") + " --sphere 0,0,0,1").status, 2); // not a runtime file
}

TEST(CommandLine, AuditExitsZeroWhenCleanOneWhenSpaceIsLostTwoWhenUnreadable) {
  TempDir dir;
  ASSERT_EQ(run(dir, "demo --out " + dir.path("demo")).status, 0);
  const std::string scene = dir.path("demo/demo-scene.obj");
  ASSERT_EQ(
      run(dir, "decompose " + scene + " -o " + dir.path("h.obj") + " --world " + dir.path("w.hcw") + " -q").status, 0);
  CommandRun r =
      run(dir, "audit " + scene + " " + dir.path("w.hcw") + " --resolution 0.15 --json " + dir.path("a.json"));
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("CLEAN"), std::string::npos) << r.out;
  const nlohmann::json j = nlohmann::json::parse(slurp(dir.path("a.json")));
  EXPECT_TRUE(j["clean"].get<bool>());
  EXPECT_GT(j["front"]["rays"].get<long>(), 0);
  EXPECT_EQ(j["front"]["lost"].get<long>(), 0);
  EXPECT_TRUE(j["front"]["deepest"].is_null());
  EXPECT_TRUE(j["probe_distance"].is_null()); // no cap unless asked
  // One hull over the whole building, as an OBJ group: the rooms are lost.
  const std::string blob = dir.write("blob.obj",
                                     "o all\nv -5 0 -4\nv 5 0 -4\nv 5 3.2 -4\nv -5 3.2 -4\n"
                                     "v -5 0 4\nv 5 0 4\nv 5 3.2 4\nv -5 3.2 4\n"
                                     "f 1 2 3 4\nf 5 6 7 8\n");
  r = run(dir, "audit " + scene + " " + blob + " --resolution 0.15 --json " + dir.path("b.json"));
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("VIOLATIONS"), std::string::npos) << r.out;
  const nlohmann::json lost = nlohmann::json::parse(slurp(dir.path("b.json")));
  EXPECT_GT(lost["front"]["lost"].get<long>(), 0);
  EXPECT_EQ(lost["front"]["deepest"]["hull"].get<int>(), 0);
  EXPECT_GT(lost["front"]["lost_length"].get<double>(), 0.0);
  EXPECT_EQ(run(dir, "audit " + scene + " " + dir.path("missing.obj")).status, 2);
  EXPECT_EQ(run(dir, "audit " + dir.path("missing.obj") + " " + blob).status, 2);
}

// `audit --threads N`: what it prints and the JSON it writes are the same
// bytes for any N, on hulls that lose space (located places included); a
// negative count is bad usage.
TEST(CommandLine, AuditPrintsAndWritesTheSameOnAnyThreadCount) {
  TempDir dir;
  ASSERT_EQ(run(dir, "demo --out " + dir.path("demo")).status, 0);
  const std::string scene = dir.path("demo/demo-scene.obj");
  // The decomposer's hulls (clean), and hulls that lose space in many
  // places: one over the back half of the building, one closing the doorway.
  ASSERT_EQ(run(dir, "decompose " + scene + " -o " + dir.path("h.obj") + " -q").status, 0);
  const std::string spoiled = dir.write("spoiled.obj",
                                        "o back\nv -5 0 -4\nv 5 0 -4\nv 5 3.2 -4\nv -5 3.2 -4\n"
                                        "v -5 0 0\nv 5 0 0\nv 5 3.2 0\nv -5 3.2 0\n"
                                        "f 1 2 3 4\nf 5 6 7 8\n"
                                        "o door\nv -0.6 0 3.8\nv 0.6 0 3.8\nv 0.6 2.1 3.8\nv -0.6 2.1 3.8\n"
                                        "v -0.6 0 4\nv 0.6 0 4\nv 0.6 2.1 4\nv -0.6 2.1 4\n"
                                        "f 9 10 11 12\nf 13 14 15 16\n");
  for (const std::string& hulls : {dir.path("h.obj"), spoiled}) {
    const std::string common = "audit " + scene + " " + hulls + " --resolution 0.15 --proxies 600 -q --json ";
    const CommandRun one = run(dir, common + dir.path("t1.json") + " --threads 1");
    ASSERT_TRUE(one.status == 0 || one.status == 1) << one.err;
    const std::string json = slurp(dir.path("t1.json"));
    for (const char* threads : {"2", "3", "8", "0"}) {
      const std::string path = dir.path(std::string("t") + threads + ".json");
      const CommandRun many = run(dir, common + path + " --threads " + threads);
      EXPECT_EQ(many.status, one.status) << threads << " threads: " << many.err;
      EXPECT_EQ(many.out, one.out) << threads << " threads";
      EXPECT_EQ(slurp(path), json) << threads << " threads";
    }
    if (hulls == spoiled) {
      EXPECT_EQ(one.status, 1);
      EXPECT_GE(nlohmann::json::parse(json)["worst"].size(), 2u);
    }
  }
  const CommandRun negative = run(dir, "audit " + scene + " " + spoiled + " --threads -1");
  EXPECT_EQ(negative.status, 2);
  EXPECT_NE(negative.err.find("--threads: must be a whole number from 0 to"), std::string::npos) << negative.err;
  EXPECT_EQ(run(dir, "audit " + scene + " " + spoiled + " --threads two").status, 2);
  EXPECT_EQ(run(dir, "audit " + scene + " " + spoiled + " --seed -1").status, 2);
  const CommandRun help = run(dir, "audit --help");
  EXPECT_NE(help.out.find("--threads"), std::string::npos) << help.out;
}

// `audit --max-ray-evaluations N`: a ray held to its two ends runs out and
// is a violation, named in the text and the JSON; below 2 is bad usage.
TEST(CommandLine, AuditSaysWhereARayRanOutOfEvaluations) {
  TempDir dir;
  ASSERT_EQ(run(dir, "demo --out " + dir.path("demo")).status, 0);
  const std::string scene = dir.path("demo/demo-scene.obj");
  ASSERT_EQ(run(dir, "decompose " + scene + " -o " + dir.path("h.obj") + " --agent-radius 0.3 -q").status, 0);
  const std::string common = "audit " + scene + " " + dir.path("h.obj") +
                             " --agent-radius 0.3 --resolution 0.3 "
                             "--proxies 300 --json " +
                             dir.path("a.json") + " --max-ray-evaluations ";
  const CommandRun bounded = run(dir, common + "2 --html " + dir.path("a.html"));
  EXPECT_EQ(bounded.status, 1) << bounded.err;
  EXPECT_NE(bounded.out.find("ran out of evaluations (undecided: a violation); the first at ("), std::string::npos)
      << bounded.out;
  const nlohmann::json allowance = nlohmann::json::parse(slurp(dir.path("a.json")))["allowance"];
  EXPECT_GT(allowance["undecided"].get<long>(), 0);
  EXPECT_GE(allowance["first_undecided"]["face"].get<int>(), 0);
  EXPECT_EQ(allowance["first_undecided"]["point"].size(), 3u);
  // The HTML report's table names it too, on the face the JSON gives, with
  // no hull and no depth.
  const std::string html = slurp(dir.path("a.html"));
  const std::string row = "first ray out of evaluations (undecided)</td>";
  const size_t at = html.find(row);
  ASSERT_NE(at, std::string::npos);
  const std::string rest = html.substr(at, html.find("</tr>", at) - at);
  EXPECT_NE(rest.find("<td>&mdash;</td><td>&mdash;</td><td>" +
                      std::to_string(allowance["first_undecided"]["face"].get<int>()) + "</td>"),
            std::string::npos)
      << rest;
  const CommandRun refused = run(dir, common + "1");
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find("--max-ray-evaluations"), std::string::npos) << refused.err;
}

// A closed room of 4 x 3 x 4, its faces turned in: a walker of radius 0.3,
// 1.8 tall, touches the floor and the four walls, and no hull may span two
// of them (it would cut across the room's corner, where walkers stand).
TEST(CommandLine, AuditBoundsTheHullsOfAnyMovementCoveringAndNeedsAReach) {
  TempDir dir;
  const std::string room = dir.write("room.obj",
                                     "v 0 0 0\nv 4 0 0\nv 0 3 0\nv 4 3 0\nv 0 0 4\nv 4 0 4\nv 0 3 4\nv 4 3 4\n"
                                     "f 3 7 5 1\nf 6 8 4 2\nf 5 6 2 1\nf 4 8 7 3\nf 2 4 3 1\nf 7 8 6 5\n");
  const std::string agent = " --agent-radius 0.3 --agent-height 1.8 --agent-climb 0.4 --agent-reach walk";
  const CommandRun made = run_hullcover(
      dir, "decompose " + room + agent + " -o " + dir.path("h.obj") + " --world " + dir.path("h.hcw") + " -q");
  ASSERT_EQ(made.status, 0) << made.err;
  const CommandRun bounded = run_hullcover(dir, "audit " + room + " " + dir.path("h.hcw") + agent +
                                                    " --hull-bound --json " + dir.path("bound.json") + " -q");
  EXPECT_EQ(bounded.status, 0) << bounded.out << bounded.err;
  EXPECT_NE(bounded.out.find("has at least 5 hulls"), std::string::npos) << bounded.out;
  const nlohmann::json json = nlohmann::json::parse(slurp(dir.path("bound.json")));
  EXPECT_EQ(json["movement"]["hull_bound"], 5);

  const CommandRun alone = run_hullcover(dir, "audit " + room + " " + dir.path("h.hcw") + " --hull-bound -q");
  EXPECT_EQ(alone.status, 2);
  EXPECT_NE(alone.err.find("--hull-bound needs --agent-reach"), std::string::npos) << alone.err;
}

} // namespace
