#pragma once
/// \file mesh.h
/// The triangle mesh every hullcover stage reads: positions, triangles and a
/// material per triangle. Plain data; the functions beside it check and
/// measure it.
///
/// Conventions (docs/definitions-and-proofs.md): a triangle's front is the side its
/// counter-clockwise winding's normal points to; lengths are in scene units.

#include "hullcover/geometry/aabb.h"
#include "hullcover/geometry/status.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace hullcover {

/// A triangle soup or indexed mesh of a whole scene, in double precision.
struct Mesh {
  /// Vertex positions in scene units.
  std::vector<Eigen::Vector3d> positions;
  /// Vertex indices into `positions`, counter-clockwise seen from the front.
  std::vector<Eigen::Vector3i> triangles;
  /// One material id per triangle, indexing `material_names` (0 when the
  /// source has no materials). Same length as `triangles`.
  std::vector<int> material_ids;
  /// Names of the materials, as the source file gives them (may be empty).
  std::vector<std::string> material_names;
  /// Absolute bound, in scene units, on the rounding error the positions
  /// carried in before hullcover saw them (e.g. a float32 importer). It is a
  /// property of the data, separate from the user's tolerance, and sets that
  /// tolerance's floor (see hullcover/mesh/tolerance.h). 0 for exact input.
  double coordinate_error = 0.0;
  /// Optional tighter bound, relative: each coordinate x carried at most
  /// |x| times this (a float32 importer: half a unit in the last place), so
  /// a world's far-apart pieces each get the floor of their own magnitude
  /// (hullcover/mesh/tolerance.h). 0: none; `coordinate_error` bounds all.
  /// A transform that moves coordinates must reset it (it bounds the
  /// magnitudes the rounding happened at).
  double coordinate_relative_error = 0.0;
};

/// Box around the vertices that triangles reference (unreferenced vertices
/// do not count: they are not part of the scene's geometry).
Aabb referenced_bounding_box(const Mesh& mesh);

/// Largest absolute coordinate among referenced vertices; what rounding
/// errors in sidedness tests scale with.
double largest_coordinate_magnitude(const Mesh& mesh);

/// Checks the invariants every stage relies on.
/// Fails with `index_out_of_range` (a triangle names a missing vertex),
/// `non_finite_coordinate` (NaN or infinite position of a referenced vertex),
/// `invalid_argument` (material_ids not one per triangle) or `empty_scene`
/// (no triangle). The message names the first offending element.
Status validate_mesh(const Mesh& mesh);

/// Twice the area vector of triangle `t` ((b - a) x (c - a)); its direction
/// is the front normal, its length twice the area.
Eigen::Vector3d triangle_area_vector(const Mesh& mesh, int t);

/// Writes triangle `t`'s three corner positions into `corners` (resized to
/// 3), for the polygon routines that take a corner list; reuses its storage.
void triangle_corners(const Mesh& mesh, int t, std::vector<Eigen::Vector3d>& corners);

/// True when two corners of triangle `t` are the same vertex index (the
/// triangle collapsed to a segment or point, e.g. after welding).
bool triangle_has_repeated_vertex(const Mesh& mesh, int t);

} // namespace hullcover
