#pragma once
// Every hull's planes in one contiguous store (private to bvh/), twice. In
// float, four planes a block, for the first test a sphere or capsule
// yes/no or overlap query makes of a hull: many hulls such a walk reaches
// are apart from the shape, or plainly hold it, and four float planes at
// a time settle that (contact queries skip it: most hulls they reach
// touch, and need the exact contact anyway). A float answer near a
// decision point is not trusted: the test then says "unsure" and the exact
// narrow phase (hull_contact.h, in double on the RuntimeHull) decides, so
// answers are those of the double code. See docs/definitions-and-proofs.md,
// "The runtime's float pre-tests". In double, two planes side by side,
// hull after hull, for the exact ray clip, which reads nothing else.
//
// Each hull's planes are stored about its own centre (its box's centre,
// in double): a plane's offset is then at most the hull's reach, and
// the rounding of a test grows with the hull's size and the query's
// distance from it, not with the world's coordinates.

#include "float4.h"
#include "planes_ray_hit.h"

#include "hullcover/bvh/hull_contact.h"
#include "hullcover/bvh/runtime_hull.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace hullcover::bvh::detail {

/// Bound on the rounding of one float plane test, relative to the sizes
/// that enter it. A signed distance n.q + d evaluated in float, with n, d
/// and q = p - centre each rounded to float once, is within
/// 8 u (|q|_1 + |d|) of its exact value (u = 2^-24: three roundings of the
/// inputs, three of the products and sums, one of the offset); |d| is at
/// most the hull's reach. Twice that, to cover the rounding of the bound
/// itself and of the comparisons built on it.
inline constexpr double kFloatPlaneSlack = 16.0 * kFloatUnit;

/// A float verdict: settled, or left to the exact test.
enum class FloatVerdict { apart, meets, unsure };

/// The packed planes of a list of hulls, indexed as the list.
class PackedPlanes {
public:
  PackedPlanes() = default;
  explicit PackedPlanes(const std::vector<RuntimeHull>& hulls);

  /// A sphere (centre p, radius >= 0) against hull h's planes: `apart` when
  /// p is farther than radius in front of some plane (then the hull, which
  /// every plane supports, is farther than radius from p), `meets` when p
  /// is behind every plane (inside the hull) or in front of exactly one
  /// plane, nearer than the radius, with its foot on that plane inside the
  /// hull; else `unsure`. Each verdict holds with the float rounding
  /// bounded as above.
  FloatVerdict sphere(int h, const Eigen::Vector3d& p, double radius) const;

  /// Segment a-b swept by `radius` (a capsule; radius 0: the segment)
  /// against hull h: `apart` when no point of the segment lies behind
  /// every plane moved out by radius (as segment_clear_of_grown_planes
  /// decides, without its rounding), `meets` when an end point lies inside
  /// the hull, else `unsure`.
  FloatVerdict segment(int h, const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius) const;

  /// ray_hit(hull h, ...) (hull_contact.h), bit for bit, from the store's
  /// own copy of the hull's planes in double: no read of the RuntimeHull.
  std::optional<RayHit> ray_hit(int h, const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                double max_t) const;

private:
  // Four planes as four lanes: n.x, n.y, n.z and the offset about the
  // hull's centre. A hull whose plane count is not a multiple of four
  // repeats its first plane, which changes no test. One cache line each,
  // aligned to one.
  struct alignas(64) PlaneBlock {
    float nx[4], ny[4], nz[4], d[4];
  };
  struct HullRecord {
    double centre[3]; // double: a float centre would move by up to half a float unit of the coordinates
    float reach;      // >= the distance from the centre to any of the hull's vertices
    std::uint32_t first_block;
    std::uint32_t blocks;
    std::uint32_t planes;     // before padding
    std::uint32_t first_pair; // in pairs_
    std::uint32_t facets;     // the first `facets` planes are the facets'
  };
  std::vector<PlaneBlock> blocks_;
  // Every hull's planes in double, two at a time, hull after hull: what
  // the exact ray clip reads instead of the scattered RuntimeHull.
  std::vector<PlanePair> pairs_;
  std::vector<HullRecord> hulls_;

  // The clip of segment q0 + t v, 0 <= t <= span, by hull h's planes moved
  // out by `grow` (float, about the centre), as [enter, leave], with the
  // largest signed distance of each end: what segment() builds its
  // verdict on.
  struct Clip {
    float enter, leave;
    bool cut; // a plane parallel to the segment is in front of it all the way
    float start_outside, end_outside;
  };
  Clip clip(const HullRecord& hull, const float q0[3], const float v[3], float span, float grow) const;
};

/// One hull's planes in a store: what a tree walk hands a query with the
/// hull. No store: the hull has no float tests (every verdict unsure).
struct PlanesOf {
  const PackedPlanes* store = nullptr;
  int local = 0;

  FloatVerdict sphere(const Eigen::Vector3d& p, double radius) const {
    return store ? store->sphere(local, p, radius) : FloatVerdict::unsure;
  }
  FloatVerdict segment(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius) const {
    return store ? store->segment(local, a, b, radius) : FloatVerdict::unsure;
  }
  /// ray_hit on the hull, from the store when there is one.
  std::optional<RayHit> ray_hit(const RuntimeHull& hull, const Eigen::Vector3d& origin,
                                const Eigen::Vector3d& direction, double max_t) const {
    return store ? store->ray_hit(local, origin, direction, max_t) : bvh::ray_hit(hull, origin, direction, max_t);
  }
};

} // namespace hullcover::bvh::detail
