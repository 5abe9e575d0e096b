#pragma once
// The packet walk's per-lane data (packet_traversal.cpp): each lane's ray constants, one array of
// eight per quantity so that a quantity loads as one AVX register, and each lane's nearest hit.
// Internal to the packet kernels: compiled for AVX2 by target attribute, run only where the CPU
// reports AVX2 (the build sets no -march).
#if defined(__x86_64__) && defined(__GNUC__)
#define GCSIM_PACKET_AVX2 1
#include <immintrin.h>

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "apps/common/geometry/hit.hpp"
#include "apps/common/geometry/packet_traversal.hpp"
#include "apps/common/geometry/primitive_arrays.hpp"
#include "apps/common/geometry/sphere.hpp"
#include "apps/common/geometry/triangle.hpp"

// No FMA: contracted products would round differently from the scalar tests the lanes must match.
#define GCSIM_AVX2 __attribute__((target("avx2")))
#define GCSIM_AVX2_INLINE __attribute__((target("avx2"), always_inline)) inline

namespace gcsim::geometry::packet {

// The per-lane constants, one array of eight per quantity (lane i in element i).
struct Lanes {
  alignas(32) float o[3][8];
  alignas(32) float inv[3][8];
  alignas(32) std::int32_t negative[3][8];  // all bits set where the lane runs towards -axis
  alignas(32) float tmin[8];
  alignas(32) float shear_x[8], shear_y[8], shear_z[8];
  unsigned in_range = 0;  // lanes whose triangle tests may skip the float range check
  struct Axes {
    int kx, ky, kz;
    unsigned lanes;
  };
  Axes axes[kPacketLanes];  // lanes grouped by the triangle test's axis permutation
  int axes_count = 0;
  // Each lane's SphereRay, one array of eight per quantity (packet_sphere_lanes.hpp reads four).
  struct Spheres {
    alignas(32) double origin[3][8];
    alignas(32) double direction[3][8];
    alignas(32) double a[8];
  } spheres;
  int sphere_count = 0;                // primitive ids below are spheres
  const Triangle* triangles = nullptr;  // primitive sphere_count + k is triangles[k]
};

// Lanes of the packet that may have a nearest hit to update: their t, kept as an array to load.
struct State {
  alignas(32) float t[8];
  Hit hit[kPacketLanes];
};

GCSIM_AVX2 inline __m256i lane_mask(unsigned lanes) {
  const __m256i bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
  return _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(int(lanes)), bit), bit);
}


// Rows r[0..7] become columns: element j of r[i] afterwards is element i of r[j] before.
GCSIM_AVX2_INLINE void transpose8(__m256 r[8]) {
  __m256 t[8], u[8];
  for (int i = 0; i < 8; i += 2) t[i] = _mm256_unpacklo_ps(r[i], r[i + 1]), t[i + 1] = _mm256_unpackhi_ps(r[i], r[i + 1]);
  for (int i = 0; i < 8; i += 4) {
    u[i] = _mm256_shuffle_ps(t[i], t[i + 2], _MM_SHUFFLE(1, 0, 1, 0));
    u[i + 1] = _mm256_shuffle_ps(t[i], t[i + 2], _MM_SHUFFLE(3, 2, 3, 2));
    u[i + 2] = _mm256_shuffle_ps(t[i + 1], t[i + 3], _MM_SHUFFLE(1, 0, 1, 0));
    u[i + 3] = _mm256_shuffle_ps(t[i + 1], t[i + 3], _MM_SHUFFLE(3, 2, 3, 2));
  }
  for (int i = 0; i < 4; ++i) {
    r[i] = _mm256_permute2f128_ps(u[i], u[i + 4], 0x20);
    r[i + 4] = _mm256_permute2f128_ps(u[i], u[i + 4], 0x31);
  }
}

// The lanes' constants from their rays (bit i of `lanes`: rays[i] is live; idle lanes copy a live
// one, so their arithmetic stays finite); `root_box` bounds every triangle the lanes will test.
// A Ray is sixteen 4-byte fields: the eight rays are read whole and turned into the lanes' arrays
// by two 8 x 8 transposes.
GCSIM_AVX2 inline void prepare_lanes(const PrimitiveArrays& prims, const Bounds3& root_box, const Ray rays[],
                                     unsigned lanes, Lanes& l) {
  static_assert(sizeof(Ray) == 16 * sizeof(float) && offsetof(Ray, origin) == 0 && offsetof(Ray, direction) == 12 &&
                offsetof(Ray, tmin) == 24 && offsetof(Ray, inv_direction) == 28 && offsetof(Ray, kx) == 40 &&
                offsetof(Ray, shear_x) == 52);
  l.sphere_count = prims.sphere_count();
  l.triangles = prims.triangles.data();
  const int first = std::countr_zero(lanes);
  __m256 a[8], b[8];  // fields 0-7 (origin, direction, tmin, inv x) and 8-15 (inv y z, kx ky kz, shear)
  for (int i = 0; i < kPacketLanes; ++i) {
    const float* f = reinterpret_cast<const float*>(&rays[lanes >> i & 1u ? i : first]);  // idle lanes copy a live one
    a[i] = _mm256_loadu_ps(f);
    b[i] = _mm256_loadu_ps(f + 8);
  }
  transpose8(a);
  transpose8(b);
  const __m256 inv[3] = {a[7], b[0], b[1]};
  for (int k = 0; k < 3; ++k) {
    _mm256_store_ps(l.o[k], a[k]);
    _mm256_store_ps(l.inv[k], inv[k]);
    _mm256_store_si256(reinterpret_cast<__m256i*>(l.negative[k]), _mm256_srai_epi32(_mm256_castps_si256(inv[k]), 31));
  }
  _mm256_store_ps(l.tmin, a[6]);
  _mm256_store_ps(l.shear_x, b[5]);
  _mm256_store_ps(l.shear_y, b[6]);
  _mm256_store_ps(l.shear_z, b[7]);
  if (!prims.spheres.empty()) {  // SphereRay's doubles: origin, direction, a = (dx dx + dy dy) + dz dz
    for (int h = 0; h < 2; ++h) {
      __m256d d[3];
      for (int k = 0; k < 3; ++k) {
        const __m128 o4 = h ? _mm256_extractf128_ps(a[k], 1) : _mm256_castps256_ps128(a[k]);
        const __m128 d4 = h ? _mm256_extractf128_ps(a[3 + k], 1) : _mm256_castps256_ps128(a[3 + k]);
        _mm256_store_pd(l.spheres.origin[k] + 4 * h, _mm256_cvtps_pd(o4));
        d[k] = _mm256_cvtps_pd(d4);
        _mm256_store_pd(l.spheres.direction[k] + 4 * h, d[k]);
      }
      _mm256_store_pd(l.spheres.a + 4 * h, _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(d[0], d[0]), _mm256_mul_pd(d[1], d[1])),
                                                          _mm256_mul_pd(d[2], d[2])));
    }
  }
  // The lanes grouped by axis permutation: one group when every live lane has the first's (a
  // packet of primary rays nearly always), else in the order the lanes first show each.
  const __m256i key = _mm256_or_si256(_mm256_castps_si256(b[2]),
                                      _mm256_or_si256(_mm256_slli_epi32(_mm256_castps_si256(b[3]), 2),
                                                      _mm256_slli_epi32(_mm256_castps_si256(b[4]), 4)));
  const __m256i first_key = _mm256_permutevar8x32_epi32(key, _mm256_set1_epi32(first));
  const unsigned same = unsigned(_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(key, first_key))));
  if ((same & lanes) == lanes) {
    l.axes[0] = {rays[first].kx, rays[first].ky, rays[first].kz, lanes};
    l.axes_count = 1;
  }
  for (unsigned m = l.axes_count ? 0u : lanes; m; m &= m - 1) {
    const Ray& r = rays[std::countr_zero(m)];
    int g = 0;
    while (g < l.axes_count && !(l.axes[g].kx == r.kx && l.axes[g].ky == r.ky && l.axes[g].kz == r.kz)) ++g;
    if (g == l.axes_count) l.axes[l.axes_count++] = {r.kx, r.ky, r.kz, 0u};
    l.axes[g].lanes |= 1u << std::countr_zero(m);
  }
  // TriangleRejectRay::assume_within for every lane: the root box in float's safe range as seen
  // from the lane's origin, so every triangle below it is.
  __m256 below = _mm256_castsi256_ps(_mm256_set1_epi32(-1)), above = _mm256_setzero_ps();
  const __m256 sign = _mm256_set1_ps(-0.0f), big = _mm256_set1_ps(1e12f), small = _mm256_set1_ps(1e-12f);
  for (int a = 0; a < 3; ++a) {
    const __m256 o = _mm256_load_ps(l.o[a]);
    const __m256 lo = _mm256_sub_ps(_mm256_set1_ps(root_box.lo[a]), o);
    const __m256 hi = _mm256_sub_ps(_mm256_set1_ps(root_box.hi[a]), o);
    below = _mm256_and_ps(below, _mm256_and_ps(_mm256_cmp_ps(_mm256_andnot_ps(sign, lo), big, _CMP_LE_OQ),
                                               _mm256_cmp_ps(_mm256_andnot_ps(sign, hi), big, _CMP_LE_OQ)));
    above = _mm256_or_ps(above, _mm256_or_ps(_mm256_cmp_ps(lo, small, _CMP_GE_OQ),
                                             _mm256_cmp_ps(hi, _mm256_set1_ps(-1e-12f), _CMP_LE_OQ)));
  }
  l.in_range = lanes & unsigned(_mm256_movemask_ps(_mm256_and_ps(below, above)));
}

}  // namespace gcsim::geometry::packet
#endif
