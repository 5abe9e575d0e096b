#pragma once
// The packet kernel's sphere test: intersect_sphere (sphere.hpp) for four lanes at once in AVX
// doubles, twice for a packet. Each lane repeats the scalar test's double operations in its order
// (no FMA; division and square root are correctly rounded in the lanes as in scalar code), and
// its branches become masks that keep exactly the lanes the scalar test would accept, so every
// lane gets the hit and the distance, bit for bit, that it gets alone.
#include "apps/common/geometry/packet_lanes.hpp"

#if defined(GCSIM_PACKET_AVX2)
#include <bit>

#include "apps/common/geometry/packet_triangle_lanes.hpp"

namespace gcsim::geometry::packet {

// (x0 y0 + x1 y1) + x2 y2, as glm::dot adds a product's components.
GCSIM_AVX2_INLINE __m256d dot_lanes(const __m256d x[3], const __m256d y[3]) {
  return _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(x[0], y[0]), _mm256_mul_pd(x[1], y[1])), _mm256_mul_pd(x[2], y[2]));
}

// intersect_sphere for lanes 4h to 4h + 3 against their distances tmax (32-byte aligned); bit j of the result: lane
// 4h + j hits, at t[j] (float, as intersect_sphere stores it).
GCSIM_AVX2_INLINE unsigned sphere_quad(const Sphere& sp, const Lanes& lanes, const float tmax[8], int h, float t[4]) {
  const Lanes::Spheres& l = lanes.spheres;
  const __m256d centre[3] = {_mm256_set1_pd(double(sp.center.x)), _mm256_set1_pd(double(sp.center.y)),
                             _mm256_set1_pd(double(sp.center.z))};
  __m256d f[3], d[3];
  for (int k = 0; k < 3; ++k) {
    f[k] = _mm256_sub_pd(_mm256_load_pd(l.origin[k] + 4 * h), centre[k]);
    d[k] = _mm256_load_pd(l.direction[k] + 4 * h);
  }
  const __m256d a = _mm256_load_pd(l.a + 4 * h);
  const __m256d r = _mm256_set1_pd(double(sp.radius));
  const __m256d rr = _mm256_mul_pd(r, r);
  const __m256d b = dot_lanes(f, d);
  const __m256d k = _mm256_div_pd(b, a);
  const __m256d v[3] = {_mm256_sub_pd(f[0], _mm256_mul_pd(k, d[0])), _mm256_sub_pd(f[1], _mm256_mul_pd(k, d[1])),
                        _mm256_sub_pd(f[2], _mm256_mul_pd(k, d[2]))};
  const __m256d disc = _mm256_mul_pd(a, _mm256_sub_pd(rr, dot_lanes(v, v)));
  const __m256d cc = _mm256_sub_pd(dot_lanes(f, f), rr);
  const __m256d sign = _mm256_set1_pd(-0.0);
  // copysign(sqrt(disc), b): the root's magnitude with b's sign.
  const __m256d root = _mm256_or_pd(_mm256_andnot_pd(sign, _mm256_sqrt_pd(disc)), _mm256_and_pd(sign, b));
  const __m256d q = _mm256_sub_pd(_mm256_xor_pd(b, sign), root);
  const __m256d q_zero = _mm256_cmp_pd(q, _mm256_setzero_pd(), _CMP_EQ_OQ);
  __m256d t0 = _mm256_andnot_pd(q_zero, _mm256_div_pd(cc, q));
  __m256d t1 = _mm256_andnot_pd(q_zero, _mm256_div_pd(q, a));
  const __m256d swap = _mm256_cmp_pd(t0, t1, _CMP_GT_OQ);
  const __m256d lo = _mm256_blendv_pd(t0, t1, swap), hi = _mm256_blendv_pd(t1, t0, swap);
  const __m128 tmin_f = _mm_load_ps(lanes.tmin + 4 * h), tmax_f = _mm_load_ps(tmax + 4 * h);
  const __m256d tmin_d = _mm256_cvtps_pd(tmin_f), tmax_d = _mm256_cvtps_pd(tmax_f);
  const __m256d td = _mm256_blendv_pd(lo, hi, _mm256_cmp_pd(lo, tmin_d, _CMP_LE_OQ));
  // The scalar test's exits: disc < 0, t <= tmin, t > tmax (each false on NaN, as in the lanes).
  const __m256d rejected = _mm256_or_pd(_mm256_cmp_pd(disc, _mm256_setzero_pd(), _CMP_LT_OQ),
                                        _mm256_or_pd(_mm256_cmp_pd(td, tmin_d, _CMP_LE_OQ),
                                                     _mm256_cmp_pd(td, tmax_d, _CMP_GT_OQ)));
  const __m128 tf = _mm256_cvtpd_ps(td);
  _mm_storeu_ps(t, tf);
  const __m128 kept = _mm_and_ps(_mm_cmp_ps(tf, tmin_f, _CMP_GT_OQ), _mm_cmp_ps(tf, tmax_f, _CMP_LE_OQ));
  return unsigned(_mm_movemask_ps(kept)) & ~unsigned(_mm256_movemask_pd(rejected)) & 15u;
}

// One sphere for the lanes of `lanes`, each offered its hit as intersect_sphere would.
GCSIM_AVX2 [[gnu::noinline]] inline void sphere_lanes(const Sphere& sp, int prim, const Lanes& l, unsigned lanes, State& s) {
  for (int h = 0; h < 2; ++h) {
    if (!(lanes >> (4 * h) & 15u)) continue;
    float t[4];
    for (unsigned m = sphere_quad(sp, l, s.t, h, t) & (lanes >> (4 * h)); m; m &= m - 1) {
      const int j = std::countr_zero(m);
      offer(s, 4 * h + j, t[j], prim);
    }
  }
}

}  // namespace gcsim::geometry::packet
#endif
