#include "hullcover/geometry/mapped_file.h"

#include <algorithm>
#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace hullcover {

Result<std::unique_ptr<MappedFile>> MappedFile::open(const std::string& path) {
  // O_NONBLOCK: a FIFO would otherwise hold the open until a writer came.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    if (errno == ENOENT) return Status{StatusCode::file_not_found, path + ": no such file"};
    return Status{StatusCode::unreadable_file, path + ": " + std::strerror(errno)};
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    return Status{StatusCode::unreadable_file, path + ": not a regular file"};
  }
  if (st.st_size <= 0) {
    ::close(fd);
    return Status{StatusCode::unreadable_file, path + ": empty file"};
  }
  const auto size = static_cast<std::size_t>(st.st_size);
  void* map = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
  if (map == MAP_FAILED) {
    const int map_error = errno;
    ::close(fd);
    return Status{StatusCode::unreadable_file, path + ": cannot map: " + std::strerror(map_error)};
  }
  // Reads jump about (tree walks, per-face tables): no read-ahead, which
  // would also bring the file into the cache in large blocks that a
  // mapping takes in whole, filling memory with pages no cell asked for.
  ::posix_fadvise(fd, 0, 0, POSIX_FADV_RANDOM);
  ::madvise(map, size, MADV_RANDOM);
  return std::unique_ptr<MappedFile>(new MappedFile(fd, static_cast<const unsigned char*>(map), size));
}

MappedFile::~MappedFile() {
  ::munmap(const_cast<unsigned char*>(data_), size_);
  ::close(fd_);
}

bool MappedFile::read(std::size_t offset, void* out, std::size_t bytes) const {
  if (offset > size_ || bytes > size_ - offset) return false;
  auto* to = static_cast<unsigned char*>(out);
  while (bytes > 0) {
    const ssize_t got = ::pread(fd_, to, bytes, static_cast<off_t>(offset));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return false;
    to += got;
    offset += static_cast<std::size_t>(got);
    bytes -= static_cast<std::size_t>(got);
  }
  return true;
}

void drop_cached_pages(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return;
  ::posix_fadvise(fd, 0, 0, POSIX_FADV_DONTNEED);
  ::close(fd);
}

void MappedFile::release_pages(std::size_t offset, std::size_t bytes) const {
  const auto page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
  if (offset >= size_) return;
  bytes = std::min(bytes, size_ - offset);
  const std::size_t first = (offset + page - 1) / page * page;
  const std::size_t last = (offset + bytes) / page * page;
  // The last page of the file is whole in memory even where the file ends
  // inside it.
  const std::size_t end = offset + bytes == size_ ? (size_ + page - 1) / page * page : last;
  if (end <= first) return;
  // A private read-only mapping's pages are only ever copies of the file's:
  // dropped, they are read again when touched.
  ::madvise(const_cast<unsigned char*>(data_) + first, end - first, MADV_DONTNEED);
}

} // namespace hullcover
