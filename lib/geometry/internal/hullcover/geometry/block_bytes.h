#pragma once
/// \file block_bytes.h
/// A byte per cell of a large grid, kept in blocks of kSide cells a side:
/// a block is not yet classified, uniform (one byte for all its cells), or
/// held (a byte per cell). Only blocks whose cells differ hold bytes, so a
/// grid over a scene's box grows with the scene's surfaces, not its volume
/// (the movement decomposer's reach grid and the movement audit's lattice).

#include <Eigen/Core>

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace hullcover {

/// Blocks are classified (set_uniform or hold) once each, at once on
/// different blocks from several threads. Cells are read (get) and changed
/// (at) by several threads at once only while no block is being held (at
/// on a block already held), each thread changing cells of its own; else
/// by one thread at a time.
class BlockBytes {
public:
  /// Cells per side of a block (a power of 2), and cells in a block.
  static constexpr int kSide = 16;
  static constexpr int kCells = kSide * kSide * kSide;

  /// No block classified, over `dims` cells.
  explicit BlockBytes(const Eigen::Vector3i& dims);

  const Eigen::Vector3i& dims() const { return dims_; }
  const Eigen::Vector3i& block_dims() const { return block_dims_; }
  long long block_count() const { return static_cast<long long>(state_.size()); }
  Eigen::Vector3i block_at(long long b) const {
    return {static_cast<int>(b % block_dims_.x()), static_cast<int>((b / block_dims_.x()) % block_dims_.y()),
            static_cast<int>(b / (static_cast<long long>(block_dims_.x()) * block_dims_.y()))};
  }
  long long block_index(const Eigen::Vector3i& block) const {
    return (static_cast<long long>(block.z()) * block_dims_.y() + block.y()) * block_dims_.x() + block.x();
  }
  static Eigen::Vector3i block_of(const Eigen::Vector3i& cell) { return cell / kSide; }
  /// Where cell (i, j, k) lies in its block's bytes (x fastest).
  static int in_block(int i, int j, int k) { return ((k % kSide) * kSide + j % kSide) * kSide + i % kSide; }

  bool classified(long long b) const { return state_[b] != kUnclassified; }
  bool uniform(long long b) const { return state_[b] == kUniform; }
  /// The block's byte when uniform.
  std::uint8_t& uniform_byte(long long b) { return uniform_[b]; }
  std::uint8_t uniform_byte(long long b) const { return uniform_[b]; }
  /// The block's bytes when held (nullptr otherwise).
  std::uint8_t* held(long long b) { return state_[b] >= 0 ? bytes_[state_[b]].get() : nullptr; }
  const std::uint8_t* held(long long b) const { return state_[b] >= 0 ? bytes_[state_[b]].get() : nullptr; }

  /// Classifies block `b` as uniform, `value` in every cell.
  void set_uniform(long long b, std::uint8_t value);
  /// Gives block `b` a byte per cell, each `fill`, and returns them.
  std::uint8_t* hold(long long b, std::uint8_t fill);

  /// The byte of cell (i, j, k): 0 in a block not classified.
  std::uint8_t get(int i, int j, int k) const {
    const long long b = block_index(block_of({i, j, k}));
    const std::int32_t s = state_[b];
    if (s >= 0) return bytes_[s][in_block(i, j, k)];
    return s == kUniform ? uniform_[b] : std::uint8_t{0};
  }
  /// The byte of cell (i, j, k) to change: a uniform block is held first
  /// (with its byte in every cell). Only on a classified block.
  std::uint8_t& at(int i, int j, int k) {
    const long long b = block_index(block_of({i, j, k}));
    if (state_[b] < 0) hold(b, uniform_[b]);
    return bytes_[state_[b]][in_block(i, j, k)];
  }
  /// Cells held a byte each (read while blocks are held at once, too).
  long long cells_held() const { return holding_->blocks.load(std::memory_order_relaxed) * kCells; }

private:
  static constexpr std::int32_t kUnclassified = -1;
  static constexpr std::int32_t kUniform = -2;
  Eigen::Vector3i dims_, block_dims_;
  std::vector<std::int32_t> state_;   // per block: kUnclassified, kUniform, or its slot in bytes_
  std::vector<std::uint8_t> uniform_; // per block, when uniform
  std::vector<std::unique_ptr<std::uint8_t[]>> bytes_;
  // The lock that hold() takes, and the count of blocks held, apart so that
  // the store can be moved.
  struct Holding {
    std::mutex lock;
    std::atomic<long long> blocks{0};
  };
  std::unique_ptr<Holding> holding_ = std::make_unique<Holding>();
};

/// A cell of a BlockBytes grid packed into one number, for the stacks of
/// a flood: 21 bits an axis.
using CellKey = std::uint64_t;
/// Cells along an axis the packing holds.
inline constexpr int kMostCellsAlongAnAxis = 1 << 21;
inline CellKey cell_key(int i, int j, int k) {
  return static_cast<CellKey>(i) | (static_cast<CellKey>(j) << 21) | (static_cast<CellKey>(k) << 42);
}
inline Eigen::Vector3i cell_of(CellKey key) {
  constexpr CellKey mask = (CellKey{1} << 21) - 1;
  return {static_cast<int>(key & mask), static_cast<int>((key >> 21) & mask), static_cast<int>(key >> 42)};
}

/// Sets the bit `reached` in every cell connected to `cells` or to the
/// uniform blocks `blocks` through cells whose byte holds every bit of
/// `through`, across shared faces (starts included, when they hold it).
/// A uniform block is reached whole, in one step; a block not classified is
/// never entered.
void flood_through(BlockBytes& bytes, const std::vector<CellKey>& cells, const std::vector<long long>& blocks,
                   std::uint8_t through, std::uint8_t reached);

} // namespace hullcover
