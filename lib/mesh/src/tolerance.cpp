#include "hullcover/mesh/tolerance.h"

#include "disjoint_sets.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hullcover {
namespace {

// Rounding error the coordinates within `box` may carry: the mesh's bound,
// or its relative bound at the box's own magnitude when it gives one (a
// float32 import rounds each coordinate at its own magnitude).
double coordinate_error_in(const Mesh& mesh, const Aabb& box) {
  const double magnitude = std::max(box.min.cwiseAbs().maxCoeff(), box.max.cwiseAbs().maxCoeff());
  const double input_error = mesh.coordinate_relative_error > 0.0
                                 ? std::min(mesh.coordinate_error, mesh.coordinate_relative_error * magnitude)
                                 : mesh.coordinate_error;
  const double arithmetic_error = magnitude * std::numeric_limits<double>::epsilon();
  return std::max(input_error, arithmetic_error);
}

// How far apart two boxes are along the axis that separates them most (0
// when they meet): boxes each grown by less than half of it do not meet.
double box_gap(const Aabb& a, const Aabb& b) {
  double gap = 0.0;
  for (int axis = 0; axis < 3; ++axis) gap = std::max({gap, b.min[axis] - a.max[axis], a.min[axis] - b.max[axis]});
  return gap;
}

} // namespace

PlaceTolerance::PlaceTolerance(const Tolerance& tolerance) : tolerance_(&tolerance), zones_(tolerance.island_zones) {}

void PlaceTolerance::zones_meeting(const Aabb& box, std::vector<int>& out) const {
  std::vector<int> met;
  zones_.overlapping(box, met);
  // The tree's boxes are rounded outward to float: ask the zones themselves.
  for (int i : met)
    if (boxes_overlap(tolerance_->island_zones[i], box)) out.push_back(i);
}

double PlaceTolerance::at(const Aabb& box) const {
  std::vector<int> met;
  zones_meeting(box, met);
  double smallest = std::numeric_limits<double>::infinity();
  for (int i : met) smallest = std::min(smallest, tolerance_->island_lengths[i]);
  return std::isfinite(smallest) ? smallest : tolerance_->length;
}

void PlaceTolerance::smaller_zones_meeting(const Aabb& box, double length, std::vector<int>& out) const {
  std::vector<int> met;
  zones_meeting(box, met);
  for (int i : met)
    if (tolerance_->island_lengths[i] < length) out.push_back(i);
}

double Tolerance::largest_length() const {
  double largest = length;
  for (double l : island_lengths) largest = std::max(largest, l);
  return largest;
}

Result<Tolerance> choose_tolerance(const Mesh& mesh, std::optional<double> user_length) {
  return choose_tolerance(mesh, find_mesh_islands(mesh), user_length);
}

Result<Tolerance> choose_tolerance(const Mesh& mesh, const MeshIslands& islands, std::optional<double> user_length) {
  if (user_length && !(std::isfinite(*user_length) && *user_length > 0.0))
    return Status{StatusCode::invalid_argument,
                  "tolerance must be a positive finite length, got " + std::to_string(*user_length)};

  Tolerance tol;
  tol.diagonal = referenced_bounding_box(mesh).diagonal();
  if (!(tol.diagonal > 0.0))
    return Status{StatusCode::degenerate_scene, "all vertices coincide: the scene has no extent"};
  if (islands.island_of_face.size() != mesh.triangles.size() || islands.boxes.empty())
    return Status{StatusCode::invalid_argument, "the islands given are not those of this mesh"};

  tol.islands = static_cast<int>(islands.boxes.size());
  tol.local_extent = islands.smallest_diagonal();
  tol.largest_island = islands.largest_diagonal();
  // Islands of no extent (a lone degenerate triangle) are passed over; none
  // with extent leaves the whole scene.
  if (!(tol.local_extent > 0.0)) tol.local_extent = tol.diagonal;
  if (!(tol.largest_island > 0.0)) tol.largest_island = tol.diagonal;
  tol.user_given = user_length.has_value();

  const int count = static_cast<int>(islands.boxes.size());
  // Places: islands whose boxes meet, directly or along a chain. Zones: each
  // box grown by kIslandZoneRelative of its diagonal, but by no more than
  // kZoneShareOfGap of the gap to any island whose box it does not meet, so
  // zones meet only within a place and a map's tolerance never depends on
  // its neighbours.
  detail::DisjointSets places(count);
  std::vector<double> margins;
  for (const Aabb& box : islands.boxes) margins.push_back(kIslandZoneRelative * box.diagonal());
  const AabbTree boxes(islands.boxes);
  std::vector<int> near;
  for (int i = 0; i < count; ++i) {
    near.clear();
    // Only islands nearer than margin / kZoneShareOfGap can narrow the zone.
    boxes.overlapping(grown(islands.boxes[i], margins[i] / kZoneShareOfGap), near);
    for (int j : near) {
      if (j == i) continue;
      const double gap = box_gap(islands.boxes[i], islands.boxes[j]);
      if (gap > 0.0)
        margins[i] = std::min(margins[i], kZoneShareOfGap * gap);
      else
        places.join(i, j);
    }
  }
  for (int i = 0; i < count; ++i) tol.island_zones.push_back(grown(islands.boxes[i], margins[i]));
  // Each place's tolerance is what it would have as one island (the map its
  // islands make): the user's length or the default from the box of its
  // islands, raised to the floor of its coordinates.
  std::vector<int> place_of_root(count, -1);
  std::vector<Aabb> place_boxes;
  for (int i = 0; i < count; ++i) {
    const int root = places.find(i);
    if (place_of_root[root] < 0) {
      place_of_root[root] = tol.places++;
      place_boxes.emplace_back();
    }
    tol.island_place.push_back(place_of_root[root]);
    Aabb& box = place_boxes[place_of_root[root]];
    box.extend(islands.boxes[i].min);
    box.extend(islands.boxes[i].max);
  }
  std::vector<double> place_lengths;
  for (const Aabb& box : place_boxes) {
    const double extent = box.diagonal() > 0.0 ? box.diagonal() : tol.local_extent;
    const double floor = kRoundingErrorsPerPlaneTest * coordinate_error_in(mesh, box);
    const double requested = user_length ? *user_length : kDefaultRelativeTolerance * extent;
    tol.floor = std::max(tol.floor, floor);
    tol.raised_to_floor = tol.raised_to_floor || requested < floor;
    place_lengths.push_back(std::max(requested, floor));
  }
  for (int i = 0; i < count; ++i) tol.island_lengths.push_back(place_lengths[tol.island_place[i]]);
  tol.length = *std::min_element(tol.island_lengths.begin(), tol.island_lengths.end());
  return tol;
}

} // namespace hullcover
