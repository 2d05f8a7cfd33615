#pragma once
// The PLY pre-check (scene_file_checks.h): what a PLY file declares, held
// against its bytes and against how Assimp will read them, before Assimp
// allocates for it.

#include "hullcover/geometry/status.h"

#include <cstdint>
#include <fstream>

namespace hullcover::detail {

/// Checks the PLY file in `in` (`file_bytes` long). The header must end
/// within kMaxPlyHeaderBytes, be read the same way by Assimp (one format
/// line, every property inside its element's list, element names Assimp
/// counts) and declare elements that fit the bytes after it. When an element
/// has a list property the body is walked element by element: each list's
/// length must fit the bytes left (binary: length x item size; ASCII: two
/// bytes an item), so Assimp, which sizes a list before reading it, never
/// allocates more than a multiple of the file's size. ASCII bodies are
/// walked twice: by tokens, as the format has it, and by lines, as Assimp
/// reads them (one element a line). Fails with `unreadable_file` and a
/// one-line message naming the element, the declared length and the bytes
/// left.
Status check_ply(std::ifstream& in, std::uint64_t file_bytes);

} // namespace hullcover::detail
