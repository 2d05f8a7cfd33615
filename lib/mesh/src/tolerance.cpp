#include "hullcover/mesh/tolerance.h"

#include "hullcover/mesh/mesh_islands.h"

#include <cmath>
#include <limits>

namespace hullcover {

Result<Tolerance> choose_tolerance(const Mesh& mesh, std::optional<double> user_length) {
  if (user_length && !(std::isfinite(*user_length) && *user_length > 0.0))
    return Status{StatusCode::invalid_argument,
                  "tolerance must be a positive finite length, got " + std::to_string(*user_length)};

  Tolerance tol;
  tol.diagonal = referenced_bounding_box(mesh).diagonal();
  if (!(tol.diagonal > 0.0))
    return Status{StatusCode::degenerate_scene, "all vertices coincide: the scene has no extent"};

  const MeshIslands islands = find_mesh_islands(mesh);
  tol.islands = static_cast<int>(islands.boxes.size());
  tol.local_extent = islands.smallest_diagonal();
  tol.largest_island = islands.largest_diagonal();
  // Islands of no extent (a lone degenerate triangle) are passed over; none
  // with extent leaves the whole scene.
  if (!(tol.local_extent > 0.0)) tol.local_extent = tol.diagonal;
  if (!(tol.largest_island > 0.0)) tol.largest_island = tol.diagonal;

  const double arithmetic_error = largest_coordinate_magnitude(mesh) * std::numeric_limits<double>::epsilon();
  tol.floor = kRoundingErrorsPerPlaneTest * std::max(mesh.coordinate_error, arithmetic_error);

  tol.user_given = user_length.has_value();
  const double requested = user_length ? *user_length : kDefaultRelativeTolerance * tol.local_extent;
  tol.raised_to_floor = requested < tol.floor;
  tol.length = std::max(requested, tol.floor);
  return tol;
}

} // namespace hullcover
