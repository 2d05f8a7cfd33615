// write_file_atomically: the destination holds its old content or all of the
// new, whatever stops the write (a failing writer, a full disk, a kill).

#include "hullcover/geometry/atomic_file.h"

#include "temp_dir.h"

#include <gtest/gtest.h>

#include <csignal>
#include <fcntl.h>
#include <pthread.h>
#include <set>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace hullcover {
namespace {

using test::TempDir;

// Whether the folder's file system makes unnamed files; where it does not,
// a killed writer may leave its named temporary file (documented).
bool makes_unnamed_files(const std::string& folder) {
  const int fd = open(folder.c_str(), O_TMPFILE | O_WRONLY, 0600);
  if (fd < 0) return false;
  close(fd);
  return true;
}

// Runs `work` in a child process, so limits and kills stay out of the test
// runner; returns the child's raw wait status.
template <typename Work>
int in_child(Work work) {
  const pid_t child = fork();
  if (child == 0) _exit(work());
  int status = 0;
  waitpid(child, &status, 0);
  return status;
}

// Set only in a forked child: the next rename raises SIGTERM just before
// it, at the moment the finished file has its temporary name (see the
// rename below).
bool terminate_before_next_rename = false;

// Big enough to pass stdio's buffer and any small file-size limit.
const std::string kLargeContent(1 << 20, 'x');

TEST(AtomicFile, WritesTheContentAndNothingElse) {
  const TempDir dir;
  const std::string path = dir.path("out.txt");
  ASSERT_TRUE(write_file_atomically(path, std::string("hull 1\n")).ok());
  EXPECT_EQ(test::slurp(path), "hull 1\n");
  EXPECT_EQ(test::folder_entries(dir.path("")), std::set<std::string>{"out.txt"});
}

TEST(AtomicFile, ReplacesAnExistingFileWhole) {
  const TempDir dir;
  const std::string path = dir.write("out.txt", "old content that is longer than the new\n");
  ASSERT_TRUE(write_file_atomically(path, std::string("new\n")).ok());
  EXPECT_EQ(test::slurp(path), "new\n");
  EXPECT_EQ(test::folder_entries(dir.path("")), std::set<std::string>{"out.txt"});
}

TEST(AtomicFile, AWriterThatGivesUpLeavesTheOldFileAndNoTemporary) {
  const TempDir dir;
  const std::string path = dir.write("out.txt", "old\n");
  const Status s = write_file_atomically(path, [](std::FILE* out) {
    std::fputs("half of the new", out);
    return false;
  });
  EXPECT_EQ(s.code(), StatusCode::unwritable_file);
  EXPECT_EQ(test::slurp(path), "old\n");
  EXPECT_EQ(test::folder_entries(dir.path("")), std::set<std::string>{"out.txt"});
}

TEST(AtomicFile, AMissingFolderOrAFolderAtThePathIsAnErrorNamingIt) {
  const TempDir dir;
  const Status missing = write_file_atomically(dir.path("no/such/folder/out.txt"), std::string("x"));
  EXPECT_EQ(missing.code(), StatusCode::unwritable_file);
  EXPECT_NE(missing.message().find("no/such/folder/out.txt"), std::string::npos) << missing.message();
  ASSERT_EQ(mkdir(dir.path("taken").c_str(), 0700), 0);
  const Status folder = write_file_atomically(dir.path("taken"), std::string("x"));
  EXPECT_EQ(folder.code(), StatusCode::unwritable_file);
  EXPECT_EQ(test::folder_entries(dir.path("")), std::set<std::string>{"taken"});
  EXPECT_TRUE(test::folder_entries(dir.path("taken")).empty());
}

// A full disk, as the file-size limit makes one: writes fail with EFBIG
// (SIGXFSZ ignored, as a disk that is full raises no signal).
TEST(AtomicFile, AFullDiskLeavesTheOldFileAndNoTemporary) {
  const TempDir dir;
  const std::string path = dir.write("out.txt", "old\n");
  constexpr rlim_t kSmallFileLimit = 64 * 1024;
  const int status = in_child([&] {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{kSmallFileLimit, kSmallFileLimit};
    if (setrlimit(RLIMIT_FSIZE, &limit) != 0) return 3;
    const Status s = write_file_atomically(path, kLargeContent);
    if (s.ok()) return 4;
    return s.message().find("write failed") != std::string::npos ? 0 : 5;
  });
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "3: no limit, 4: the write succeeded, 5: another message";
  EXPECT_EQ(test::slurp(path), "old\n");
  EXPECT_EQ(test::folder_entries(dir.path("")), std::set<std::string>{"out.txt"});
}

// Killed half way through its content: the destination keeps its old content.
TEST(AtomicFile, AKillDuringTheWriteLeavesTheOldFile) {
  const TempDir dir;
  const std::string path = dir.write("out.txt", "old\n");
  const int status = in_child([&] {
    const Status s = write_file_atomically(path, [](std::FILE* out) {
      std::fwrite(kLargeContent.data(), 1, kLargeContent.size(), out);
      std::fflush(out);
      std::raise(SIGKILL);
      return true;
    });
    return s.ok() ? 0 : 1;
  });
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(test::slurp(path), "old\n");
  const std::set<std::string> left = test::folder_entries(dir.path(""));
  if (makes_unnamed_files(dir.path(""))) {
    EXPECT_EQ(left, std::set<std::string>{"out.txt"});
  } else {
    for (const std::string& name : left)
      EXPECT_TRUE(name == "out.txt" || name.rfind(".out.txt.hullcover-", 0) == 0) << name;
  }
}

TEST(AtomicFile, AStopSignalWhileTheFileHasItsTemporaryNameWaitsForTheRename) {
  // The moment InterruptedOutputs can land in, rarely: before the signals
  // were held there, a SIGTERM between naming the file and renaming it left
  // `.out.txt.hullcover-PID-0` behind and the old content (this test showed
  // it).
  const TempDir dir;
  const std::string path = dir.write("out.txt", "old\n");
  const int status = in_child([&] {
    // SIGTERM as a plain program gets it, whatever the runner set.
    std::signal(SIGTERM, SIG_DFL);
    sigset_t term;
    sigemptyset(&term);
    sigaddset(&term, SIGTERM);
    pthread_sigmask(SIG_UNBLOCK, &term, nullptr);
    terminate_before_next_rename = true;
    const Status s = write_file_atomically(path, std::string("new\n"));
    return s.ok() ? 0 : 1;
  });
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << "the signal was never delivered";
  EXPECT_EQ(test::slurp(path), "new\n");
  EXPECT_EQ(test::folder_entries(dir.path("")), std::set<std::string>{"out.txt"});
}

TEST(AtomicFile, ANewFileIsLinkedInPlaceWithNoTemporaryNameToLeave) {
  // A parallel bake writes its cell cache from worker threads, where a stop
  // signal taken by another thread does not wait for the rename: a new file
  // must never have a temporary name at all. With the rename interposed to
  // raise SIGTERM, a write that renamed would be stopped (the test above).
  const TempDir dir;
  if (!makes_unnamed_files(dir.path(""))) GTEST_SKIP() << "no O_TMPFILE here: a new file has a temporary name";
  const std::string path = dir.path("new.cell");
  const int status = in_child([&] {
    std::signal(SIGTERM, SIG_DFL);
    sigset_t term;
    sigemptyset(&term);
    sigaddset(&term, SIGTERM);
    pthread_sigmask(SIG_UNBLOCK, &term, nullptr);
    terminate_before_next_rename = true;
    const Status s = write_file_atomically(path, std::string("cell\n"));
    return s.ok() ? 0 : 1;
  });
  ASSERT_TRUE(WIFEXITED(status)) << "stopped: the new file went through a temporary name and a rename";
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(test::slurp(path), "cell\n");
  EXPECT_EQ(test::folder_entries(dir.path("")), std::set<std::string>{"new.cell"});
}

TEST(AtomicFile, ASymlinkAtTheDestinationIsReplacedNotWrittenThrough) {
  // The link in place refuses an existing name, a symlink's too (dangling
  // or not): the rename then replaces the link itself.
  const TempDir dir;
  const std::string target = dir.write("target.txt", "target\n");
  const std::string path = dir.path("out.txt");
  ASSERT_EQ(symlink(target.c_str(), path.c_str()), 0);
  const std::string dangling = dir.path("dangling.txt");
  ASSERT_EQ(symlink(dir.path("nothing").c_str(), dangling.c_str()), 0);
  ASSERT_TRUE(write_file_atomically(path, std::string("new\n")).ok());
  ASSERT_TRUE(write_file_atomically(dangling, std::string("also new\n")).ok());
  EXPECT_EQ(test::slurp(target), "target\n");
  EXPECT_EQ(test::slurp(path), "new\n");
  EXPECT_EQ(test::slurp(dangling), "also new\n");
  struct stat info {};
  ASSERT_EQ(lstat(path.c_str(), &info), 0);
  EXPECT_TRUE(S_ISREG(info.st_mode));
  EXPECT_EQ(test::folder_entries(dir.path("")), (std::set<std::string>{"dangling.txt", "out.txt", "target.txt"}));
}

} // namespace
} // namespace hullcover

// The C library's rename, interposed for the test above: a definition in the
// executable wins over the shared library's for the hullcover code linked
// into it. Every other caller gets the plain rename.
extern "C" int rename(const char* from, const char* to) noexcept {
  if (hullcover::terminate_before_next_rename) {
    hullcover::terminate_before_next_rename = false;
    std::raise(SIGTERM);
  }
  return renameat(AT_FDCWD, from, AT_FDCWD, to);
}
