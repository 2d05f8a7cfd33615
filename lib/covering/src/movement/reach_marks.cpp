#include "movement/reach_marks.h"

namespace hullcover::detail {

void keep_cells(const ReachMarks& marks, std::uint8_t kept, ReachGrid& grid) {
  grid.clear_blocks();
  std::vector<std::uint8_t> flags(kReachBlockCells);
  for (long long b = 0; b < marks.block_count(); ++b) {
    const Eigen::Vector3i block = marks.block_at(b);
    if (const std::uint8_t* bytes = marks.held(b)) {
      for (int c = 0; c < kReachBlockCells; ++c) flags[c] = (bytes[c] & kept) == kept;
      grid.set_block_cells(block, flags.data());
    } else {
      grid.set_block(block, marks.uniform(b) && (marks.uniform_byte(b) & kept) == kept);
    }
  }
}

} // namespace hullcover::detail
