#pragma once
// The watertight triangle test of triangle.cpp for the eight lanes of a packet, split as the
// single-ray walk's rejection and finish are: the verdict (sheared vertices, edge functions,
// which lanes are inside, which the scalar test must decide) and the finish (distance, rounding
// bound, offer). Each lane repeats the scalar float operations in the scalar order (no FMA), so it
// gets the bits the scalar test gives it; lanes the verdict cannot decide go to that test.
#include "apps/common/geometry/packet_lanes.hpp"

#if defined(GCSIM_PACKET_AVX2)
#include <bit>
#include <limits>

#include "apps/common/geometry/float_util.hpp"

namespace gcsim::geometry::packet {

GCSIM_AVX2 inline void offer(State& s, int lane, float t, int prim, float b1 = 0, float b2 = 0) {
  s.hit[lane].offer(t, prim, b1, b2);
  s.t[lane] = s.hit[lane].t;
}

// The full scalar test for one lane (outside float's safe range, or an edge function exactly 0).
GCSIM_AVX2 inline void scalar_triangle(const Triangle& tri, int prim, const Ray rays[], int i, State& s) {
  float t, b1 = 0, b2 = 0;
  if (intersect_triangle(tri, rays[i], s.t[i], &t, &b1, &b2)) offer(s, i, t, prim, b1, b2);
}

// max(|v0|, |v1|, |v2|) per lane.
GCSIM_AVX2 inline __m256 largest(const __m256 v[3]) {
  const __m256 sign = _mm256_set1_ps(-0.0f);
  return _mm256_max_ps(_mm256_max_ps(_mm256_andnot_ps(sign, v[0]), _mm256_andnot_ps(sign, v[1])),
                       _mm256_andnot_ps(sign, v[2]));
}

// The rounding bound on t for the lanes, term by term as triangle.cpp writes it.
GCSIM_AVX2_INLINE __m256 t_error_bound(const __m256 (&zs)[3], const __m256 (&x)[3], const __m256 (&y)[3],
                                       const __m256 (&e)[3], __m256 inv_det) {
  const __m256 sign = _mm256_set1_ps(-0.0f);
  const __m256 max_z = largest(zs), max_x = largest(x), max_y = largest(y), max_e = largest(e);
  const __m256 g2 = _mm256_set1_ps(gamma_of<float>(2)), g3 = _mm256_set1_ps(gamma_of<float>(3)),
               g5 = _mm256_set1_ps(gamma_of<float>(5));
  const __m256 dz = _mm256_mul_ps(g3, max_z);
  const __m256 dx = _mm256_mul_ps(g5, _mm256_add_ps(max_x, max_z));
  const __m256 dy = _mm256_mul_ps(g5, _mm256_add_ps(max_y, max_z));
  const __m256 de = _mm256_mul_ps(
      _mm256_set1_ps(2.0f),
      _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(_mm256_mul_ps(g2, max_x), max_y), _mm256_mul_ps(dy, max_x)),
                    _mm256_mul_ps(dx, max_y)));
  return _mm256_mul_ps(
      _mm256_mul_ps(_mm256_set1_ps(3.0f),
                    _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(_mm256_mul_ps(g3, max_e), max_z), _mm256_mul_ps(de, max_z)),
                                  _mm256_mul_ps(dz, max_e))),
      _mm256_andnot_ps(sign, inv_det));
}

// The first half of the watertight test of triangle.cpp (its float path) for the lanes of one
// axis permutation: the sheared vertices and edge functions, with the scalar test's float
// operations in its order, so each lane rounds as it would alone. It does not read the lanes'
// hit distances, so a node's two triangles can take it before either is finished.
struct TriangleVerdict {
  __m256 x[3], y[3], z[3], e[3];
  unsigned scalar;  // lanes the scalar test decides: outside float's range, or an edge function 0 or NaN
  unsigned inside;  // lanes inside all three edges, to be finished
};

GCSIM_AVX2_INLINE void triangle_verdict(const Triangle& tri, const Lanes& l, const Lanes::Axes& ax, unsigned lanes,
                                        TriangleVerdict& v) {
  const unsigned group = lanes & ax.lanes;
  // The nine coordinates as floats in a row (glm's operator[] with a run-time index is a switch).
  static_assert(sizeof(Triangle) == 9 * sizeof(float));
  const float* p = &tri.p0.x;
  __m256(&x)[3] = v.x;
  __m256(&y)[3] = v.y;
  __m256(&z)[3] = v.z;
  const __m256 sx = _mm256_load_ps(l.shear_x), sy = _mm256_load_ps(l.shear_y);
  const __m256 ox = _mm256_load_ps(l.o[ax.kx]), oy = _mm256_load_ps(l.o[ax.ky]), oz = _mm256_load_ps(l.o[ax.kz]);
  for (int k = 0; k < 3; ++k) {
    z[k] = _mm256_sub_ps(_mm256_set1_ps(p[3 * k + ax.kz]), oz);
    const __m256 vx = _mm256_sub_ps(_mm256_set1_ps(p[3 * k + ax.kx]), ox);
    const __m256 vy = _mm256_sub_ps(_mm256_set1_ps(p[3 * k + ax.ky]), oy);
    x[k] = _mm256_add_ps(vx, _mm256_mul_ps(sx, z[k]));
    y[k] = _mm256_add_ps(vy, _mm256_mul_ps(sy, z[k]));
  }
  __m256(&e)[3] = v.e;
  e[0] = _mm256_sub_ps(_mm256_mul_ps(x[1], y[2]), _mm256_mul_ps(y[1], x[2]));
  e[1] = _mm256_sub_ps(_mm256_mul_ps(x[2], y[0]), _mm256_mul_ps(y[2], x[0]));
  e[2] = _mm256_sub_ps(_mm256_mul_ps(x[0], y[1]), _mm256_mul_ps(y[0], x[1]));
  const __m256 zero = _mm256_setzero_ps();
  __m256 unsure = zero, negative = zero, positive = zero;
  for (const __m256& f : e) {
    unsure = _mm256_or_ps(unsure, _mm256_cmp_ps(f, zero, _CMP_EQ_UQ));  // 0 or NaN
    negative = _mm256_or_ps(negative, _mm256_cmp_ps(f, zero, _CMP_LT_OQ));
    positive = _mm256_or_ps(positive, _mm256_cmp_ps(f, zero, _CMP_GT_OQ));
  }
  v.scalar = group & ~(l.in_range & ~unsigned(_mm256_movemask_ps(unsure)));
  v.inside = group & ~v.scalar & ~unsigned(_mm256_movemask_ps(_mm256_and_ps(negative, positive)));
}

// The second half for the verdict's inside lanes: distance, its rounding bound and the hit
// offered to each lane, which reads the lanes' distances as they are now.
GCSIM_AVX2_INLINE void finish_triangle_lanes(const TriangleVerdict& v, int prim, const Lanes& l, State& s) {
  const __m256(&x)[3] = v.x;
  const __m256(&y)[3] = v.y;
  const __m256(&z)[3] = v.z;
  const __m256(&e)[3] = v.e;
  const __m256 zero = _mm256_setzero_ps();
  const __m256 det = _mm256_add_ps(_mm256_add_ps(e[0], e[1]), e[2]);
  const __m256 sz = _mm256_load_ps(l.shear_z);
  const __m256 zs[3] = {_mm256_mul_ps(z[0], sz), _mm256_mul_ps(z[1], sz), _mm256_mul_ps(z[2], sz)};
  const __m256 t_scaled = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(e[0], zs[0]), _mm256_mul_ps(e[1], zs[1])),
                                        _mm256_mul_ps(e[2], zs[2]));
  const __m256 tmax = _mm256_load_ps(s.t), tmin = _mm256_load_ps(l.tmin);
  const __m256 t0 = _mm256_mul_ps(tmin, det);
  const __m256 t1 = _mm256_mul_ps(_mm256_mul_ps(tmax, _mm256_set1_ps(1 + 4.0f * std::numeric_limits<float>::epsilon())), det);
  // det < 0: t_scaled in (t1 det, t0 det); det > 0: in (t0 det, t1 det]; det 0 or NaN: no hit.
  const __m256 below = _mm256_andnot_ps(
      _mm256_or_ps(_mm256_cmp_ps(t_scaled, t0, _CMP_GE_OQ), _mm256_cmp_ps(t_scaled, t1, _CMP_LT_OQ)),
      _mm256_cmp_ps(det, zero, _CMP_LT_OQ));
  const __m256 above = _mm256_andnot_ps(
      _mm256_or_ps(_mm256_cmp_ps(t_scaled, t0, _CMP_LE_OQ), _mm256_cmp_ps(t_scaled, t1, _CMP_GT_OQ)),
      _mm256_cmp_ps(det, zero, _CMP_GT_OQ));
  unsigned hit = v.inside & unsigned(_mm256_movemask_ps(_mm256_or_ps(below, above)));
  if (!hit) return;
  const __m256 inv_det = _mm256_div_ps(_mm256_set1_ps(1.0f), det);
  const __m256 t = _mm256_mul_ps(t_scaled, inv_det);
  const __m256 dt = t_error_bound(zs, x, y, e, inv_det);
  const __m256 ok = _mm256_andnot_ps(_mm256_cmp_ps(t, dt, _CMP_LE_OQ),
                                     _mm256_and_ps(_mm256_cmp_ps(t, tmin, _CMP_GT_OQ), _mm256_cmp_ps(t, tmax, _CMP_LE_OQ)));
  hit &= unsigned(_mm256_movemask_ps(ok));
  alignas(32) float tv[8], b1[8], b2[8];
  _mm256_store_ps(tv, t);
  _mm256_store_ps(b1, _mm256_mul_ps(e[1], inv_det));
  _mm256_store_ps(b2, _mm256_mul_ps(e[2], inv_det));
  // The lanes' t updated in one store, not eight scalar ones: the walk reads them back as one
  // vector, which could not be forwarded from narrower stores. After an offer a lane's t is
  // min(old t, t) whether or not the id tie-break took the hit.
  _mm256_store_ps(s.t, _mm256_blendv_ps(tmax, _mm256_min_ps(tmax, t), _mm256_castsi256_ps(lane_mask(hit))));
  for (; hit; hit &= hit - 1) {
    const int i = std::countr_zero(hit);
    s.hit[i].offer(tv[i], prim, b1[i], b2[i]);
  }
}

// The whole test for the lanes of one axis permutation: hits offered; returns the lanes the
// scalar test must decide (it retries those in double).
GCSIM_AVX2_INLINE unsigned intersect_lanes(const Triangle& tri, int prim, const Lanes& l, const Lanes::Axes& ax,
                                           unsigned lanes, State& s) {
  TriangleVerdict v;
  triangle_verdict(tri, l, ax, lanes, v);
  if (v.inside) finish_triangle_lanes(v, prim, l, s);
  return v.scalar;
}

}  // namespace gcsim::geometry::packet
#endif
