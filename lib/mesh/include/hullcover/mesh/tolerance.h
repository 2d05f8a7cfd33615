#pragma once
/// \file tolerance.h
/// hullcover's ONE length tolerance, and how it is chosen.
///
/// Every sidedness and containment test in hullcover uses `Tolerance::length`
/// ("strictly inside" means deeper than it; "coincident" means closer than
/// it). Every other threshold is declared in hullcover/geometry/tolerances.h:
/// lengths as named multiples of it, directions and the runtime's as
/// dimensionless numbers. See ../shared/DESIGN.md, "tolerance".
///
/// Default: `kDefaultRelativeTolerance` x the scene's local extent: the
/// diagonal of its SMALLEST island (mesh_islands.h), not of the whole world.
/// A map laid beside others no smaller than itself keeps the tolerance it has
/// alone; beside a smaller one it is judged at the smaller one's precision,
/// never coarser than alone (conservative: a tolerance derived from a larger
/// neighbour would let a small object's hulls take space, or weld its
/// vertices, at the neighbour's scale).
/// A user may override it with an absolute length, but never below the floor
/// the data itself imposes (its own rounding error, as Jolt and Manifold do):
/// a tolerance under the noise of the coordinates would turn rounding into
/// geometry.

#include "hullcover/geometry/mesh.h"
#include "hullcover/geometry/status.h"
#include "hullcover/geometry/tolerances.h"

#include <optional>

namespace hullcover {

/// The tolerance in force and where it came from.
struct Tolerance {
  /// The tolerance, an absolute length in scene units (> 0).
  double length = 0.0;
  /// Smallest length the data can support: rounding error of its coordinates
  /// (input error plus double-precision arithmetic at its magnitude), times
  /// `kRoundingErrorsPerPlaneTest`.
  double floor = 0.0;
  /// The whole scene's bounding-box diagonal: how far a ray may have to run
  /// to cross it.
  double diagonal = 0.0;
  /// The diagonal of the scene's smallest island (mesh_islands.h): what the
  /// default tolerance is derived from. Equal to `diagonal` for a scene of
  /// one island.
  double local_extent = 0.0;
  /// The diagonal of the scene's largest island: the farthest a patch (and
  /// so a hull made of one) can span. Equal to `diagonal` for one island.
  double largest_island = 0.0;
  /// How many islands the scene has.
  int islands = 0;
  /// True when the user gave the length.
  bool user_given = false;
  /// True when the requested (or default) length was below `floor` and was
  /// raised to it.
  bool raised_to_floor = false;
};

/// Chooses the tolerance for a mesh.
///
/// `user_length`, when given, is an absolute length in scene units.
/// Fails with `invalid_argument` when `user_length` is not a positive finite
/// number, and with `degenerate_scene` when the mesh has no extent (all
/// referenced vertices coincide), since then no relative default exists.
/// The mesh must already pass `validate_mesh`.
Result<Tolerance> choose_tolerance(const Mesh& mesh, std::optional<double> user_length);

} // namespace hullcover
