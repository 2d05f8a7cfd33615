#pragma once
/// \file reach_moves.h
/// How the reach grid (reach_grid.h) follows an agent's moves, cell by
/// cell: where a walker stands and drops, and the floods from the seeds'
/// cells (flying: through every kept cell; walking: the one-way moves of
/// docs/definitions-and-proofs.md, "Movement coverings").

#include "movement/reach_cells.h"

#include "hullcover/covering/movement_options.h"
#include "hullcover/geometry/mesh.h"

#include <cstdint>
#include <vector>

namespace hullcover::detail {

/// Per-cell marks while the grid is built.
constexpr std::uint8_t kClear = 1;     // may hold a point at clearance >= r
constexpr std::uint8_t kStanding = 2;  // within a walkable face's standing envelope
constexpr std::uint8_t kDropping = 4;  // below a standing cell, falling straight down
constexpr std::uint8_t kSeeded = 8;    // reached from a seed
constexpr std::uint8_t kWalkable = 16; // clear, and standing or dropping: a walking agent's centre may be here

/// Cell range [lo, hi] (inclusive) of the cells meeting `box`, clamped to the grid.
void cell_range(const ReachGrid& grid, const Aabb& box, Eigen::Vector3i& lo, Eigen::Vector3i& hi);

/// Marks kStanding in the kept cells where an agent standing on walkable
/// face `face` may have a point of its axis (reach_moves.cpp says how).
void mark_standing(const ReachGrid& grid, const Mesh& mesh, const AgentShape& agent, int face,
                   std::vector<std::uint8_t>& marks);

/// Marks kDropping below every standing cell, down through kept cells.
void mark_drops(const ReachGrid& grid, const AgentShape& agent, std::vector<std::uint8_t>& marks);

/// Appends the grid's outer kept cells (where the sky beyond meets it).
void add_outer_cells(const ReachGrid& grid, const std::vector<std::uint8_t>& marks, std::vector<std::uint32_t>& out);

/// Floods kSeeded from `starts` through cells holding every bit of
/// `through`, across shared faces.
void flood(const ReachGrid& grid, std::vector<std::uint32_t> starts, std::uint8_t through,
           std::vector<std::uint8_t>& marks);

/// Floods kSeeded from `starts` as a walking agent moves: between standing
/// cells freely, from a standing cell into a dropping cell beside or below
/// it, from a dropping cell only straight down.
void flood_walking(const ReachGrid& grid, const AgentShape& agent, std::vector<std::uint32_t> starts,
                   std::vector<std::uint8_t>& marks);

} // namespace hullcover::detail
