// `hullcover audit --html`: one self-contained file holding the verdict,
// every figure of the JSON and pictures of the scene, its hulls and the lost
// space; then opened in headless Chromium, as a reviewer would, to check
// that what a browser shows carries the verdict.

#include "child_process.h"
#include "demo_hull_files.h"
#include "png_pixels.h"

#include "render/audit_report_html.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <filesystem>
#include <memory>
#include <optional>

namespace {

using hullcover::test::CommandRun;
using hullcover::test::decode_png;
using hullcover::test::DecodedPng;
using hullcover::test::run_hullcover;
using hullcover::test::slurp;
using hullcover::test::TempDir;
namespace render = hullcover::app::render;

constexpr const char* kChromium = "/usr/bin/chromium";
// Chromium starts in about a second here; a loaded CI machine may take far longer.
constexpr std::chrono::seconds kChromiumTimeLimit{120};
// Proxies are not what this test is about: a few keep each audit short.
constexpr const char* kQuickAudit = " --proxies 300";

// The pictures embedded as data: URIs, decoded.
std::vector<std::string> embedded_pngs(const std::string& html) {
  const std::string marker = "data:image/png;base64,";
  std::vector<std::string> pngs;
  for (size_t at = html.find(marker); at != std::string::npos; at = html.find(marker, at + 1)) {
    const size_t begin = at + marker.size(), end = html.find('"', begin);
    std::string bytes;
    unsigned group = 0;
    int bits = 0;
    for (size_t i = begin; i < end && html[i] != '='; ++i) {
      const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
      group = (group << 6) | static_cast<unsigned>(alphabet.find(html[i]));
      bits += 6;
      if (bits >= 8) {
        bits -= 8;
        bytes += static_cast<char>((group >> bits) & 0xff);
      }
    }
    pngs.push_back(bytes);
  }
  return pngs;
}

// Pixels of the lost-space red (a lit red ball), which no hull colour has.
size_t red_pixels(const DecodedPng& png) {
  size_t n = 0;
  for (const hullcover::test::Pixel& p : png.pixels) n += p.r > 140 && p.g < 70 && p.b < 70;
  return n;
}

// Every key of `figures`, at any depth.
void collect_keys(const nlohmann::json& figures, std::vector<std::string>& keys) {
  if (figures.is_object())
    for (const auto& [key, value] : figures.items()) {
      keys.push_back(key);
      collect_keys(value, keys);
    }
  else if (figures.is_array())
    for (const nlohmann::json& item : figures) collect_keys(item, keys);
}

class AuditHtml : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<TempDir>();
    if (!hullcover::test::write_demo(*dir_)) return;
    // The demo's hulls and a box floating in the middle of the room's left
    // half: rays from the floor below run into it.
    std::vector<hullcover::test::ObjHull> hulls = hullcover::test::read_obj_hulls(slurp(hulls_path()));
    intruder_ = static_cast<int>(hulls.size());
    hulls.push_back(hullcover::test::box_hull("intruder", {-3.5, 1.0, -1.0}, {-2.5, 2.0, 0.0}));
    dir_->write("intruder.obj", hullcover::test::write_obj_hulls(hulls));
  }
  static void TearDownTestSuite() {
    clean_.reset();
    violation_.reset();
    dir_.reset();
  }

  // Each audit runs the first time a test asks for it: ctest runs every
  // test in its own process, and under the sanitizers one audit of the demo
  // takes tens of seconds.
  static const CommandRun& clean() {
    if (!clean_)
      clean_ = run_hullcover(*dir_, "audit " + scene() + " " + hulls_path() + " --html " + dir_->path("clean.html") +
                                        " --json " + dir_->path("clean.json") + kQuickAudit);
    return *clean_;
  }
  static const CommandRun& violation() {
    if (!violation_)
      violation_ = run_hullcover(*dir_, "audit " + scene() + " " + dir_->path("intruder.obj") + " --html " +
                                            dir_->path("violation.html") + kQuickAudit);
    return *violation_;
  }

  static std::string scene() { return dir_->path("demo/demo-scene.obj"); }
  static std::string hulls_path() { return dir_->path("demo/demo-hulls.obj"); }

  // Chromium, headless and cut off from the network, on `html`; its
  // output goes to `name`.out and `name`.err.
  static hullcover::test::ChildOutcome chromium(const std::string& html, const std::string& name,
                                                const std::vector<std::string>& action) {
    const std::string profile = dir_->path(name + "-profile"); // a fresh profile each run
    std::filesystem::create_directories(profile);
    hullcover::test::ChildSpec spec;
    spec.argv = {kChromium,
                 "--headless",
                 "--no-sandbox",
                 "--disable-gpu",
                 "--disable-quic",
                 "--no-first-run",
                 "--disable-background-networking",
                 "--disable-component-update",
                 "--disable-sync",
                 "--user-data-dir=" + profile};
    spec.argv.insert(spec.argv.end(), action.begin(), action.end());
    spec.argv.push_back("file://" + html);
    spec.stdout_path = dir_->path(name + ".out");
    spec.stderr_path = dir_->path(name + ".err");
    hullcover::test::ChildLimits limits;
    limits.wall = kChromiumTimeLimit;
    limits.address_space_bytes = 0; // Chromium reserves terabytes of address space up front
    limits.parallel = 1;
    return hullcover::test::run_children({spec}, limits).front();
  }

  static std::unique_ptr<TempDir> dir_;
  static std::optional<CommandRun> clean_, violation_;
  static int intruder_;
};
std::unique_ptr<TempDir> AuditHtml::dir_;
std::optional<CommandRun> AuditHtml::clean_, AuditHtml::violation_;
int AuditHtml::intruder_ = -1;

TEST_F(AuditHtml, CleanReportHoldsTheVerdictEveryFigureAndItsPictures) {
  ASSERT_EQ(clean().status, 0) << clean().out << clean().err;
  const std::string html = slurp(dir_->path("clean.html"));
  EXPECT_NE(html.find("id=\"verdict\""), std::string::npos);
  EXPECT_NE(html.find(">CLEAN<"), std::string::npos);
  EXPECT_NE(html.find(render::kCleanBannerColour), std::string::npos);
  EXPECT_EQ(html.find(render::kViolationBannerColour), std::string::npos);
  // Self-contained: no reference leaves the file.
  EXPECT_EQ(html.find("http://"), std::string::npos);
  EXPECT_EQ(html.find("https://"), std::string::npos);
  EXPECT_EQ(html.find("src=\"data:image/png;base64,"), html.find("src=\""));
  // Every figure of the JSON has its row.
  std::vector<std::string> keys;
  collect_keys(nlohmann::json::parse(slurp(dir_->path("clean.json"))), keys);
  ASSERT_GT(keys.size(), 40u);
  for (const std::string& key : keys) EXPECT_NE(html.find("<th>" + key + "</th>"), std::string::npos) << key;
  // Three pictures, each a real PNG with the scene on it, no lost space marked.
  const std::vector<std::string> pngs = embedded_pngs(html);
  ASSERT_EQ(pngs.size(), 3u);
  for (size_t i = 0; i < pngs.size(); ++i) {
    const DecodedPng png = decode_png(dir_->write("clean-" + std::to_string(i) + ".png", pngs[i]));
    ASSERT_GT(png.width, 0) << "picture " << i << " is no PNG";
    EXPECT_GT(hullcover::test::distinct_colours(png), 100u) << i;
    EXPECT_LT(red_pixels(png), 20u) << i;
  }
}

TEST_F(AuditHtml, ViolationReportNamesTheFindingAndMarksTheLostSpaceInRed) {
  ASSERT_EQ(violation().status, 1) << violation().out << violation().err;
  const std::string html = slurp(dir_->path("violation.html"));
  EXPECT_NE(html.find(">VIOLATION: front_space_lost<"), std::string::npos);
  EXPECT_NE(html.find(render::kViolationBannerColour), std::string::npos);
  // The table of places names the intruding hull.
  EXPECT_NE(html.find("id=\"places\""), std::string::npos);
  EXPECT_NE(html.find("<td>" + std::to_string(intruder_) + "</td>"), std::string::npos);
  const std::vector<std::string> pngs = embedded_pngs(html);
  ASSERT_EQ(pngs.size(), 3u);
  // The cut-away and the view from above show the red ball; the first picture is the hulls alone.
  for (size_t i = 1; i < pngs.size(); ++i) {
    const DecodedPng png = decode_png(dir_->write("violation-" + std::to_string(i) + ".png", pngs[i]));
    EXPECT_GT(red_pixels(png), 100u) << "picture " << i;
  }
}

TEST_F(AuditHtml, ChromiumShowsTheVerdictInItsBanner) {
  if (access(kChromium, X_OK) != 0)
    GTEST_SKIP() << kChromium << " is not installed (Debian package 'chromium', scripts/setup.sh): the reports are "
                 << "not opened in a browser";
  ASSERT_EQ(clean().status, 0) << clean().err;
  ASSERT_EQ(violation().status, 1) << violation().err;
  struct Report {
    std::string name, verdict, banner, other_banner;
  };
  for (const Report& report : {Report{"clean", "CLEAN", render::kCleanBannerColour, render::kViolationBannerColour},
                               Report{"violation", "VIOLATION: front_space_lost", render::kViolationBannerColour,
                                      render::kCleanBannerColour}}) {
    const std::string html = dir_->path(report.name + ".html");
    const std::string shot = dir_->path(report.name + "-screenshot.png");
    const hullcover::test::ChildOutcome shown =
        chromium(html, report.name + "-shot", {"--screenshot=" + shot, "--window-size=1200,1600"});
    ASSERT_TRUE(shown.exited && shown.status == 0) << "chromium " << (shown.timed_out ? "timed out" : "failed") << ": "
                                                   << slurp(dir_->path(report.name + "-shot.err"));
    const DecodedPng png = decode_png(shot);
    ASSERT_EQ(png.width, 1200) << "no screenshot";
    ASSERT_EQ(png.height, 1600);
    EXPECT_GT(hullcover::test::distinct_colours(png), 100u) << report.name;
    EXPECT_LT(hullcover::test::pixels_near(png, "#ffffff", 0), png.pixels.size() * 9 / 10) << "blank page";
    // The banner: a band across the page in the verdict's colour, and none of the other's.
    EXPECT_GT(hullcover::test::pixels_near(png, report.banner, 4), 40000u) << report.name;
    EXPECT_LT(hullcover::test::pixels_near(png, report.other_banner, 4), 500u) << report.name;

    const hullcover::test::ChildOutcome dumped = chromium(html, report.name + "-dom", {"--dump-dom"});
    ASSERT_TRUE(dumped.exited && dumped.status == 0) << slurp(dir_->path(report.name + "-dom.err"));
    const std::string dom = slurp(dir_->path(report.name + "-dom.out"));
    const size_t banner = dom.find("id=\"verdict\"");
    ASSERT_NE(banner, std::string::npos) << dom.substr(0, 500);
    EXPECT_EQ(dom.find(report.verdict, banner), dom.find('>', banner) + 1) << "the banner's text is the verdict";
  }
}

} // namespace
