#include "hullcover/geometry/atomic_file.h"

#include <cerrno>
#include <cstring>
#include <csignal>
#include <fcntl.h>
#include <memory>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

namespace hullcover {
namespace {

// Names a sibling of the destination gets while it is being made visible:
// hidden, and telling whoever finds one which program left it.
constexpr const char* kTemporaryInfix = ".hullcover-";
// Attempts at a free temporary name before giving up (each collision means
// another process is writing the same destination at this moment).
constexpr int kTemporaryNameAttempts = 64;
// New files get these permissions less the umask, as fopen's do.
constexpr mode_t kNewFileMode = 0666;

struct DestinationParts {
  std::string folder; ///< "." for a bare file name
  std::string name;
};

DestinationParts split_destination(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return {".", path};
  return {slash == 0 ? "/" : path.substr(0, slash), path.substr(slash + 1)};
}

Status failure(const std::string& path, const std::string& what, int error_number) {
  return {StatusCode::unwritable_file, path + ": " + what + ": " + std::strerror(error_number)};
}

// A stream over a file that exists only while it is open (O_TMPFILE), or,
// where the file system cannot make one, over a named temporary file that is
// removed unless it was renamed into place.
class TemporaryFile {
public:
  TemporaryFile(const DestinationParts& destination) : destination_(destination) {}
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile() { discard(); }

  // Opens the stream; errno tells why when it returns false.
  bool open() {
    int fd = ::open(destination_.folder.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, kNewFileMode);
    if (fd < 0) {
      if (errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL) return false;
      std::string pattern = sibling_prefix() + "XXXXXX";
      fd = ::mkstemp(pattern.data());
      if (fd < 0) return false;
      named_path_ = pattern;
      const mode_t mask = ::umask(0);
      ::umask(mask);
      ::fchmod(fd, kNewFileMode & ~mask);
    }
    stream_ = ::fdopen(fd, "w");
    if (stream_ == nullptr) {
      const int saved = errno;
      ::close(fd);
      errno = saved;
      return false;
    }
    return true;
  }

  std::FILE* stream() const { return stream_; }

  // Flushes the content to the disk; errno tells why when it returns false.
  // A full disk shows here at the latest.
  bool finish_content() {
    errno = 0;
    if (std::fflush(stream_) != 0 || std::ferror(stream_) != 0 || ::fsync(fileno(stream_)) != 0) {
      if (errno == 0) errno = EIO; // an earlier write set the error flag and errno moved on
      return false;
    }
    return true;
  }

  // Gives the finished file its name and closes the stream; errno tells why
  // when it returns false. An unnamed file with nothing at `path` yet is
  // linked there at once, complete (a link never replaces a file, so that
  // is atomic too), and never has a temporary name a stop could leave
  // behind: the cell cache's entries, written from worker threads that a
  // stop signal may not wait for, are all new files. Otherwise it gets a
  // temporary name, which replace() renames over `path`.
  bool name_and_close(const std::string& path) {
    if (named_path_.empty()) { // the name comes from the open descriptor
      if (::linkat(AT_FDCWD, descriptor_path().c_str(), AT_FDCWD, path.c_str(), AT_SYMLINK_FOLLOW) == 0) {
        if (close_stream()) return in_place_ = true;
        const int saved = errno; // a failure leaves no file where there was none
        ::unlink(path.c_str());
        errno = saved;
        return false;
      }
      if (errno != EEXIST) return false;
      return give_name();
    }
    return close_stream();
  }

  // Closes the stream and removes the temporary name, if any, now.
  void discard() {
    if (stream_ != nullptr) std::fclose(stream_);
    stream_ = nullptr;
    if (!named_path_.empty()) ::unlink(named_path_.c_str());
    named_path_.clear();
  }

  // Renames the finished file over `path`, unless it was linked there
  // already; errno tells why when it fails.
  bool replace(const std::string& path) {
    if (in_place_) return true;
    if (::rename(named_path_.c_str(), path.c_str()) != 0) return false;
    named_path_.clear();
    return true;
  }

private:
  std::string sibling_prefix() const { return destination_.folder + "/." + destination_.name + kTemporaryInfix; }

  // The unnamed file, as a path linkat can link from.
  std::string descriptor_path() const { return "/proc/self/fd/" + std::to_string(fileno(stream_)); }

  bool close_stream() {
    const bool closed = std::fclose(stream_) == 0;
    stream_ = nullptr;
    return closed;
  }

  // Links the unnamed file into the folder under a free temporary name (a
  // link cannot replace an existing file; the rename that follows can).
  bool give_name() {
    const std::string descriptor = descriptor_path();
    const std::string prefix = sibling_prefix() + std::to_string(::getpid()) + "-";
    for (int attempt = 0; attempt < kTemporaryNameAttempts; ++attempt) {
      std::string candidate = prefix + std::to_string(attempt);
      if (::linkat(AT_FDCWD, descriptor.c_str(), AT_FDCWD, candidate.c_str(), AT_SYMLINK_FOLLOW) == 0) {
        named_path_ = std::move(candidate); // no allocation between naming the file and recording it
        return close_stream();
      }
      if (errno != EEXIST) return false;
    }
    return false;
  }

  DestinationParts destination_;
  std::FILE* stream_ = nullptr;
  std::string named_path_;
  bool in_place_ = false; ///< linked at the destination itself: nothing to rename
};

// Holds back, on this thread, the signals that stop a program by default
// from a terminal or a supervisor (SIGINT, SIGTERM, SIGHUP, SIGQUIT) for as
// long as it lives: one that arrives meanwhile is delivered when it ends.
// Used while a finished file has its temporary name in the destination's
// folder, so that a stopped run never leaves that name behind.
class TerminationSignalsHeld {
public:
  TerminationSignalsHeld() {
    sigset_t held;
    sigemptyset(&held);
    for (const int signal_number : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) sigaddset(&held, signal_number);
    holding_ = ::pthread_sigmask(SIG_BLOCK, &held, &previous_) == 0;
  }
  TerminationSignalsHeld(const TerminationSignalsHeld&) = delete;
  TerminationSignalsHeld& operator=(const TerminationSignalsHeld&) = delete;
  ~TerminationSignalsHeld() {
    if (holding_) ::pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
  }

private:
  sigset_t previous_{};
  bool holding_ = false;
};

} // namespace

Status write_file_atomically(const std::string& path, const FileContentWriter& write_content) {
  if (path.empty() || path.back() == '/') return {StatusCode::unwritable_file, "'" + path + "': not a file name"};
  TemporaryFile file(split_destination(path));
  if (!file.open()) return failure(path, "cannot create a file in its folder", errno);
  if (!write_content(file.stream())) return {StatusCode::unwritable_file, path + ": the content could not be made"};
  if (!file.finish_content()) return failure(path, "write failed", errno);
  // From naming the file to the rename, or to removing the name again, a
  // stop signal waits.
  const TerminationSignalsHeld held;
  const bool named = file.name_and_close(path);
  if (!named || !file.replace(path)) {
    const int error_number = errno;
    file.discard();
    return failure(path, named ? "cannot replace it" : "write failed", error_number);
  }
  return Status::success();
}

Status write_file_atomically(const std::string& path, const std::string& content) {
  return write_file_atomically(path, [&content](std::FILE* out) {
    std::fwrite(content.data(), 1, content.size(), out); // a short write sets the error flag, checked after
    return true;
  });
}

} // namespace hullcover
