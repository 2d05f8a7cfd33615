#pragma once
/// \file tolerance.h
/// hullcover's length tolerance, ONE per place, and how it is chosen.
///
/// Every sidedness and containment test in hullcover uses the tolerance of
/// the place it happens ("strictly inside" means deeper than it;
/// "coincident" means closer than it). Every other threshold is declared in hullcover/geometry/tolerances.h:
/// lengths as named multiples of it, directions and the runtime's as
/// dimensionless numbers. See docs/definitions-and-proofs.md, "The tolerance".
///
/// Default, per place: islands (mesh_islands.h) whose boxes meet, directly
/// or along a chain (a map and a prop island inside its L-shaped box), as
/// opposed to the maps of a world: `kDefaultRelativeTolerance` x the
/// diagonal of the box of the place's islands, never below the floor of its
/// own coordinates. A map laid in a world of others keeps the tolerance it
/// has alone, and so its hulls. Each island's *zone* is its box grown by
/// `kIslandZoneRelative` of its diagonal, but never by more than
/// `kZoneShareOfGap` of the gap to an island of another place, so zones of
/// different places never meet. A test is judged at the tolerance of the
/// place it happens: the smallest of the zones a test's box meets
/// (PlaceTolerance), and `length`, the smallest of all, where it meets
/// none. The decomposer checks an island's hulls at its place's tolerance
/// and keeps them out of every zone of a smaller one (a prism stops short
/// of it), so the audit judges each hull at the tolerance it was made at,
/// and a map's tolerance never depends on its neighbours.
/// A user may override it with an absolute length, but never below the floor
/// the data itself imposes (its own rounding error, as Jolt and Manifold do):
/// a tolerance under the noise of the coordinates would turn rounding into
/// geometry.

#include "hullcover/geometry/aabb_tree.h"
#include "hullcover/geometry/mesh.h"
#include "hullcover/geometry/status.h"
#include "hullcover/geometry/tolerances.h"
#include "hullcover/mesh/mesh_islands.h"

#include <optional>
#include <vector>

namespace hullcover {

/// The tolerance in force and where it came from.
struct Tolerance {
  /// The smallest tolerance of any island, an absolute length in scene units
  /// (> 0): the one in force where no place is known. Equal to every
  /// island's for a scene of one island or a user-given length.
  double length = 0.0;
  /// Per island (mesh_islands.h numbering), scene units (> 0): the
  /// tolerance of tests in its zone: its place's (the user's length, or the
  /// default from the diagonal of the box of the place's islands, raised to
  /// the floor of its coordinates).
  std::vector<double> island_lengths;
  /// Per island: its zone, where its tolerance holds and its hulls lie (see
  /// the file comment). Zones of different places never meet.
  std::vector<Aabb> island_zones;
  /// Per island: its place (0 .. places - 1, numbered by their lowest
  /// island): the islands whose boxes meet it, directly or along a chain.
  std::vector<int> island_place;
  /// How many places the scene has.
  int places = 0;
  /// Smallest length the data can support: rounding error of its coordinates
  /// (input error plus double-precision arithmetic at its magnitude), times
  /// `kRoundingErrorsPerPlaneTest`; the largest of the islands' floors (each
  /// island's is that of its own coordinates' magnitude).
  double floor = 0.0;
  /// The whole scene's bounding-box diagonal: how far a ray may have to run
  /// to cross it.
  double diagonal = 0.0;
  /// The diagonal of the scene's smallest island (mesh_islands.h) with an
  /// extent; islands of none take it as theirs. Equal to `diagonal` for a
  /// scene of one island.
  double local_extent = 0.0;
  /// The diagonal of the scene's largest island: the farthest a patch (and
  /// so a hull made of one) can span. Equal to `diagonal` for one island.
  double largest_island = 0.0;
  /// How many islands the scene has.
  int islands = 0;
  /// True when the user gave the length.
  bool user_given = false;
  /// True when the requested (or default) length of some island was below
  /// its floor and was raised to it.
  bool raised_to_floor = false;

  /// The largest tolerance of any island (`length` when there are none).
  double largest_length() const;
};

/// The tolerance of a test confined to a box: the smallest of the islands'
/// whose zones the box meets; `Tolerance::length` where it meets none (the
/// rule of tolerance.h's header; what an audit judges a hull from any source
/// by). Refers to the Tolerance given, which must outlive it.
class PlaceTolerance {
public:
  /// Refers to `tolerance`, which must outlive this.
  explicit PlaceTolerance(const Tolerance& tolerance);
  PlaceTolerance(Tolerance&&) = delete; // would refer to a temporary
  /// Scene units (> 0). O(log islands + zones met); thread-safe.
  double at(const Aabb& box) const;
  /// Appends the islands whose zones `box` meets and whose tolerance is
  /// below `length`: where a hull judged at `length` must not reach.
  void smaller_zones_meeting(const Aabb& box, double length, std::vector<int>& out) const;

private:
  /// Appends the islands whose zones `box` meets.
  void zones_meeting(const Aabb& box, std::vector<int>& out) const;

  const Tolerance* tolerance_;
  AabbTree zones_;
};

/// Chooses the tolerance for a mesh.
///
/// `user_length`, when given, is an absolute length in scene units.
/// Fails with `invalid_argument` when `user_length` is not a positive finite
/// number, and with `degenerate_scene` when the mesh has no extent (all
/// referenced vertices coincide), since then no relative default exists.
/// The mesh must already pass `validate_mesh`.
Result<Tolerance> choose_tolerance(const Mesh& mesh, std::optional<double> user_length);

/// The same, with the mesh's islands already found (`find_mesh_islands(mesh)`);
/// fails with `invalid_argument` when they are not the mesh's (another face
/// count, or none).
Result<Tolerance> choose_tolerance(const Mesh& mesh, const MeshIslands& islands, std::optional<double> user_length);

} // namespace hullcover
