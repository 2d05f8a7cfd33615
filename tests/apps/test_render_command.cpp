// `hullcover render` run as a user would, its PNGs read back with cairo's
// decoder: the demo scene with its hulls in many colours, the scene alone in
// grey, the cut-away showing the hulls inside the building, and exit 2 with
// a message for what it cannot read or draw.

#include "demo_hull_files.h"
#include "png_pixels.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

namespace {

using hullcover::test::CommandRun;
using hullcover::test::decode_png;
using hullcover::test::DecodedPng;
using hullcover::test::ObjHull;
using hullcover::test::run_hullcover;
using hullcover::test::slurp;
using hullcover::test::TempDir;

class RenderCommand : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<TempDir>();
    demo_written_ = hullcover::test::write_demo(*dir_);
  }
  static void TearDownTestSuite() { dir_.reset(); }
  void SetUp() override { ASSERT_TRUE(demo_written_) << "hullcover demo failed"; }

  static std::string scene() { return dir_->path("demo/demo-scene.obj"); }
  static std::string hulls() { return dir_->path("demo/demo-hulls.obj"); }
  static CommandRun render(const std::string& arguments) { return run_hullcover(*dir_, "render " + arguments); }

  static std::unique_ptr<TempDir> dir_;
  static bool demo_written_;
};
std::unique_ptr<TempDir> RenderCommand::dir_;
bool RenderCommand::demo_written_ = false;

TEST_F(RenderCommand, DrawsTheDemoHullsEachInItsOwnColour) {
  const std::string out = dir_->path("hulls.png");
  const CommandRun r = render(scene() + " " + hulls() + " -o " + out + " --size 640x480");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("wrote " + out), std::string::npos) << r.out;
  const DecodedPng png = decode_png(out);
  ASSERT_EQ(png.width, 640);
  ASSERT_EQ(png.height, 480);
  // Flat shading of many hulls, antialiased edges: many colours.
  EXPECT_GT(hullcover::test::distinct_colours(png), 500u);
  // The building and the terrain fill a good part of the frame, in saturated hull colours ...
  EXPECT_GT(hullcover::test::saturated_pixels(png), png.pixels.size() / 10);
  // ... of many different hues, not one colour shaded.
  EXPECT_GE(hullcover::test::hue_buckets(png, 12, 200), 6);
}

TEST_F(RenderCommand, DrawsTheSceneAloneInShadedGrey) {
  const std::string out = dir_->path("scene.png");
  const CommandRun r = render(scene() + " -o " + out + " --size 400x300");
  ASSERT_EQ(r.status, 0) << r.err;
  const DecodedPng png = decode_png(out);
  ASSERT_EQ(png.width, 400);
  ASSERT_EQ(png.height, 300);
  EXPECT_LT(hullcover::test::saturated_pixels(png), png.pixels.size() / 200); // grey: no hull colour
  // Not blank: faces in several shades of grey, darker than the background.
  size_t shaded = 0;
  for (const hullcover::test::Pixel& p : png.pixels) shaded += p.r < 200 && p.g < 200 && p.b < 200;
  EXPECT_GT(shaded, png.pixels.size() / 20);
  EXPECT_GT(hullcover::test::distinct_colours(png), 20u);
}

TEST_F(RenderCommand, CutAwayShowsTheHullsInsideTheBuilding) {
  // The hulls standing in the building's room (the interior wall, the
  // stairs, the inner faces of the walls): the roof and the walls hide them.
  std::vector<ObjHull> inside;
  for (const ObjHull& hull : hullcover::test::read_obj_hulls(slurp(hulls()))) {
    bool in_room = !hull.points.empty();
    for (const Eigen::Vector3d& p : hull.points)
      in_room = in_room && p.x() >= -4.8 - 1e-9 && p.x() <= 4.8 + 1e-9 && p.y() >= -1e-9 && p.y() <= 3.0 + 1e-9 &&
                p.z() >= -3.8 - 1e-9 && p.z() <= 3.8 + 1e-9;
    if (in_room) inside.push_back(hull);
  }
  ASSERT_GE(inside.size(), 5u) << "the demo's interior wall and six steps";
  const std::string inner = dir_->write("inside.obj", hullcover::test::write_obj_hulls(inside));
  const std::string closed = dir_->path("closed.png"), cut = dir_->path("cut.png");
  ASSERT_EQ(render(scene() + " " + inner + " -o " + closed + " --size 640x480").status, 0);
  ASSERT_EQ(render(scene() + " " + inner + " -o " + cut + " --size 640x480 --cut").status, 0);
  const size_t seen_closed = hullcover::test::saturated_pixels(decode_png(closed));
  const size_t seen_cut = hullcover::test::saturated_pixels(decode_png(cut));
  // Closed, only the doorway shows a little of the inside.
  EXPECT_GT(seen_cut, 5 * seen_closed + 2000) << "closed " << seen_closed << ", cut " << seen_cut;

  // With every hull, the cut takes the roof and the front walls away.
  const std::string all_closed = dir_->path("all.png"), all_cut = dir_->path("all-cut.png");
  ASSERT_EQ(render(scene() + " " + hulls() + " -o " + all_closed + " --size 640x480").status, 0);
  ASSERT_EQ(render(scene() + " " + hulls() + " -o " + all_cut + " --size 640x480 --cut").status, 0);
  EXPECT_GT(hullcover::test::changed_fraction(decode_png(all_closed), decode_png(all_cut)), 0.05);
}

TEST_F(RenderCommand, ViewsLookFromWhereTheySay) {
  const std::string iso = dir_->path("iso.png"), top = dir_->path("top.png"), angled = dir_->path("angled.png");
  ASSERT_EQ(render(scene() + " " + hulls() + " -o " + iso + " --size 320x240").status, 0);
  ASSERT_EQ(render(scene() + " " + hulls() + " -o " + top + " --size 320x240 --view top").status, 0);
  ASSERT_EQ(render(scene() + " " + hulls() + " -o " + angled + " --size 320x240 --view -30,60").status, 0);
  EXPECT_GT(hullcover::test::changed_fraction(decode_png(iso), decode_png(top)), 0.2);
  EXPECT_GT(hullcover::test::changed_fraction(decode_png(iso), decode_png(angled)), 0.2);
  // A scene that is z-up drawn as such is another picture again.
  const std::string z_up = dir_->path("z-up.png");
  ASSERT_EQ(render(scene() + " " + hulls() + " -o " + z_up + " --size 320x240 --up z").status, 0);
  EXPECT_GT(hullcover::test::changed_fraction(decode_png(iso), decode_png(z_up)), 0.2);
}

TEST_F(RenderCommand, PeerHullsFromAnyToolAreDrawnToo) {
  // V-HACD-like hulls: groups of triangles whose convex hull is the hull.
  std::vector<ObjHull> peers = {hullcover::test::box_hull("a", {-5, -0.2, -4}, {5, 3.2, 4}),
                                hullcover::test::box_hull("b", {-16, -0.6, -6}, {-6, 0, 6})};
  const std::string file = dir_->write("peers.obj", hullcover::test::write_obj_hulls(peers));
  const std::string out = dir_->path("peers.png");
  ASSERT_EQ(render(scene() + " " + file + " -o " + out + " --size 320x240").status, 0);
  const DecodedPng png = decode_png(out);
  EXPECT_GT(hullcover::test::saturated_pixels(png), png.pixels.size() / 10);
  EXPECT_GE(hullcover::test::hue_buckets(png, 12, 100), 2);
}

TEST_F(RenderCommand, UnreadableInputAndBadSizesExitWithTwoAndAMessage) {
  const std::string out = dir_->path("bad.png");
  struct Case {
    std::string arguments, message;
  };
  const std::vector<Case> cases = {
      {dir_->path("missing.obj") + " -o " + out, "missing.obj"},
      {scene() + " " + dir_->path("missing-hulls.obj") + " -o " + out, "missing-hulls.obj"},
      {scene() + " -o " + out + " --size 0x0", "--size"},
      {scene() + " -o " + out + " --size 100000x100000", "--size"},
      {scene() + " -o " + out + " --size 640", "--size"},
      {scene() + " -o " + out + " --view sideways", "--view"},
      {scene() + " -o " + out + " --view 0,95", "--view"},
      {scene() + " -o " + out + " --up w", "--up"},
      {scene() + " -o " + dir_->path("no-such-folder/out.png"), "no-such-folder"},
  };
  for (const Case& c : cases) {
    const CommandRun r = render(c.arguments);
    EXPECT_EQ(r.status, 2) << c.arguments << "\n" << r.out << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.arguments << "\n" << r.err;
    EXPECT_NE(r.err.find("hullcover: error:"), std::string::npos) << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(out)) << "nothing is written for bad input";
}

} // namespace
