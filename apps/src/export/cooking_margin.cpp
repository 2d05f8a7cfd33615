#include "export/cooking_margin.h"

#include "hullcover/covering/convex_hull_3d.h"
#include "hullcover/geometry/triangle_distance.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace hullcover::app {
namespace {

// Rounds of repair before a hull is reported: a round's octahedra can leave
// a neighbouring corner short, which the next round takes.
constexpr int kRepairRounds = 4;
// A corner this many hull tolerances in front of the others' planes is
// never dropped (builders drop within one): the margin an export keeps,
// and the half-diagonal of the octahedra that restore it.
constexpr double kMarginInHullTolerances = 2.0;
// The error Jolt's builder accepts, in hull tolerances: a corner whose
// reach is within it may be dropped harmlessly.
constexpr double kAcceptedErrorInHullTolerances = 4.0;
// Share by which a corner's margin may fall short of the margin and still
// pass: an octahedron's corner stands exactly the margin clear, and
// rounding or a corner nearby must not start another round over it. (Its
// reach is at most the margin, half the accepted error: the reach test
// needs no such share.)
constexpr double kRoundingShare = 0.01;

bool on_facet(const std::vector<int>& facet, int v) { return std::find(facet.begin(), facet.end(), v) != facet.end(); }

// The corner's margin, and its distance from the hull of the others
// (`reach`; 0 when the corner is not outside them).
double margin_with(ConvexHullBuilder& builder, const ConvexPolytope& hull, int v, double& reach) {
  std::vector<Eigen::Vector3d> others;
  others.reserve(hull.vertices.size());
  for (int k = 0; k < static_cast<int>(hull.vertices.size()); ++k)
    if (k != v) others.push_back(hull.vertices[k]);
  const Eigen::Vector3d& corner = hull.vertices[v];
  double margin = -std::numeric_limits<double>::infinity();
  reach = 0.0;
  Result<ConvexPolytope> rest = builder.build(others);
  if (rest.ok()) {
    for (const Plane& plane : rest.value().planes) margin = std::max(margin, plane.signed_distance(corner));
    if (margin > 0.0) reach = distance_to_facet_fans(rest.value(), corner);
    return margin;
  }
  // The other corners are flat: `v` is the apex over the facet they make
  // (the one facet without it). Its height above that facet is its margin,
  // its distance from the facet's polygon its reach.
  for (size_t f = 0; f < hull.facets.size() && f < hull.planes.size(); ++f) {
    const std::vector<int>& base = hull.facets[f];
    if (on_facet(base, v)) continue;
    margin = std::max(margin, -hull.planes[f].signed_distance(corner));
    double nearest = std::numeric_limits<double>::infinity();
    for (size_t k = 1; k + 1 < base.size(); ++k)
      nearest = std::min(nearest, (closest_point_on_triangle(corner, hull.vertices[base[0]], hull.vertices[base[k]],
                                                             hull.vertices[base[k + 1]]) -
                                   corner)
                                      .norm());
    if (std::isfinite(nearest)) reach = std::max(reach, nearest);
  }
  return margin;
}

} // namespace

double corner_margin(const ConvexPolytope& hull, int v, double& reach) {
  ConvexHullBuilder builder;
  return margin_with(builder, hull, v, reach);
}

CookingRepair repair_cooking_margins(const std::vector<ConvexPolytope>& hulls, double hull_tolerance) {
  CookingRepair out;
  const double margin = kMarginInHullTolerances * hull_tolerance;
  out.margin = margin;
  out.hulls.reserve(hulls.size());
  ConvexHullBuilder builder;
  const double passing = margin * (1.0 - kRoundingShare);
  const double harmless = kAcceptedErrorInHullTolerances * hull_tolerance;
  std::vector<int> at_risk;
  for (size_t h = 0; h < hulls.size(); ++h) {
    ConvexPolytope hull = hulls[h];
    bool repaired = false;
    double worst_margin = 0.0, worst_reach = 0.0;
    for (int round = 0;; ++round) {
      at_risk.clear();
      for (int v = 0; v < static_cast<int>(hull.vertices.size()); ++v) {
        double reach = 0.0;
        const double m = margin_with(builder, hull, v, reach);
        if (m < passing && reach > harmless) {
          if (at_risk.empty() || reach > worst_reach) worst_margin = m, worst_reach = reach;
          at_risk.push_back(v);
        }
      }
      if (at_risk.empty() || round == kRepairRounds) break;
      std::vector<Eigen::Vector3d> points;
      for (int v = 0; v < static_cast<int>(hull.vertices.size()); ++v) {
        if (!std::binary_search(at_risk.begin(), at_risk.end(), v)) {
          points.push_back(hull.vertices[v]);
          continue;
        }
        for (int axis = 0; axis < 3; ++axis)
          for (const double side : {-1.0, 1.0})
            points.push_back(hull.vertices[v] + side * margin * Eigen::Vector3d::Unit(axis));
      }
      Result<ConvexPolytope> rebuilt = builder.build(points);
      if (!rebuilt.ok()) break; // reported below: the corners stay at risk
      hull = std::move(rebuilt).value();
      repaired = true;
      out.corners_replaced += static_cast<int>(at_risk.size());
    }
    if (!at_risk.empty()) {
      char line[256];
      std::snprintf(line, sizeof line,
                    "hull %zu keeps a corner %.6g out of the hull of its other corners but only %.6g in front of its "
                    "planes, under the engine's margin %.6g",
                    h, worst_reach, worst_margin, margin);
      out.failures.emplace_back(line);
    }
    out.repaired += repaired;
    out.hulls.push_back(std::move(hull));
  }
  return out;
}

} // namespace hullcover::app
