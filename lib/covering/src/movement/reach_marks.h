#pragma once
/// \file reach_marks.h
/// The reach grid's marks while it is built (reach_grid.cpp): a byte per
/// cell in blocks (block_bytes.h), uniform over open air and solid ground.

#include "movement/reach_cells.h"

#include "hullcover/geometry/block_bytes.h"

#include <cstdint>

namespace hullcover::detail {

/// Per-cell marks while the grid is built.
constexpr std::uint8_t kClear = 1;     // may hold a point at clearance >= r
constexpr std::uint8_t kStanding = 2;  // within a walkable face's standing envelope
constexpr std::uint8_t kDropping = 4;  // below a standing cell, falling straight down
constexpr std::uint8_t kSeeded = 8;    // reached from a seed
constexpr std::uint8_t kWalkable = 16; // clear, and standing or dropping: a walking agent's centre may be here

/// The marks of the reach grid's cells while it is built.
using ReachMarks = BlockBytes;

/// The grid's cells from `marks`: a cell is kept when its marks hold `kept`.
void keep_cells(const ReachMarks& marks, std::uint8_t kept, ReachGrid& grid);

} // namespace hullcover::detail
