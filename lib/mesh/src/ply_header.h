#pragma once
// A PLY file's header, read the way Assimp reads it: shared by the PLY
// pre-check (ply_file_checks.h) and the project's PLY reader
// (ply_reader.h), so both see the same elements.

#include "ply_walk.h"

#include "hullcover/geometry/status.h"

#include <cstdint>
#include <istream>
#include <vector>

namespace hullcover::detail {

/// What a PLY header declares, and where its body starts.
struct PlyHeader {
  bool ascii = false;
  bool big_endian = false;
  std::vector<Element> elements;
  std::uint64_t after_line = 0;  ///< just past the byte ending the 'end_header' line: Assimp's next line read
  std::uint64_t line_number = 1; ///< of the line at after_line
  std::uint64_t data_at = 0;     ///< binary data: past the 'end_header' line's "\n" or "\r\n"
};

/// Reads the header at the start of `in` (`file_bytes` long) the way Assimp
/// does (its line ends, its word separators, a property only in the
/// unbroken run of lines after its element's), within kMaxPlyHeaderBytes.
/// Fails with `unreadable_file` and a one-line message.
Status read_ply_header(std::istream& in, std::uint64_t file_bytes, PlyHeader& h);

} // namespace hullcover::detail
