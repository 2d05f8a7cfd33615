#pragma once
/// \file convex_hull_3d.h
/// Three-dimensional convex hulls through Qhull's reentrant C library
/// (never the C++ wrapper: it replaces qh_fprintf and a Qhull error would
/// then end the process, see docs/design.md).

#include "hullcover/geometry/convex_polytope.h"
#include "hullcover/geometry/status.h"

#include <cstdio>
#include <vector>

namespace hullcover {

/// Computes hulls one after another, reusing what Qhull allows. Not thread
/// safe: use one builder per thread.
class ConvexHullBuilder {
public:
  ConvexHullBuilder();
  ~ConvexHullBuilder();
  ConvexHullBuilder(const ConvexHullBuilder&) = delete;
  ConvexHullBuilder& operator=(const ConvexHullBuilder&) = delete;

  /// The hull of `points` (at least 4, not all within a plane): vertices
  /// (a subset of the points, in input order), facets counter-clockwise
  /// seen from outside, and outward unit planes. Coplanar facets Qhull
  /// merges are one polygon. Work happens in a frame centred on the points,
  /// so scenes far from the origin lose no precision.
  /// Fails with `degenerate_scene` when Qhull rejects the input (flat or
  /// too few points), with Qhull's error number in the message, and when the
  /// hull it builds is thinner than kFlatHullRelativeWidth of the points'
  /// extent (flat but for rounding).
  /// `ids`, when not empty, gives an id per point that is copied into the
  /// result's `vertex_ids`.
  Result<ConvexPolytope> build(const std::vector<Eigen::Vector3d>& points, const std::vector<int>& ids = {});

  /// How many hulls were asked for (for statistics).
  long calls() const { return calls_; }

private:
  std::FILE* error_sink_ = nullptr; // Qhull's messages go here, not to the user's terminal
  long calls_ = 0;
};

} // namespace hullcover
