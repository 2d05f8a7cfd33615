#pragma once
/// \file reach_moves.h
/// How the reach grid (reach_grid.h) follows an agent's moves, cell by
/// cell: where a walker stands and drops, and the floods from the seeds'
/// cells (flying: through every kept cell; walking: the one-way moves of
/// docs/definitions-and-proofs.md, "Movement coverings").

#include "movement/reach_marks.h"

#include "hullcover/covering/movement_options.h"
#include "hullcover/geometry/mesh.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace hullcover::detail {

/// Where the floods start: cells, and (flying) whole uniform blocks.
struct FloodStarts {
  std::vector<CellKey> cells;
  std::vector<long long> blocks;
};

/// Cell range [lo, hi] (inclusive) of the cells meeting `box`, clamped to the grid.
void cell_range(const ReachGrid& grid, const Aabb& box, Eigen::Vector3i& lo, Eigen::Vector3i& hi);

/// The box where an agent standing on walkable face `face` may have a
/// point of its axis: the face's box grown by r across and climb + H - r up.
Aabb standing_box(const Mesh& mesh, const AgentShape& agent, int face);

/// Marks kStanding in the kept cells where an agent standing on walkable
/// face `face` may have a point of its axis (reach_moves.cpp says how).
/// The blocks meeting standing_box(face) must be classified. Stops, false,
/// when more than `most_held` cells would be held one by one.
bool mark_standing(const ReachGrid& grid, const Mesh& mesh, const AgentShape& agent, int face, long long most_held,
                   ReachMarks& marks);

/// Marks kDropping below every standing cell, down through kept cells,
/// classifying (`classify`) each block a fall enters. Stops, false, when
/// more than `most_held` cells would be held one by one.
bool mark_drops(const AgentShape& agent, long long most_held, ReachMarks& marks,
                const std::function<void(long long)>& classify);

/// Adds the grid's outer kept cells and blocks (where the sky beyond meets it).
void add_outer_cells(ReachMarks& marks, FloodStarts& out);

/// Floods kSeeded from `starts` through cells holding every bit of
/// `through`, across shared faces; a uniform block holding `through` is
/// flooded whole.
void flood(const FloodStarts& starts, std::uint8_t through, ReachMarks& marks);

/// Floods kSeeded from `starts` as a walking agent moves: between standing
/// cells freely, from a standing cell into a dropping cell beside or below
/// it, from a dropping cell only straight down.
void flood_walking(const AgentShape& agent, std::vector<CellKey> starts, ReachMarks& marks);

} // namespace hullcover::detail
