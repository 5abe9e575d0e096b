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

// The per-ray constants of the rejection, broadcast once per ray rather than per test.
struct TriangleRejectRay {
  __m128 o[3];
  __m128 shear_x, shear_y;
  int kx, ky, kz;
  bool in_range = false;  // every triangle tested passes the float range check
  TriangleRejectRay() = default;  // for a walk without triangles, which never reads it
  explicit TriangleRejectRay(const Ray& r)
      : o{_mm_set1_ps(r.origin.x), _mm_set1_ps(r.origin.y), _mm_set1_ps(r.origin.z)},
        shear_x(_mm_set1_ps(r.shear_x)), shear_y(_mm_set1_ps(r.shear_y)), kx(r.kx), ky(r.ky), kz(r.kz),
        origin(r.origin) {}

  // Skips the range check for triangles whose vertices lie in `box` (a tree's root box) when the
  // whole box passes it: float subtraction is monotonic, so a vertex's |p - o| per axis is at
  // most the larger of |lo - o| and |hi - o|, and on an axis where the box lies wholly 1e-12 or
  // more to one side of the origin, every vertex has a coordinate at least that large.
  void assume_within(const Bounds3& box) {
    bool below = true, above = false;
    for (int a = 0; a < 3; ++a) {
      const float l = box.lo[a] - origin[a], h = box.hi[a] - origin[a];
      below = below && std::fabs(l) <= 1e12f && std::fabs(h) <= 1e12f;
      above = above || l >= 1e-12f || h <= -1e-12f;
    }
    in_range = below && above;
  }

 private:
  glm::vec3 origin;
};

// What the rejection found: the triangle is surely missed; or its edge functions all have one
// sign (none 0) and its coordinates are in float's range, so watertight_finish (triangle_finish.hpp)
// decides from what was computed here; or the scalar test must decide alone.
enum class RejectVerdict { missed, inside, unsure };

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
  const __m128 v[3] = {_mm_sub_ps(r0, r.o[0]), _mm_sub_ps(r1, r.o[1]), _mm_sub_ps(r2, r.o[2])};

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
  const __m128 x = _mm_add_ps(v[kX < 0 ? r.kx : kX], _mm_mul_ps(r.shear_x, z));
  const __m128 y = _mm_add_ps(v[kY < 0 ? r.ky : kY], _mm_mul_ps(r.shear_y, z));
  const __m128 x1 = _mm_shuffle_ps(x, x, _MM_SHUFFLE(3, 0, 2, 1)), x2 = _mm_shuffle_ps(x, x, _MM_SHUFFLE(3, 1, 0, 2));
  const __m128 y1 = _mm_shuffle_ps(y, y, _MM_SHUFFLE(3, 0, 2, 1)), y2 = _mm_shuffle_ps(y, y, _MM_SHUFFLE(3, 1, 0, 2));
  const __m128 e = _mm_sub_ps(_mm_mul_ps(x1, y2), _mm_mul_ps(y1, x2));
  const __m128 zero = _mm_setzero_ps();
  // An edge function exactly 0: the scalar test retries in double; NaN (a NaN vertex, which no
  // box bounds): leave it to the scalar test too.
  if (_mm_movemask_ps(_mm_or_ps(_mm_cmpeq_ps(e, zero), _mm_cmpunord_ps(e, e))) & 7) return RejectVerdict::unsure;
  sheared[0] = x, sheared[1] = y, sheared[2] = z, sheared[3] = e;
  const int negative = _mm_movemask_ps(_mm_cmplt_ps(e, zero)) & 7;
  const int positive = _mm_movemask_ps(_mm_cmpgt_ps(e, zero)) & 7;
  return negative != 0 && positive != 0 ? RejectVerdict::missed : RejectVerdict::inside;
}

// True only if intersect_triangle(tri, ray, ...) surely returns false for any tmax.
template <int kX = -1, int kY = -1, int kZ = -1>
inline bool triangle_surely_missed(const Triangle& tri, const TriangleRejectRay& r) {
  __m128 sheared[4];
  return triangle_verdict<kX, kY, kZ>(tri, r, sheared) == RejectVerdict::missed;
}

#else

struct TriangleRejectRay {
  TriangleRejectRay() = default;
  explicit TriangleRejectRay(const Ray&) {}
  void assume_within(const Bounds3&) {}
};
template <int kX = -1, int kY = -1, int kZ = -1>
inline bool triangle_surely_missed(const Triangle&, const TriangleRejectRay&) { return false; }

#endif

}  // namespace gcsim::geometry
