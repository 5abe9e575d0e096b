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


// The lanes' constants from their rays (bit i of `lanes`: rays[i] is live; idle lanes copy a live
// one, so their arithmetic stays finite); `root_box` bounds every triangle the lanes will test.
GCSIM_AVX2 inline void prepare_lanes(const PrimitiveArrays& prims, const Bounds3& root_box, const Ray rays[],
                                     unsigned lanes, Lanes& l) {
  l.sphere_count = prims.sphere_count();
  l.triangles = prims.triangles.data();
  for (int i = 0; i < kPacketLanes; ++i) {
    const Ray& r = rays[lanes >> i & 1u ? i : std::countr_zero(lanes)];  // idle lanes copy a live one
    for (int a = 0; a < 3; ++a) {
      l.o[a][i] = r.origin[a];
      l.inv[a][i] = r.inv_direction[a];
      l.negative[a][i] = std::signbit(r.inv_direction[a]) ? -1 : 0;
    }
    l.tmin[i] = r.tmin;
    l.shear_x[i] = r.shear_x;
    l.shear_y[i] = r.shear_y;
    l.shear_z[i] = r.shear_z;
    if (!prims.spheres.empty()) {  // idle lanes too: their doubles stay finite
      const SphereRay sr(r);
      for (int a = 0; a < 3; ++a) l.spheres.origin[a][i] = sr.origin[a], l.spheres.direction[a][i] = sr.direction[a];
      l.spheres.a[i] = sr.a;
    }
    if (!(lanes >> i & 1u)) continue;
    int g = 0;
    while (g < l.axes_count && !(l.axes[g].kx == r.kx && l.axes[g].ky == r.ky && l.axes[g].kz == r.kz)) ++g;
    if (g == l.axes_count) l.axes[l.axes_count++] = {r.kx, r.ky, r.kz, 0u};
    l.axes[g].lanes |= 1u << i;
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
