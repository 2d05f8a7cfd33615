#pragma once
/// \file hull_under_check.h
/// One hull as the re-check (validity_recheck.h) takes it, apart so that
/// the re-check's geometry can take it without the re-check.

#include "hullcover/geometry/convex_polytope.h"

#include <vector>

namespace hullcover::validate {

/// One hull to re-check.
struct HullUnderCheck {
  const ConvexPolytope* shape = nullptr;
  bool flat = false;      ///< a polygon of thickness 0 (front and back facets)
  std::vector<int> faces; ///< mesh faces it claims to cover, ascending; empty when unknown
};

} // namespace hullcover::validate
