#include "hullcover/geometry/regular_file.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace hullcover {
namespace {

// Closes the descriptor however the read ends.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

} // namespace

Result<std::string> read_regular_file(const std::string& path, std::uint64_t max_bytes) {
  // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer.
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) {
    if (errno == ENOENT || errno == ENOTDIR) return Status{StatusCode::file_not_found, path + ": no such file"};
    return Status{StatusCode::unreadable_file, path + ": cannot open: " + std::strerror(errno)};
  }
  struct stat info {};
  if (::fstat(file.fd, &info) != 0) return Status{StatusCode::unreadable_file, path + ": cannot read its status"};
  if (!S_ISREG(info.st_mode)) return Status{StatusCode::unreadable_file, path + ": not a regular file"};
  const auto size = static_cast<std::uint64_t>(info.st_size);
  if (size > max_bytes)
    return Status{StatusCode::limit_exceeded,
                  path + ": " + std::to_string(size) + " bytes, more than the limit of " + std::to_string(max_bytes)};
  std::string content(static_cast<size_t>(size), '\0');
  size_t done = 0;
  while (done < content.size()) {
    const ssize_t got = ::read(file.fd, content.data() + done, content.size() - done);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) return Status{StatusCode::unreadable_file, path + ": read failed: " + std::strerror(errno)};
    if (got == 0) break; // shrank while read: keep what is there
    done += static_cast<size_t>(got);
  }
  content.resize(done);
  return content;
}

} // namespace hullcover
