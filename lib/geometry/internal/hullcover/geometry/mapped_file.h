#pragma once
/// \file mapped_file.h
/// A regular file mapped read-only into memory: a prepared scene file that
/// a bake's workers read in place (hullcover/covering/staged_decomposition.h).
/// Only the pages a worker reads are brought into memory, and it can hand
/// them back between tasks, so its resident memory follows the work at hand
/// rather than the file's size.

#include "hullcover/geometry/status.h"

#include <cstddef>
#include <memory>
#include <string>

namespace hullcover {

/// A read-only mapping of a whole regular file; unmapped when destroyed.
/// Reading its bytes is safe from many threads.
class MappedFile {
public:
  /// Maps `path`. Opens without blocking (a FIFO is refused, not waited on)
  /// and maps only a non-empty regular file. Fails with `file_not_found`,
  /// `unreadable_file` (a folder, device, empty file, or a failed map) with
  /// a message naming the file.
  [[nodiscard]] static Result<std::unique_ptr<MappedFile>> open(const std::string& path);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  const unsigned char* data() const { return data_; }
  /// Copies `bytes` bytes at `offset` to `out` by reading the file, not the
  /// mapping: what is read this way takes no memory of the process (a
  /// checksum pass over the whole file). False on a read error or past the
  /// end.
  bool read(std::size_t offset, void* out, std::size_t bytes) const;
  std::size_t size() const { return size_; }
  /// Hands the pages of [offset, offset + bytes) back to the system (they
  /// are read from the file again when next touched): the mapping stays
  /// valid, and what it reads does not change. Rounded inward to whole
  /// pages.
  void release_pages(std::size_t offset, std::size_t bytes) const;
  /// release_pages over the whole file.
  void release_pages() const { release_pages(0, size_); }

private:
  MappedFile(int fd, const unsigned char* data, std::size_t size) : fd_(fd), data_(data), size_(size) {}
  int fd_;
  const unsigned char* data_;
  std::size_t size_;
};

/// Asks the system to drop the pages of `path` it holds in its cache (a file
/// just written), so that readers that map it bring in only the pages they
/// read, one by one, instead of pages the writer left in large blocks that
/// a mapping takes in whole. Only a hint: nothing happens where the system
/// declines.
void drop_cached_pages(const std::string& path);

} // namespace hullcover
