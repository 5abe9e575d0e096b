#pragma once
// The single-ray walk's box test: both children of a PairNode against one ray at once (the
// octant-compiled walks in traversal.cpp and the depth-first walk of shadow rays).
#include <algorithm>
#include <cmath>
#include <type_traits>
#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "apps/common/geometry/float_util.hpp"
#include "apps/common/geometry/packed_tree.hpp"
#include "apps/common/geometry/ray.hpp"

namespace gcsim::geometry::slab {

// Slab tests of both children of n at once (see intersect_box for the conservative rounding and
// NaN handling: a NaN from 0 * inf, an axis-parallel ray in a slab plane, is dropped by max/min,
// which return their second operand when the first is NaN). The far distance is scaled up once,
// after the minimum, which is the same as scaling each.
struct SlabRay {
  float o[3], inv[3];
  bool negative[3];  // the hi plane is met first
  explicit SlabRay(const Ray& r) {
    for (int a = 0; a < 3; ++a) {
      o[a] = r.origin[a];
      inv[a] = r.inv_direction[a];
      negative[a] = std::signbit(inv[a]);
    }
  }
};

// Bit a of kSigns: the ray runs towards -axis a; -1: read from the ray at run time. The
// closest-hit walk is compiled for each of the eight octants, so the near/far choice per axis
// costs nothing inside the loop.
template <int kSigns>
inline bool negative_axis(const SlabRay& r, int a) {
  if constexpr (kSigns < 0) return r.negative[a];
  else return (kSigns >> a) & 1;
}

#if defined(__SSE2__)
// The ray's slab constants broadcast once per ray, not once per node. For a walk compiled for the
// ray's octant, also the reciprocal with its far half negated (see both_children).
struct SlabLanes {
  const SlabRay& ray;
  __m128 o[3], inv[3], tmin;
  __m128 inv_signed[3];  // (inv, inv, -inv, -inv); on an axis the ray runs down, (-inv, -inv, inv, inv)
  __m128 start;          // (tmin, tmin, -inf, -inf)
  // The conservative scalings of both_children, in memory for the multiplies to read (the loop
  // has no register to keep them in, and would otherwise rebuild them at every node).
  __m128 far_scale_negated = _mm_set1_ps(-(1.0f + 2.0f * gamma(3)));
  __m128 near_scale = _mm_set1_ps(1.0f - 2.0f * gamma(3));
  // kSigns >= 0: the ray's octant, known to the walk at compile time (negative_axis).
  template <int kSigns = -1>
  SlabLanes(const SlabRay& r, float t0, std::integral_constant<int, kSigns> = {})
      : ray(r),
        o{_mm_set1_ps(r.o[0]), _mm_set1_ps(r.o[1]), _mm_set1_ps(r.o[2])},
        inv{_mm_set1_ps(r.inv[0]), _mm_set1_ps(r.inv[1]), _mm_set1_ps(r.inv[2])},
        tmin(_mm_set1_ps(t0)),
        start(_mm_setr_ps(t0, t0, -kInfinity, -kInfinity)) {
    alignas(16) static constexpr float kFlip[2][4] = {{0.0f, 0.0f, -0.0f, -0.0f}, {-0.0f, -0.0f, 0.0f, 0.0f}};
    for (int a = 0; a < 3; ++a) inv_signed[a] = _mm_xor_ps(inv[a], _mm_load_ps(kFlip[negative_axis<kSigns>(r, a)]));
  }
};

template <int kSigns>
inline unsigned both_children(const PairNode& n, const SlabLanes& r, float tmax, float entry[2]) {
  __m128 t0, far;
  if constexpr (kSigns >= 0) {
    // One max per axis instead of a max and a min: the far distances are carried negated,
    // (lo0, lo1, hi0, hi1) - o times (inv, inv, -inv, -inv) being (near0, near1, -far0, -far1)
    // exactly (negation is exact in every step), halves swapped on an axis the ray runs down.
    // max(-f, -t) is -min(f, t) bit for bit, and like min it keeps its second operand when the
    // first is NaN or the two are equal.
    t0 = r.start;
    for (int a = 0; a < 3; ++a) {
      __m128 t = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(n.bounds[a]), r.o[a]), r.inv_signed[a]);
      if ((kSigns >> a) & 1) t = _mm_shuffle_ps(t, t, _MM_SHUFFLE(1, 0, 3, 2));
      t0 = _mm_max_ps(t, t0);
    }
    // (-f) * -(1 + 2 gamma) is f * (1 + 2 gamma) bit for bit: rounding to nearest is symmetric.
    far = _mm_min_ps(_mm_mul_ps(_mm_movehl_ps(t0, t0), r.far_scale_negated), _mm_set1_ps(tmax));
  } else {
    t0 = r.tmin;
    __m128 t1 = _mm_set1_ps(kInfinity);
    for (int a = 0; a < 3; ++a) {
      // (lo0, lo1, hi0, hi1) -> distances; the near pair is in the low or high half.
      const __m128 t = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(n.bounds[a]), r.o[a]), r.inv[a]);
      const __m128 swapped = _mm_movehl_ps(t, t);
      const bool negative = r.ray.negative[a];
      const __m128 tn = negative ? swapped : t;
      const __m128 tf = negative ? t : swapped;
      t0 = _mm_max_ps(tn, t0);
      t1 = _mm_min_ps(tf, t1);
    }
    far = _mm_min_ps(_mm_mul_ps(t1, _mm_set1_ps(1.0f + 2.0f * gamma(3))), _mm_set1_ps(tmax));
  }
  const __m128 near = _mm_mul_ps(t0, r.near_scale);
  entry[0] = _mm_cvtss_f32(near);
  entry[1] = _mm_cvtss_f32(_mm_shuffle_ps(near, near, _MM_SHUFFLE(1, 1, 1, 1)));
  return static_cast<unsigned>(_mm_movemask_ps(_mm_cmple_ps(t0, far))) & 3u;
}
#else
struct SlabLanes {
  const SlabRay& ray;
  float tmin;
  template <int kSigns = -1>
  SlabLanes(const SlabRay& r, float t0, std::integral_constant<int, kSigns> = {}) : ray(r), tmin(t0) {}
};

template <int kSigns>
inline unsigned both_children(const PairNode& n, const SlabLanes& lanes, float tmax, float entry[2]) {
  const SlabRay& r = lanes.ray;
  unsigned mask = 0;
  for (int c = 0; c < 2; ++c) {
    float t0 = lanes.tmin, t1 = kInfinity;
    for (int a = 0; a < 3; ++a) {
      float tn = (n.bounds[a][c] - r.o[a]) * r.inv[a];
      float tf = (n.bounds[a][2 + c] - r.o[a]) * r.inv[a];
      if (negative_axis<kSigns>(r, a)) std::swap(tn, tf);
      t0 = tn > t0 ? tn : t0;
      t1 = tf < t1 ? tf : t1;
    }
    entry[c] = t0 * (1.0f - 2.0f * gamma(3));
    mask |= unsigned(t0 <= std::min(t1 * (1.0f + 2.0f * gamma(3)), tmax)) << c;
  }
  return mask;
}
#endif

}  // namespace gcsim::geometry::slab
