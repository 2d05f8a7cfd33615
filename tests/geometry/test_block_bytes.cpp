// The block store of a byte per cell (block_bytes.h): uniform blocks read
// as their byte, a changed cell holds its block and changes that cell
// alone, and blocks held from several threads at once stay apart.

#include "hullcover/geometry/block_bytes.h"
#include "hullcover/geometry/parallel_for.h"

#include <gtest/gtest.h>

#include <cstdint>

namespace hullcover {
namespace {

TEST(BlockBytes, AUniformBlockReadsAsItsByteUntilACellChanges) {
  // Not a whole number of blocks along any axis: the last blocks are partial.
  const Eigen::Vector3i dims(20, 17, 33);
  BlockBytes bytes(dims);
  EXPECT_EQ(bytes.block_dims(), Eigen::Vector3i(2, 2, 3));
  EXPECT_EQ(bytes.block_count(), 12);
  EXPECT_EQ(bytes.get(19, 16, 32), 0); // not classified
  EXPECT_FALSE(bytes.classified(bytes.block_count() - 1));

  const long long last = bytes.block_index(BlockBytes::block_of({19, 16, 32}));
  EXPECT_EQ(last, bytes.block_count() - 1);
  bytes.set_uniform(last, 5);
  EXPECT_TRUE(bytes.uniform(last));
  EXPECT_EQ(bytes.cells_held(), 0);
  for (int k = 32; k < 33; ++k)
    for (int j = 16; j < 17; ++j)
      for (int i = 16; i < 20; ++i) EXPECT_EQ(bytes.get(i, j, k), 5);

  bytes.at(18, 16, 32) |= 2;
  EXPECT_FALSE(bytes.uniform(last));
  ASSERT_NE(bytes.held(last), nullptr);
  EXPECT_EQ(bytes.cells_held(), BlockBytes::kCells);
  EXPECT_EQ(bytes.get(18, 16, 32), 7);
  EXPECT_EQ(bytes.get(17, 16, 32), 5);
  EXPECT_EQ(bytes.get(19, 16, 32), 5);
  // The block's own order: x fastest.
  EXPECT_EQ(BlockBytes::in_block(18, 16, 32), (0 * BlockBytes::kSide + 0) * BlockBytes::kSide + 2);
  EXPECT_EQ(bytes.held(last)[BlockBytes::in_block(18, 16, 32)], 7);
  EXPECT_EQ(bytes.block_at(last), Eigen::Vector3i(1, 1, 2));
}

TEST(BlockBytes, BlocksHeldFromSeveralThreadsAtOnceStayApart) {
  const Eigen::Vector3i dims(64, 64, 64);
  BlockBytes bytes(dims);
  const long long blocks = bytes.block_count();
  // Every other block held, filled with a byte of its own; the rest uniform.
  parallel_for(static_cast<int>(blocks), 4, [&](int b) {
    if (b % 2)
      bytes.hold(b, static_cast<std::uint8_t>(b));
    else
      bytes.set_uniform(b, 200);
  });
  EXPECT_EQ(bytes.cells_held(), blocks / 2 * BlockBytes::kCells);
  for (long long b = 0; b < blocks; ++b) {
    const Eigen::Vector3i lo = bytes.block_at(b) * BlockBytes::kSide;
    const std::uint8_t expected = b % 2 ? static_cast<std::uint8_t>(b) : 200;
    for (int c = 0; c < BlockBytes::kSide; ++c) {
      ASSERT_EQ(bytes.get(lo.x() + c, lo.y(), lo.z()), expected) << "block " << b;
      ASSERT_EQ(bytes.get(lo.x(), lo.y() + c, lo.z() + BlockBytes::kSide - 1), expected) << "block " << b;
    }
  }
}

// Three layers of blocks: open (uniform) below and above, and between them
// held blocks with a wall across at z = 20, open or not at one cell. The
// flood from a corner block reaches the top through the hole alone, and
// never enters a block not classified.
TEST(BlockBytes, AFloodCrossesUniformBlocksWholeAndAWallOnlyAtItsHole) {
  constexpr std::uint8_t kOpen = 1, kReached = 2;
  for (bool hole : {true, false}) {
    SCOPED_TRACE(hole);
    BlockBytes bytes(Eigen::Vector3i(48, 48, 48));
    for (long long b = 0; b < bytes.block_count(); ++b) {
      const Eigen::Vector3i block = bytes.block_at(b);
      if (block.z() != 1) {
        if (block != Eigen::Vector3i(2, 2, 0)) bytes.set_uniform(b, kOpen); // that one stays not classified
        continue;
      }
      std::uint8_t* held = bytes.hold(b, kOpen);
      const Eigen::Vector3i lo = block * BlockBytes::kSide;
      for (int j = lo.y(); j < lo.y() + BlockBytes::kSide; ++j)
        for (int i = lo.x(); i < lo.x() + BlockBytes::kSide; ++i)
          if (!(hole && i == 40 && j == 40)) held[BlockBytes::in_block(i, j, 20)] = 0;
    }
    flood_through(bytes, {}, {0}, kOpen, kReached);
    EXPECT_TRUE(bytes.get(47, 20, 0) & kReached);
    EXPECT_TRUE(bytes.get(3, 30, 19) & kReached);
    EXPECT_FALSE(bytes.get(3, 30, 20) & kReached); // the wall
    EXPECT_EQ((bytes.get(3, 30, 21) & kReached) != 0, hole);
    EXPECT_EQ((bytes.get(0, 0, 47) & kReached) != 0, hole);
    EXPECT_FALSE(bytes.classified(bytes.block_index({2, 2, 0})));
  }
}

} // namespace
} // namespace hullcover
