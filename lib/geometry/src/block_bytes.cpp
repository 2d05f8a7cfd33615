#include "hullcover/geometry/block_bytes.h"

#include <algorithm>

namespace hullcover {

BlockBytes::BlockBytes(const Eigen::Vector3i& dims) : dims_(dims), block_dims_((dims.array() + kSide - 1) / kSide) {
  const size_t blocks = static_cast<size_t>(block_dims_.x()) * block_dims_.y() * block_dims_.z();
  state_.assign(blocks, kUnclassified);
  uniform_.assign(blocks, 0);
}

void BlockBytes::set_uniform(long long b, std::uint8_t value) {
  state_[b] = kUniform;
  uniform_[b] = value;
}

std::uint8_t* BlockBytes::hold(long long b, std::uint8_t fill) {
  auto block = std::make_unique<std::uint8_t[]>(kCells);
  std::fill(block.get(), block.get() + kCells, fill);
  std::uint8_t* bytes = block.get();
  // The slot list grows under the lock; the block's own state is written
  // by this call alone.
  std::lock_guard<std::mutex> lock(holding_->lock);
  state_[b] = static_cast<std::int32_t>(bytes_.size());
  bytes_.push_back(std::move(block));
  holding_->blocks.fetch_add(1, std::memory_order_relaxed);
  return bytes;
}

namespace {

// The flood's stacks: a cell enters when it holds `through` and is not yet
// reached; a uniform block enters whole.
struct Flooding {
  BlockBytes& bytes;
  std::uint8_t through;
  std::uint8_t reached;
  std::vector<CellKey> cells;
  std::vector<long long> blocks;

  void visit(int i, int j, int k) {
    const long long b = bytes.block_index(BlockBytes::block_of({i, j, k}));
    if (bytes.uniform(b)) {
      visit_block(b);
      return;
    }
    std::uint8_t* held = bytes.held(b);
    if (!held) return;
    std::uint8_t& m = held[BlockBytes::in_block(i, j, k)];
    if ((m & reached) || (m & through) != through) return;
    m |= reached;
    cells.push_back(cell_key(i, j, k));
  }
  void visit_block(long long b) {
    if (!bytes.uniform(b)) return;
    std::uint8_t& m = bytes.uniform_byte(b);
    if ((m & reached) || (m & through) != through) return;
    m |= reached;
    blocks.push_back(b);
  }
  // Every cell of block `b` is reached: so is every cell across its faces.
  void spread_from_block(long long b) {
    const Eigen::Vector3i block = bytes.block_at(b);
    const Eigen::Vector3i& d = bytes.dims();
    for (int a = 0; a < 3; ++a)
      for (int s = -1; s <= 1; s += 2) {
        Eigen::Vector3i next = block;
        next[a] += s;
        if (next[a] < 0 || next[a] >= bytes.block_dims()[a]) continue;
        const long long nb = bytes.block_index(next);
        if (bytes.uniform(nb)) {
          visit_block(nb);
          continue;
        }
        if (!bytes.held(nb)) continue;
        // The layer of the neighbour's cells against this block.
        Eigen::Vector3i lo = next * BlockBytes::kSide;
        Eigen::Vector3i hi = (lo.array() + BlockBytes::kSide).min(d.array()) - 1;
        if (s > 0)
          hi[a] = lo[a];
        else
          lo[a] = hi[a];
        for (int k = lo.z(); k <= hi.z(); ++k)
          for (int j = lo.y(); j <= hi.y(); ++j)
            for (int i = lo.x(); i <= hi.x(); ++i) visit(i, j, k);
      }
  }
  void spread_from_cell(CellKey key) {
    const Eigen::Vector3i c = cell_of(key);
    for (int a = 0; a < 3; ++a)
      for (int s = -1; s <= 1; s += 2) {
        Eigen::Vector3i n = c;
        n[a] += s;
        if (n[a] < 0 || n[a] >= bytes.dims()[a]) continue;
        visit(n.x(), n.y(), n.z());
      }
  }
};

} // namespace

void flood_through(BlockBytes& bytes, const std::vector<CellKey>& cells, const std::vector<long long>& blocks,
                   std::uint8_t through, std::uint8_t reached) {
  Flooding flooding{bytes, through, reached, {}, {}};
  for (CellKey key : cells) {
    const Eigen::Vector3i c = cell_of(key);
    flooding.visit(c.x(), c.y(), c.z());
  }
  for (long long b : blocks) flooding.visit_block(b);
  while (!flooding.cells.empty() || !flooding.blocks.empty()) {
    if (!flooding.blocks.empty()) {
      const long long b = flooding.blocks.back();
      flooding.blocks.pop_back();
      flooding.spread_from_block(b);
      continue;
    }
    const CellKey key = flooding.cells.back();
    flooding.cells.pop_back();
    flooding.spread_from_cell(key);
  }
}

} // namespace hullcover
