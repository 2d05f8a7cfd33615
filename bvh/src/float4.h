#pragma once
// Four floats at once (private to bvh/): the lanes of the wide tree's box
// tests and of the packed hulls' plane tests. SSE2 where the compiler offers
// it (every x86-64 build), plain loops elsewhere; both give the same bits,
// as every operation is a correctly rounded IEEE one per lane (a compiler
// allowed to fuse a multiply and an add rounds once instead of twice: the
// bits may then differ, never by more than the bounds built on them allow).

#include <cmath>
#include <cstdint>
#include <limits>

#if defined(__SSE2__) || defined(_M_X64)
#include <emmintrin.h>
#define HULLCOVER_FLOAT4_SSE2 1
#endif

namespace hullcover::bvh::detail {

/// Float's unit roundoff, 2^-24: one correctly rounded float operation is
/// within this much of its exact value, relative to it. The float tests'
/// bounds are named multiples of it.
inline constexpr double kFloatUnit = 1.0 / 16777216.0;

#if HULLCOVER_FLOAT4_SSE2

struct Float4 {
  __m128 v;

  static Float4 load(const float* p) { return {_mm_loadu_ps(p)}; }
  static Float4 all(float x) { return {_mm_set1_ps(x)}; }
  void store(float* p) const { _mm_storeu_ps(p, v); }

  friend Float4 operator+(Float4 a, Float4 b) { return {_mm_add_ps(a.v, b.v)}; }
  friend Float4 operator-(Float4 a, Float4 b) { return {_mm_sub_ps(a.v, b.v)}; }
  friend Float4 operator*(Float4 a, Float4 b) { return {_mm_mul_ps(a.v, b.v)}; }
  friend Float4 operator/(Float4 a, Float4 b) { return {_mm_div_ps(a.v, b.v)}; }
  friend Float4 min(Float4 a, Float4 b) { return {_mm_min_ps(a.v, b.v)}; }
  friend Float4 max(Float4 a, Float4 b) { return {_mm_max_ps(a.v, b.v)}; }

  // Comparisons give lane masks (all bits set where true); a NaN lane
  // compares false.
  friend Float4 operator<(Float4 a, Float4 b) { return {_mm_cmplt_ps(a.v, b.v)}; }
  friend Float4 operator<=(Float4 a, Float4 b) { return {_mm_cmple_ps(a.v, b.v)}; }
  friend Float4 operator>(Float4 a, Float4 b) { return {_mm_cmpgt_ps(a.v, b.v)}; }
  friend Float4 operator>=(Float4 a, Float4 b) { return {_mm_cmpge_ps(a.v, b.v)}; }
  friend Float4 operator&(Float4 a, Float4 b) { return {_mm_and_ps(a.v, b.v)}; }
  friend Float4 operator|(Float4 a, Float4 b) { return {_mm_or_ps(a.v, b.v)}; }
  /// Lane i of the result is `yes` where mask lane i is set, else `no`.
  friend Float4 select(Float4 mask, Float4 yes, Float4 no) {
    return {_mm_or_ps(_mm_and_ps(mask.v, yes.v), _mm_andnot_ps(mask.v, no.v))};
  }
  /// Bit i set where mask lane i is.
  int bits() const { return _mm_movemask_ps(v); }
};

#else

struct Float4 {
  float v[4];

  static Float4 load(const float* p) { return {{p[0], p[1], p[2], p[3]}}; }
  static Float4 all(float x) { return {{x, x, x, x}}; }
  void store(float* p) const {
    for (int i = 0; i < 4; ++i) p[i] = v[i];
  }

  template <typename Op>
  static Float4 each(Float4 a, Float4 b, Op op) {
    Float4 r;
    for (int i = 0; i < 4; ++i) r.v[i] = op(a.v[i], b.v[i]);
    return r;
  }
  static float mask(bool x) {
    const std::uint32_t bits = x ? 0xffffffffu : 0u;
    float f;
    __builtin_memcpy(&f, &bits, sizeof f);
    return f;
  }
  static std::uint32_t raw(float f) {
    std::uint32_t bits;
    __builtin_memcpy(&bits, &f, sizeof f);
    return bits;
  }
  static float from_raw(std::uint32_t bits) {
    float f;
    __builtin_memcpy(&f, &bits, sizeof f);
    return f;
  }

  friend Float4 operator+(Float4 a, Float4 b) {
    return each(a, b, [](float x, float y) { return x + y; });
  }
  friend Float4 operator-(Float4 a, Float4 b) {
    return each(a, b, [](float x, float y) { return x - y; });
  }
  friend Float4 operator*(Float4 a, Float4 b) {
    return each(a, b, [](float x, float y) { return x * y; });
  }
  friend Float4 operator/(Float4 a, Float4 b) {
    return each(a, b, [](float x, float y) { return x / y; });
  }
  // As SSE's minps / maxps: the second operand when either is NaN.
  friend Float4 min(Float4 a, Float4 b) {
    return each(a, b, [](float x, float y) { return x < y ? x : y; });
  }
  friend Float4 max(Float4 a, Float4 b) {
    return each(a, b, [](float x, float y) { return x > y ? x : y; });
  }
  friend Float4 operator<(Float4 a, Float4 b) {
    return each(a, b, [](float x, float y) { return mask(x < y); });
  }
  friend Float4 operator<=(Float4 a, Float4 b) {
    return each(a, b, [](float x, float y) { return mask(x <= y); });
  }
  friend Float4 operator>(Float4 a, Float4 b) {
    return each(a, b, [](float x, float y) { return mask(x > y); });
  }
  friend Float4 operator>=(Float4 a, Float4 b) {
    return each(a, b, [](float x, float y) { return mask(x >= y); });
  }
  friend Float4 operator&(Float4 a, Float4 b) {
    return each(a, b, [](float x, float y) { return from_raw(raw(x) & raw(y)); });
  }
  friend Float4 operator|(Float4 a, Float4 b) {
    return each(a, b, [](float x, float y) { return from_raw(raw(x) | raw(y)); });
  }
  friend Float4 select(Float4 m, Float4 yes, Float4 no) {
    Float4 r;
    for (int i = 0; i < 4; ++i) r.v[i] = raw(m.v[i]) ? yes.v[i] : no.v[i];
    return r;
  }
  int bits() const {
    int b = 0;
    for (int i = 0; i < 4; ++i) b |= (raw(v[i]) >> 31) << i;
    return b;
  }
};

#endif

/// The next float below f (finite): a positive float's bit pattern one
/// less, a negative one's one more, and below zero the least negative
/// (by its bits: std::nextafter is a library call, and a query rounds a
/// few coordinates).
inline float float_step_down(float f) {
  std::uint32_t bits;
  __builtin_memcpy(&bits, &f, sizeof bits);
  if (f > 0.0f)
    --bits;
  else if (f < 0.0f)
    ++bits;
  else
    bits = 0x80000001u; // -denorm_min
  float below;
  __builtin_memcpy(&below, &bits, sizeof below);
  return below;
}

/// The float nearest `x` at or below it: a box rounded outward to floats
/// holds the box. Beyond float's range: its largest value or infinity,
/// still outward.
inline float float_at_or_below(double x) {
  constexpr float kLargest = std::numeric_limits<float>::max();
  if (x > kLargest) return kLargest; // beyond float's range: the cast would not be defined
  if (x < -kLargest) return -std::numeric_limits<float>::infinity();
  const float f = static_cast<float>(x);
  return static_cast<double>(f) > x ? float_step_down(f) : f;
}
/// The float nearest `x` at or above it; see float_at_or_below.
inline float float_at_or_above(double x) { return -float_at_or_below(-x); }

/// float_at_or_below(x) and float_at_or_above(x), the same floats, from
/// one rounding of x (round to nearest is symmetric: -x rounds to minus
/// x's float).
inline void float_bracket(double x, float& below, float& above) {
  if (!(std::abs(x) <= static_cast<double>(std::numeric_limits<float>::max()))) {
    below = float_at_or_below(x);
    above = float_at_or_above(x);
    return;
  }
  const float f = static_cast<float>(x);
  const double back = static_cast<double>(f);
  below = back > x ? float_step_down(f) : f;
  above = back < x ? -float_step_down(-f) : f;
}

/// The largest of the four lanes.
inline float largest_lane(Float4 a) {
  float x[4];
  a.store(x);
  const float l = x[0] > x[1] ? x[0] : x[1], r = x[2] > x[3] ? x[2] : x[3];
  return l > r ? l : r;
}
/// The smallest of the four lanes.
inline float smallest_lane(Float4 a) {
  float x[4];
  a.store(x);
  const float l = x[0] < x[1] ? x[0] : x[1], r = x[2] < x[3] ? x[2] : x[3];
  return l < r ? l : r;
}

} // namespace hullcover::bvh::detail
