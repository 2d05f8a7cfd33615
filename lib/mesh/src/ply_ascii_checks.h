#pragma once
// The PLY pre-check's walks over an ASCII body (ply_file_checks.h). Each
// starts at the body's first byte and fails with `unreadable_file` on a list
// longer than the bytes left could hold, or data that ends too soon.

#include "ply_walk.h"

#include <cstdint>
#include <vector>

namespace hullcover::detail {

/// The PLY format's reading of an ASCII body: whitespace-separated tokens,
/// elements in any layout of lines.
Status walk_ascii_tokens(BodyReader& body, const std::vector<Element>& elements);

/// Assimp's reading of an ASCII body: one element a line, the first at
/// `line_number` (for messages); `data_bytes` is the body's size, which bounds
/// the list items Assimp keeps all at once. Values Assimp would not read
/// whole fail too, since it would read the rest as the next value.
Status walk_assimp_lines(BodyReader& body, const std::vector<Element>& elements, std::uint64_t line_number,
                         std::uint64_t data_bytes);

} // namespace hullcover::detail
