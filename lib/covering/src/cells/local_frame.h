#pragma once
// The frame a decomposition works in (internal to the decomposer). A scene
// far from the origin, relative to its size, is moved next to it before
// anything is computed, and its hulls are moved back at the end: every
// predicate then rounds at the scene's own size, not at its distance from
// the origin, so a map at 1e5 gets the hulls it has at the origin. A scene
// near the origin is worked where it is (the same hulls, bit for bit, as
// with no frame at all).

#include "hullcover/covering/covering_types.h"
#include "prepared_scene_view.h"

#include <Eigen/Core>

namespace hullcover::detail {

/// The origin of the frame `prepared` is worked in: zero when the centre
/// of its box lies within kFarFromOriginInDiagonals diagonals of the
/// origin (in every coordinate), else, in each coordinate that far out, the
/// centre's snapped to a grid whose step is the least power of two at or
/// above the diagonal (a small edit keeps the frame), and zero in the others.
Eigen::Vector3d local_frame_origin(const PreparedSceneView& prepared);

/// A scene is far from the origin when its box's centre lies farther than
/// this many of its diagonals from it in some coordinate.
inline constexpr double kFarFromOriginInDiagonals = 1.0;

/// `prepared` moved by -origin: positions, island boxes and tolerance
/// zones; the tolerance lengths, topology and face ids are unchanged.
PreparedMesh in_local_frame(const PreparedSceneView& prepared, const Eigen::Vector3d& origin);

/// Moves every hull of `covering` by +origin, back into the scene's frame.
void to_scene_frame(Covering& covering, const Eigen::Vector3d& origin);

} // namespace hullcover::detail
