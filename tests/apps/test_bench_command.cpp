// `hullcover bench` run as a user would: what it writes must agree with
// what `decompose` and the files themselves say.

#include "command_run.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <sstream>
#include <vector>

namespace {

using hullcover::test::CommandRun;
using hullcover::test::run_hullcover;
using hullcover::test::slurp;
using hullcover::test::TempDir;

// A floor with two crates 0.1 apart.
std::string crates_obj() {
  std::ostringstream obj;
  int base = 1;
  const auto quad = [&](double ax, double ay, double az, double bx, double by, double bz, double cx, double cy,
                        double cz, double dx, double dy, double dz) {
    obj << "v " << ax << ' ' << ay << ' ' << az << "\nv " << bx << ' ' << by << ' ' << bz << "\nv " << cx << ' ' << cy
        << ' ' << cz << "\nv " << dx << ' ' << dy << ' ' << dz << "\nf " << base << ' ' << base + 1 << ' ' << base + 2
        << ' ' << base + 3 << '\n';
    base += 4;
  };
  quad(-5, 0, -5, -5, 0, 5, 5, 0, 5, 5, 0, -5); // floor, facing +y
  for (double x0 : {-1.05, 0.05}) {             // crates [x0, x0 + 1] x [0, 1] x [0, 1], faces out
    const double x1 = x0 + 1;
    quad(x0, 1, 0, x0, 1, 1, x1, 1, 1, x1, 1, 0); // top
    quad(x0, 0, 0, x0, 0, 1, x0, 1, 1, x0, 1, 0); // -x
    quad(x1, 0, 0, x1, 1, 0, x1, 1, 1, x1, 0, 1); // +x
    quad(x0, 0, 0, x0, 1, 0, x1, 1, 0, x1, 0, 0); // -z
    quad(x0, 0, 1, x1, 0, 1, x1, 1, 1, x0, 1, 1); // +z
  }
  return obj.str();
}

// The CSV as rows of column name -> text.
std::vector<std::map<std::string, std::string>> read_csv(const std::string& text) {
  std::vector<std::vector<std::string>> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> fields;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) fields.push_back(cell);
    if (!line.empty() && line.back() == ',') fields.emplace_back();
    lines.push_back(fields);
  }
  std::vector<std::map<std::string, std::string>> rows;
  for (size_t i = 1; i < lines.size(); ++i) {
    std::map<std::string, std::string> row;
    for (size_t c = 0; c < lines[0].size() && c < lines[i].size(); ++c) row[lines[0][c]] = lines[i][c];
    rows.push_back(row);
  }
  return rows;
}

int hull_groups(const std::string& obj) {
  int groups = 0;
  std::istringstream in(obj);
  for (std::string line; std::getline(in, line);) groups += line.rfind("o ", 0) == 0;
  return groups;
}

constexpr const char* kQuick = " --query-poses 64 --query-seconds 0.01 -q";

TEST(BenchCommand, EveryRowAgreesWithDecomposeTheFilesAndTheAudit) {
  TempDir dir;
  const std::string scene = dir.write("crates.obj", crates_obj());
  const CommandRun r = run_hullcover(
      dir, "bench " + scene + "@1 --agent-radius 0,0.3m --max-deviation 0 --out " + dir.path("out") + kQuick);
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  const auto rows = read_csv(slurp(dir.path("out/bench.csv")));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].at("setting"), "exact");
  EXPECT_EQ(rows[1].at("setting"), "r=0.3m");
  EXPECT_DOUBLE_EQ(std::stod(rows[1].at("agent_radius")), 0.3); // 1 unit per metre

  const std::vector<std::string> decompose_options = {"", " --agent-radius 0.3"};
  for (size_t i = 0; i < rows.size(); ++i) {
    const auto& row = rows[i];
    SCOPED_TRACE(row.at("setting"));
    // The hull count is decompose's at the same setting.
    const CommandRun d =
        run_hullcover(dir, "decompose " + scene + decompose_options[i] + " -o " + dir.path("d.obj") + " -q");
    ASSERT_EQ(d.status, 0) << d.err;
    EXPECT_EQ(std::stoi(row.at("hulls")), hull_groups(slurp(dir.path("d.obj"))));
    // The runtime file is there, as large as reported, and audits as the row says.
    const std::string hcw = dir.path(std::string("out/crates.") + (i == 0 ? "exact" : "r0.3m") + ".hcw");
    ASSERT_TRUE(std::filesystem::exists(hcw)) << hcw;
    EXPECT_EQ(std::stol(row.at("hcw_bytes")), static_cast<long>(std::filesystem::file_size(hcw)));
    const CommandRun audit = run_hullcover(dir, "audit " + scene + " " + hcw + decompose_options[i]);
    EXPECT_EQ(row.at("clean"), audit.status == 0 ? "yes" : "no") << audit.out;
    EXPECT_EQ(row.at("clean"), "yes");
    EXPECT_DOUBLE_EQ(std::stod(row.at("coverage_percent")), 100.0);
    // Both worlds were timed on every query kind.
    for (const char* kind : {"touches", "contacts", "ray"}) {
      EXPECT_GT(std::stod(row.at(std::string(kind) + "_hull_us")), 0.0) << kind;
      EXPECT_GT(std::stod(row.at(std::string(kind) + "_triangle_us")), 0.0) << kind;
    }
  }
  // Measured against the exact row of the same scene.
  EXPECT_NEAR(std::stod(rows[1].at("hull_change_vs_exact_percent")),
              100.0 * (std::stod(rows[1].at("hulls")) / std::stod(rows[0].at("hulls")) - 1.0), 1e-6);

  const std::string png = slurp(dir.path("out/bench.png"));
  ASSERT_GE(png.size(), 8u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  EXPECT_NE(slurp(dir.path("out/bench.svg")).find("<svg"), std::string::npos);
  const std::string markdown = slurp(dir.path("out/bench.md"));
  EXPECT_NE(markdown.find("| crates.obj | r=0.3m |"), std::string::npos) << markdown;
  EXPECT_EQ(r.out.find(markdown.substr(0, 40)), 0u); // the table is printed too
}

TEST(BenchCommand, MovementRowsAgreeWithDecomposeAndTheMovementAudit) {
  TempDir dir;
  const std::string scene = dir.write("crates.obj", crates_obj());
  const CommandRun r = run_hullcover(dir, "bench " + scene +
                                              "@1 --agent-radius 0,0.3m --max-deviation 0 --agent-reach exact,walk "
                                              "--agent-slop 0.02m,0.06m --out " +
                                              dir.path("out") + kQuick);
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  const auto rows = read_csv(slurp(dir.path("out/bench.csv")));
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0].at("reach"), "exact");
  EXPECT_EQ(rows[1].at("setting"), "r=0.3m");
  const char* slops[] = {"0.02", "0.06"};
  for (int i = 0; i < 2; ++i) {
    const auto& row = rows[2 + i];
    SCOPED_TRACE(row.at("setting"));
    EXPECT_EQ(row.at("setting"), std::string("walk r=0.3m slop=") + slops[i] + "m");
    EXPECT_EQ(row.at("reach"), "walk");
    EXPECT_DOUBLE_EQ(std::stod(row.at("slop")), std::stod(slops[i]));
    const std::string options = std::string(" --agent-radius 0.3 --agent-reach walk --agent-slop ") + slops[i];
    const CommandRun d = run_hullcover(dir, "decompose " + scene + options + " -o " + dir.path("d.obj") + " -q");
    ASSERT_EQ(d.status, 0) << d.err;
    EXPECT_EQ(std::stoi(row.at("hulls")), hull_groups(slurp(dir.path("d.obj"))));
    // Fewer hulls than the exact covering: the floor under the crates and
    // the gap between them are nobody's.
    EXPECT_LT(std::stoi(row.at("hulls")), std::stoi(rows[0].at("hulls")));
    const std::string hcw = dir.path(std::string("out/crates.walk_r0.3m_slop") + slops[i] + "m.hcw");
    ASSERT_TRUE(std::filesystem::exists(hcw)) << hcw;
    const CommandRun audit = run_hullcover(dir, "audit " + scene + " " + hcw + options);
    EXPECT_EQ(audit.status, 0) << audit.out;
    EXPECT_EQ(row.at("clean"), "yes");
    EXPECT_GT(std::stol(row.at("reachable_centres")), 0);
    EXPECT_GT(std::stol(row.at("touching_poses")), 0);
    EXPECT_EQ(row.at("sinking_centres"), "0");
    EXPECT_EQ(row.at("contacts_lost"), "0");
  }
  const std::string markdown = slurp(dir.path("out/bench.md"));
  EXPECT_NE(markdown.find("| crates.obj | walk r=0.3m slop=0.06m |"), std::string::npos) << markdown;
}

TEST(BenchCommand, LengthsResolveInMetresAndPercentOfTheDiagonal) {
  TempDir dir;
  const std::string scene = dir.write("crates.obj", crates_obj());
  const CommandRun r = run_hullcover(
      dir, "bench " + scene + "@20 --agent-radius 0 --max-deviation 0.005m,1% --out " + dir.path("out") + kQuick);
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  const auto rows = read_csv(slurp(dir.path("out/bench.csv")));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_DOUBLE_EQ(std::stod(rows[0].at("max_deviation")), 0.1); // 0.005 m at 20 units per metre
  const double diagonal = std::stod(rows[1].at("diagonal"));
  EXPECT_NEAR(std::stod(rows[1].at("max_deviation")), 0.01 * diagonal, 1e-9 * diagonal);
  EXPECT_NEAR(std::stod(rows[1].at("max_deviation_percent_of_diagonal")), 1.0, 1e-9);
}

TEST(BenchCommand, BadSweepsAndScenesExitWithTwoAndSaySo) {
  TempDir dir;
  const std::string scene = dir.write("crates.obj", crates_obj());
  for (const std::string& arguments :
       {scene + " --agent-radius 0.3x", scene + " --max-deviation -1", scene + "@0", scene + "@metres",
        dir.path("missing.obj"), scene + " --query-radius 0", scene + " --max-triangles 2",
        scene + " --agent-reach swim", scene + " --agent-reach walk --agent-radius 0",
        scene + " --agent-reach fly --agent-slop 0", scene + " --agent-reach walk --agent-slop 1q",
        scene + " --agent-slop 0.02m", scene + " --agent-radius 0.3m,0.3m"}) {
    const CommandRun r = run_hullcover(dir, "bench " + arguments + " --out " + dir.path("out") + kQuick);
    EXPECT_EQ(r.status, 2) << arguments;
    EXPECT_NE(r.err.find("error"), std::string::npos) << arguments << ": " << r.err;
  }
}

} // namespace
