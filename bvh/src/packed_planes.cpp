#include "packed_planes.h"

#include "float4.h"
#include "planes_ray_hit.h"

#include "hullcover/geometry/tolerances.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace hullcover::bvh::detail {
namespace {

constexpr float kFloatInfinity = std::numeric_limits<float>::infinity();
// Each lane's slot within its block.
alignas(16) constexpr float kLaneSlots[4] = {0.0f, 1.0f, 2.0f, 3.0f};
// Largest coordinate, distance or radius the float tests take: sums of a
// few such terms stay far inside float's range (3.4e38), so no test
// overflows; anything larger is left to the exact tests.
constexpr double kFloatTestRange = 1e30;
// Bound on the rounding of s_i (n_j . n_i) relative to s_i, for unit
// normals: the dot's three products and two sums, the product with s_i,
// and the normals' own rounding to float, each within a few u.
constexpr double kFootSlack = 32.0 * kFloatUnit;

// Sizes entering a bound: |x|_1 of a float point, in double.
double l1(const float q[3]) { return std::abs(double(q[0])) + std::abs(double(q[1])) + std::abs(double(q[2])); }

// `p` about a hull's centre, in float: the subtraction in double is exact
// to within double's rounding, far below the one float rounding after it.
// False, leaving q unset, when p is so far from the hull that float could
// not hold it with the bounds' room (the float tests then stand aside).
bool about_centre(const Eigen::Vector3d& p, const double centre[3], float q[3]) {
  for (int k = 0; k < 3; ++k) {
    const double x = p[k] - centre[k];
    if (!(std::abs(x) <= kFloatTestRange)) return false;
    q[k] = static_cast<float>(x);
  }
  return true;
}

// The exact tests count a shape as touching up to kTouchingFraction of
// the coordinates' and the hull's size away (hull_contact.cpp,
// separating_axes.h), which also covers their own double rounding. A float
// verdict leaves twice that to them, so it never settles a case they
// would decide the other way, however far from the origin.
double exact_slack(const Eigen::Vector3d& p, double reach, double radius) {
  return 2.0 * kTouchingFraction * (1.0 + p.cwiseAbs().maxCoeff() + 2.0 * reach + radius);
}

} // namespace

PackedPlanes::PackedPlanes(const std::vector<RuntimeHull>& hulls) {
  hulls_.reserve(hulls.size());
  // Blocks are never more than planes, so one bound on the planes serves
  // both stores' 32-bit indices.
  size_t total_blocks = 0, total_planes = 0;
  for (const RuntimeHull& hull : hulls) {
    total_blocks += (hull.shape.planes.size() + 3) / 4;
    total_planes += hull.shape.planes.size();
  }
  if (total_planes > std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("more planes than the packed store indexes");
  blocks_.reserve(total_blocks);
  pairs_.reserve(total_planes / 2 + hulls.size());
  for (const RuntimeHull& hull : hulls) {
    HullRecord record{};
    const Eigen::Vector3d centre = 0.5 * (hull.box.min + hull.box.max);
    for (int k = 0; k < 3; ++k) record.centre[k] = centre[k];
    double reach = 0.0;
    for (const Eigen::Vector3d& v : hull.shape.vertices) reach = std::max(reach, (v - centre).norm());
    // The bounds, and the foot of a point on a plane, take every normal as
    // unit: a hull with other normals, or none, is left to the exact tests.
    bool unit = !hull.shape.planes.empty();
    std::vector<float> nx, ny, nz, d;
    for (const Plane& plane : hull.shape.planes) {
      unit = unit && std::abs(plane.normal.norm() - 1.0) <= kUnitNormalSlack;
      const double offset = plane.normal.dot(centre) - plane.offset;
      reach = std::max(reach, std::abs(offset));
      nx.push_back(static_cast<float>(plane.normal.x()));
      ny.push_back(static_cast<float>(plane.normal.y()));
      nz.push_back(static_cast<float>(plane.normal.z()));
      d.push_back(static_cast<float>(offset));
    }
    record.reach = float_at_or_above(reach);
    record.first_block = static_cast<std::uint32_t>(blocks_.size());
    record.planes = static_cast<std::uint32_t>(nx.size());
    record.first_pair = static_cast<std::uint32_t>(pairs_.size());
    record.facets = static_cast<std::uint32_t>(hull.shape.facets.size());
    for (size_t i = 0; i < hull.shape.planes.size(); i += 2) {
      PlanePair pair{};
      for (size_t l = 0; l < 2; ++l) {
        if (i + l < hull.shape.planes.size()) {
          const Plane& plane = hull.shape.planes[i + l];
          pair.nx[l] = plane.normal.x();
          pair.ny[l] = plane.normal.y();
          pair.nz[l] = plane.normal.z();
          pair.offset[l] = plane.offset;
        } else {
          pair.offset[l] = std::numeric_limits<double>::max(); // the padding: zero normal, behind everything
        }
      }
      pairs_.push_back(pair);
    }
    record.blocks = unit && std::isfinite(record.reach) ? static_cast<std::uint32_t>((nx.size() + 3) / 4) : 0;
    for (std::uint32_t b = 0; b < record.blocks; ++b) {
      PlaneBlock block{};
      for (size_t lane = 0; lane < 4; ++lane) {
        const size_t i = 4 * b + lane < nx.size() ? 4 * b + lane : 0;
        block.nx[lane] = nx[i];
        block.ny[lane] = ny[i];
        block.nz[lane] = nz[i];
        block.d[lane] = d[i];
      }
      blocks_.push_back(block);
    }
    hulls_.push_back(record);
  }
}

FloatVerdict PackedPlanes::sphere(int h, const Eigen::Vector3d& p, double radius) const {
  const HullRecord& hull = hulls_[h];
  if (hull.blocks == 0) return FloatVerdict::unsure;
  float q[3];
  if (!about_centre(p, hull.centre, q) || !(radius <= kFloatTestRange)) return FloatVerdict::unsure;
  const Float4 qx = Float4::all(q[0]), qy = Float4::all(q[1]), qz = Float4::all(q[2]);
  // The largest signed distance, and in each lane the slot (4 x block +
  // lane) where that lane's largest was seen.
  Float4 outside = Float4::all(-kFloatInfinity), slot = Float4::all(0.0f);
  const Float4 lane_slot = Float4::load(kLaneSlots);
  const PlaneBlock* first = blocks_.data() + hull.first_block;
  for (std::uint32_t b = 0; b < hull.blocks; ++b) {
    const PlaneBlock& block = first[b];
    const Float4 s =
        Float4::load(block.nx) * qx + Float4::load(block.ny) * qy + Float4::load(block.nz) * qz + Float4::load(block.d);
    const Float4 larger = s > outside;
    outside = select(larger, s, outside);
    slot = select(larger, lane_slot + Float4::all(static_cast<float>(4 * b)), slot);
  }
  const float most = largest_lane(outside);
  const double slack = kFloatPlaneSlack * (l1(q) + hull.reach + radius) + exact_slack(p, hull.reach, radius);
  if (most > radius + slack) return FloatVerdict::apart;
  if (most < -slack) return FloatVerdict::meets;
  if (most > radius - slack) return FloatVerdict::unsure;
  // The centre is in front of plane i (the largest), nearer than the
  // radius. Its foot on that plane, f = p - s_i n_i, is within s_i < radius
  // of p; when f is behind every other plane it is in the hull, so the
  // sphere meets it. The most common case by far: a character on a floor,
  // against a wall, or on a flat polygon's face.
  float slots[4], values[4];
  slot.store(slots);
  outside.store(values);
  int lane = 0;
  while (values[lane] != most) ++lane;
  const int at = static_cast<int>(slots[lane]);
  const PlaneBlock& own = first[at / 4];
  const float ix = own.nx[at % 4], iy = own.ny[at % 4], iz = own.nz[at % 4];
  const Float4 nix = Float4::all(ix), niy = Float4::all(iy), niz = Float4::all(iz);
  // Plane i by its index (slots past the hull's planes repeat plane 0), not
  // by its values: another plane whose floats equal plane i's is tested.
  const int own_index = static_cast<std::uint32_t>(at) < hull.planes ? at : 0;
  const Float4 own_plane = Float4::all(static_cast<float>(own_index));
  const Float4 planes_f = Float4::all(static_cast<float>(hull.planes));
  const Float4 zero = Float4::all(0.0f);
  const Float4 m = Float4::all(most);
  // s_j(f) = s_j(p) - s_i (n_j . n_i): off by the two distances' rounding
  // (slack) and the product's, which is within 32 u of s_i <= radius.
  const Float4 margin = Float4::all(-float_at_or_above(2.0 * slack + kFootSlack * radius));
  for (std::uint32_t b = 0; b < hull.blocks; ++b) {
    const PlaneBlock& block = first[b];
    const Float4 nx = Float4::load(block.nx), ny = Float4::load(block.ny), nz = Float4::load(block.nz);
    const Float4 s = nx * qx + ny * qy + nz * qz + Float4::load(block.d);
    const Float4 at_foot = s - m * (nx * nix + ny * niy + nz * niz);
    // Plane i itself (and, when it is plane 0, its copies padding the last
    // block) holds f; a plane facing exactly the other way (a flat
    // polygon's back) holds it too, since no point is in front of both.
    const Float4 slots_here = lane_slot + Float4::all(static_cast<float>(4 * b));
    const Float4 plane_here = select(slots_here < planes_f, slots_here, zero);
    const Float4 itself = (plane_here >= own_plane) & (plane_here <= own_plane);
    const Float4 opposite = ((nx + nix) >= zero) & ((nx + nix) <= zero) & ((ny + niy) >= zero) & ((ny + niy) <= zero) &
                            ((nz + niz) >= zero) & ((nz + niz) <= zero);
    if (((at_foot <= margin) | itself | opposite).bits() != 0xf) return FloatVerdict::unsure;
  }
  return FloatVerdict::meets;
}

PackedPlanes::Clip PackedPlanes::clip(const HullRecord& hull, const float q0[3], const float v[3], float span,
                                      float grow) const {
  const Float4 qx = Float4::all(q0[0]), qy = Float4::all(q0[1]), qz = Float4::all(q0[2]);
  const Float4 vx = Float4::all(v[0]), vy = Float4::all(v[1]), vz = Float4::all(v[2]);
  const Float4 zero = Float4::all(0.0f), g = Float4::all(grow);
  const Float4 up = Float4::all(kFloatInfinity), down = Float4::all(-kFloatInfinity);
  Float4 enter = zero, leave = Float4::all(span), cut = zero & up; // no lane cut
  Float4 start = down, end = down;
  const PlaneBlock* block = blocks_.data() + hull.first_block;
  for (std::uint32_t b = 0; b < hull.blocks; ++b, ++block) {
    const Float4 nx = Float4::load(block->nx), ny = Float4::load(block->ny), nz = Float4::load(block->nz);
    const Float4 num = nx * qx + ny * qy + nz * qz + Float4::load(block->d);
    const Float4 den = nx * vx + ny * vy + nz * vz;
    // Along the segment the signed distance to the moved plane is
    // num - grow + t den: it crosses 0 at t = (grow - num) / den.
    const Float4 t = (g - num) / den;
    const Float4 rising = den > zero, falling = den < zero;
    leave = min(select(rising, t, up), leave);
    enter = max(select(falling, t, down), enter);
    cut = cut | ((den >= zero) & (den <= zero) & (num > g));
    start = max(num, start);
    end = max(num + den * Float4::all(span), end);
  }
  return {largest_lane(enter), smallest_lane(leave), cut.bits() != 0, largest_lane(start), largest_lane(end)};
}

FloatVerdict PackedPlanes::segment(int h, const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius) const {
  const HullRecord& hull = hulls_[h];
  if (hull.blocks == 0) return FloatVerdict::unsure;
  float q0[3], v[3];
  if (!about_centre(a, hull.centre, q0) || !about_centre(b, hull.centre, v) || !(radius <= kFloatTestRange))
    return FloatVerdict::unsure;
  for (int k = 0; k < 3; ++k) v[k] = static_cast<float>(b[k] - a[k]);
  // The signed distance at any t in [0, 1] is off by at most this: the
  // start's rounding plus t times the direction's (docs: "float pre-tests").
  const double slack =
      kFloatPlaneSlack * (l1(q0) + hull.reach + l1(v) + radius) + exact_slack(a, hull.reach, radius + l1(v));
  // Planes moved out by a further 2 x slack keep a part of the segment
  // whenever the exact ones do, whatever the rounding of the divisions.
  const Clip c = clip(hull, q0, v, 1.0f, float_at_or_above(radius + 2.0 * slack));
  if (c.cut || c.enter > c.leave) return FloatVerdict::apart;
  if (c.start_outside < -slack || c.end_outside < -slack) return FloatVerdict::meets;
  return FloatVerdict::unsure;
}

std::optional<RayHit> PackedPlanes::ray_hit(int h, const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                            double max_t) const {
  const HullRecord& hull = hulls_[h];
  return first_hit_on_plane_pairs(pairs_.data() + hull.first_pair, static_cast<int>(hull.planes),
                                  static_cast<int>(hull.facets), origin, direction, max_t);
}

} // namespace hullcover::bvh::detail
