// read_regular_file: what the hull readers accept as input. A FIFO must be
// refused at once (opening it for reading would wait for a writer forever),
// a device or folder refused, and the size limit applied before reading.

#include "hullcover/geometry/regular_file.h"

#include "temp_dir.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

namespace hullcover {
namespace {

TEST(RegularFile, ReadsARegularFileWhole) {
  const test::TempDir dir;
  const Result<std::string> read = read_regular_file(dir.write("h.obj", "o hull_0\n"));
  ASSERT_TRUE(read.ok()) << read.status().message();
  EXPECT_EQ(read.value(), "o hull_0\n");
}

TEST(RegularFile, RefusesFifosDevicesFoldersAndMissingPaths) {
  const test::TempDir dir;
  ASSERT_EQ(mkfifo(dir.path("pipe").c_str(), 0600), 0);
  EXPECT_EQ(read_regular_file(dir.path("pipe")).status().code(), StatusCode::unreadable_file); // returns, not waits
  EXPECT_EQ(read_regular_file("/dev/zero").status().code(), StatusCode::unreadable_file);
  EXPECT_EQ(read_regular_file(dir.path("")).status().code(), StatusCode::unreadable_file);
  EXPECT_EQ(read_regular_file(dir.path("missing")).status().code(), StatusCode::file_not_found);
}

TEST(RegularFile, AFileOverTheLimitIsRefusedNamingItsSize) {
  const test::TempDir dir;
  const std::string path = dir.write("big.hcw", std::string(100, 'x'));
  const Result<std::string> refused = read_regular_file(path, 99);
  EXPECT_EQ(refused.status().code(), StatusCode::limit_exceeded);
  EXPECT_NE(refused.status().message().find("100 bytes"), std::string::npos) << refused.status().message();
  EXPECT_TRUE(read_regular_file(path, 100).ok());
}

} // namespace
} // namespace hullcover
