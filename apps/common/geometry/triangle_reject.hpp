#pragma once
// A quick SSE rejection in front of the watertight triangle test (triangle.cpp). Most triangle
// tests of a traversal miss, and they miss at the edge-function signs; this computes those three
// edge functions at once, with the same float operations in the same order as the scalar test,
// so it rejects exactly the triangles the scalar test rejects there. Whenever the scalar test
// would take another path (coordinates outside float's safe range, an edge function exactly 0)
// it answers "not sure" and the caller runs the full test.
#include <cmath>
#include <cstddef>

#include "apps/common/geometry/bounds.hpp"
#include "apps/common/geometry/ray.hpp"
#include "apps/common/geometry/triangle.hpp"

#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace gcsim::geometry {

#if defined(__SSE2__)

static_assert(sizeof(Triangle) == 9 * sizeof(float) && offsetof(Triangle, p1) == 3 * sizeof(float) &&
                  offsetof(Triangle, p2) == 6 * sizeof(float),
              "the loads below read the three vertices as 9 packed floats");

#if defined(__AVX__)
using RejectLanes = __m256;  // both halves the same: two triangles are rejected at once (triangle_verdicts2)
inline RejectLanes broadcast_lanes(float v) { return _mm256_set1_ps(v); }
inline __m128 low_lanes(RejectLanes v) { return _mm256_castps256_ps128(v); }
#else
using RejectLanes = __m128;
inline RejectLanes broadcast_lanes(float v) { return _mm_set1_ps(v); }
inline __m128 low_lanes(RejectLanes v) { return v; }
#endif

// The per-ray constants of the rejection, broadcast once per ray rather than per test.
struct TriangleRejectRay {
  RejectLanes o[3];
  RejectLanes shear_x, shear_y;
  int kx, ky, kz;
  bool in_range = false;  // every triangle tested passes the float range check
  TriangleRejectRay() = default;  // for a walk without triangles, which never reads it
  explicit TriangleRejectRay(const Ray& r)
      : o{broadcast_lanes(r.origin.x), broadcast_lanes(r.origin.y), broadcast_lanes(r.origin.z)},
        shear_x(broadcast_lanes(r.shear_x)), shear_y(broadcast_lanes(r.shear_y)), kx(r.kx), ky(r.ky), kz(r.kz) {}

  // Skips the range check for triangles whose vertices lie in `box` (a tree's root box) when the
  // whole box passes it: float subtraction is monotonic, so a vertex's |p - o| per axis is at
  // most the larger of |lo - o| and |hi - o|, and on an axis where the box lies wholly 1e-12 or
  // more to one side of the origin, every vertex has a coordinate at least that large.
  // (Per axis: l = lo - o, h = hi - o; below: every |l|, |h| <= 1e12; above: some l >= 1e-12 or
  // h <= -1e-12. Lane 3 is not an axis.)
  void assume_within(const Bounds3& box) {
    const __m128 o4 = _mm_setr_ps(lane_of(o[0]), lane_of(o[1]), lane_of(o[2]), 0.0f);
    const __m128 l = _mm_sub_ps(_mm_setr_ps(box.lo.x, box.lo.y, box.lo.z, 0.0f), o4);
    const __m128 h = _mm_sub_ps(_mm_setr_ps(box.hi.x, box.hi.y, box.hi.z, 0.0f), o4);
    const __m128 sign = _mm_set1_ps(-0.0f), big = _mm_set1_ps(1e12f);
    const __m128 below = _mm_and_ps(_mm_cmple_ps(_mm_andnot_ps(sign, l), big), _mm_cmple_ps(_mm_andnot_ps(sign, h), big));
    const __m128 above = _mm_or_ps(_mm_cmpge_ps(l, _mm_set1_ps(1e-12f)), _mm_cmple_ps(h, _mm_set1_ps(-1e-12f)));
    in_range = (_mm_movemask_ps(below) & 7) == 7 && (_mm_movemask_ps(above) & 7) != 0;
  }

 private:
  static float lane_of(RejectLanes v) { return _mm_cvtss_f32(low_lanes(v)); }
};

// What the rejection found: the triangle is surely missed; or its edge functions all have one
// sign (none 0) and its coordinates are in float's range, so watertight_finish (triangle_finish.hpp)
// decides from what was computed here; or the scalar test must decide alone.
enum class RejectVerdict { missed, inside, unsure };

// Lanes whose edge function is neither 0 nor NaN: there its sign bit is its sign.
inline int edge_functions_decided(__m128 e) {
#if defined(__AVX__)
  return _mm_movemask_ps(_mm_cmp_ps(e, _mm_setzero_ps(), _CMP_NEQ_OQ));
#else
  return _mm_movemask_ps(_mm_and_ps(_mm_cmpneq_ps(e, _mm_setzero_ps()), _mm_cmpord_ps(e, e)));
#endif
}

// From the sign bits of three decided edge functions: signs both ways miss.
inline RejectVerdict sign_verdict(int negative) {
  return negative != 0 && negative != 7 ? RejectVerdict::missed : RejectVerdict::inside;
}

// kX, kY, kZ: the ray's kx, ky, kz when the caller knows them at compile time (the vertex rows
// then stay in registers), -1 to read them from r. Unless the verdict is unsure, sets `sheared`:
// rows x, y, z of the sheared vertices a, b, c, then the edge functions e (lane 3 unused).
template <int kX = -1, int kY = -1, int kZ = -1>
[[gnu::always_inline]] inline RejectVerdict triangle_verdict(const Triangle& tri, const TriangleRejectRay& r, __m128 sheared[4]) {
  const float* p = &tri.p0.x;
  // Rows p0, p1, p2 (lane 3 unused), all loads inside the 36 bytes of the triangle.
  __m128 r0 = _mm_loadu_ps(p), r1 = _mm_loadu_ps(p + 3), r2 = _mm_loadu_ps(p + 5);
  r2 = _mm_shuffle_ps(r2, r2, _MM_SHUFFLE(3, 3, 2, 1));
  __m128 r3 = r2;
  _MM_TRANSPOSE4_PS(r0, r1, r2, r3);  // r0 = (a.x, b.x, c.x, c.x), r1 = y, r2 = z, as vertices a, b, c
  const __m128 v[3] = {_mm_sub_ps(r0, low_lanes(r.o[0])), _mm_sub_ps(r1, low_lanes(r.o[1])), _mm_sub_ps(r2, low_lanes(r.o[2]))};

  // The scalar test runs in float only if the largest |coordinate| is within [1e-12, 1e12].
  if (!r.in_range) {
    const __m128 sign = _mm_set1_ps(-0.0f), big = _mm_set1_ps(1e12f), small = _mm_set1_ps(1e-12f);
    const __m128 m0 = _mm_andnot_ps(sign, v[0]), m1 = _mm_andnot_ps(sign, v[1]), m2 = _mm_andnot_ps(sign, v[2]);
    const __m128 below = _mm_and_ps(_mm_and_ps(_mm_cmple_ps(m0, big), _mm_cmple_ps(m1, big)), _mm_cmple_ps(m2, big));
    const __m128 above =
        _mm_or_ps(_mm_or_ps(_mm_cmpge_ps(m0, small), _mm_cmpge_ps(m1, small)), _mm_cmpge_ps(m2, small));
    if (_mm_movemask_ps(below) != 15 || _mm_movemask_ps(above) == 0) return RejectVerdict::unsure;
  }

  // Permute and shear (ax = a[kx] + sx * a[kz], ...), then e_i = x_j y_k - y_j x_k over the
  // cyclic rotations (j, k) = (b, c), (c, a), (a, b).
  const __m128 z = v[kZ < 0 ? r.kz : kZ];
  const __m128 x = _mm_add_ps(v[kX < 0 ? r.kx : kX], _mm_mul_ps(low_lanes(r.shear_x), z));
  const __m128 y = _mm_add_ps(v[kY < 0 ? r.ky : kY], _mm_mul_ps(low_lanes(r.shear_y), z));
  const __m128 x1 = _mm_shuffle_ps(x, x, _MM_SHUFFLE(3, 0, 2, 1)), x2 = _mm_shuffle_ps(x, x, _MM_SHUFFLE(3, 1, 0, 2));
  const __m128 y1 = _mm_shuffle_ps(y, y, _MM_SHUFFLE(3, 0, 2, 1)), y2 = _mm_shuffle_ps(y, y, _MM_SHUFFLE(3, 1, 0, 2));
  const __m128 e = _mm_sub_ps(_mm_mul_ps(x1, y2), _mm_mul_ps(y1, x2));
  // An edge function exactly 0: the scalar test retries in double; NaN (a NaN vertex, which no
  // box bounds): leave it to the scalar test too.
  if ((edge_functions_decided(e) & 7) != 7) return RejectVerdict::unsure;
  sheared[0] = x, sheared[1] = y, sheared[2] = z, sheared[3] = e;
  return sign_verdict(_mm_movemask_ps(e) & 7);
}

#if defined(__AVX__)
// triangle_verdict for two triangles at once, for a tree node whose children are both triangles:
// triangle a in the low half of every register and b in the high half, each half the operations
// of triangle_verdict in the same order, so each verdict and its rows are triangle_verdict's.
struct RejectPair {
  RejectVerdict verdict[2];
  __m256 x, y, z, e;  // the rows of both; half k is triangle k's sheared[] when not unsure
  void rows(int k, __m128 sheared[4]) const {
    const auto half = [k](__m256 v) { return k == 0 ? _mm256_castps256_ps128(v) : _mm256_extractf128_ps(v, 1); };
    sheared[0] = half(x), sheared[1] = half(y), sheared[2] = half(z), sheared[3] = half(e);
  }
};

template <int kX = -1, int kY = -1, int kZ = -1>
[[gnu::always_inline]] inline RejectPair triangle_verdicts2(const Triangle& ta, const Triangle& tb,
                                                            const TriangleRejectRay& r) {
  const auto rows_of = [&](int offset) {
    return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(&ta.p0.x + offset)), _mm_loadu_ps(&tb.p0.x + offset), 1);
  };
  __m256 r0 = rows_of(0), r1 = rows_of(3), r2 = rows_of(5);
  r2 = _mm256_shuffle_ps(r2, r2, _MM_SHUFFLE(3, 3, 2, 1));
  // _MM_TRANSPOSE4_PS in each half (its unpacks, movelh and movehl are these in-lane shuffles).
  const __m256 t0 = _mm256_unpacklo_ps(r0, r1), t1 = _mm256_unpackhi_ps(r0, r1);
  const __m256 t2 = _mm256_unpacklo_ps(r2, r2), t3 = _mm256_unpackhi_ps(r2, r2);
  r0 = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0));
  r1 = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2));
  r2 = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0));
  const __m256 v[3] = {_mm256_sub_ps(r0, r.o[0]), _mm256_sub_ps(r1, r.o[1]), _mm256_sub_ps(r2, r.o[2])};
  bool sure[2] = {true, true};
  if (!r.in_range) {
    const __m256 sign = _mm256_set1_ps(-0.0f), big = _mm256_set1_ps(1e12f), small = _mm256_set1_ps(1e-12f);
    const __m256 m0 = _mm256_andnot_ps(sign, v[0]), m1 = _mm256_andnot_ps(sign, v[1]), m2 = _mm256_andnot_ps(sign, v[2]);
    const int below = _mm256_movemask_ps(_mm256_and_ps(
        _mm256_and_ps(_mm256_cmp_ps(m0, big, _CMP_LE_OS), _mm256_cmp_ps(m1, big, _CMP_LE_OS)), _mm256_cmp_ps(m2, big, _CMP_LE_OS)));
    const int above = _mm256_movemask_ps(_mm256_or_ps(
        _mm256_or_ps(_mm256_cmp_ps(m0, small, _CMP_GE_OS), _mm256_cmp_ps(m1, small, _CMP_GE_OS)), _mm256_cmp_ps(m2, small, _CMP_GE_OS)));
    for (int k = 0; k < 2; ++k) sure[k] = (below >> (4 * k) & 15) == 15 && (above >> (4 * k) & 15) != 0;
  }
  RejectPair out;
  out.z = v[kZ < 0 ? r.kz : kZ];
  out.x = _mm256_add_ps(v[kX < 0 ? r.kx : kX], _mm256_mul_ps(r.shear_x, out.z));
  out.y = _mm256_add_ps(v[kY < 0 ? r.ky : kY], _mm256_mul_ps(r.shear_y, out.z));
  const __m256 x1 = _mm256_shuffle_ps(out.x, out.x, _MM_SHUFFLE(3, 0, 2, 1)), x2 = _mm256_shuffle_ps(out.x, out.x, _MM_SHUFFLE(3, 1, 0, 2));
  const __m256 y1 = _mm256_shuffle_ps(out.y, out.y, _MM_SHUFFLE(3, 0, 2, 1)), y2 = _mm256_shuffle_ps(out.y, out.y, _MM_SHUFFLE(3, 1, 0, 2));
  out.e = _mm256_sub_ps(_mm256_mul_ps(x1, y2), _mm256_mul_ps(y1, x2));
  const int decided = _mm256_movemask_ps(_mm256_cmp_ps(out.e, _mm256_setzero_ps(), _CMP_NEQ_OQ));
  const int negative = _mm256_movemask_ps(out.e);
  for (int k = 0; k < 2; ++k)
    out.verdict[k] = !sure[k] || (decided >> (4 * k) & 7) != 7 ? RejectVerdict::unsure : sign_verdict(negative >> (4 * k) & 7);
  return out;
}
#endif

// True only if intersect_triangle(tri, ray, ...) surely returns false for any tmax.
template <int kX = -1, int kY = -1, int kZ = -1>
inline bool triangle_surely_missed(const Triangle& tri, const TriangleRejectRay& r) {
  __m128 sheared[4];
  return triangle_verdict<kX, kY, kZ>(tri, r, sheared) == RejectVerdict::missed;
}

#else

struct TriangleRejectRay {
  bool in_range = false;  // read and kept by the walk's per-origin memo; nothing to skip here
  TriangleRejectRay() = default;
  explicit TriangleRejectRay(const Ray&) {}
  void assume_within(const Bounds3&) {}
};
template <int kX = -1, int kY = -1, int kZ = -1>
inline bool triangle_surely_missed(const Triangle&, const TriangleRejectRay&) { return false; }

#endif

}  // namespace gcsim::geometry
