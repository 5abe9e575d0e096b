#pragma once
// classify() of one box against four planes at once (the uniformity test's region pyramid, or a
// subtree's two planes twice over): the
// same float operations in the same order per plane, one plane per SSE lane, so the answer
// "outside one of them" is exactly that of four scalar classify() calls.
#include <array>

#include "apps/raytrace/plane_classification.hpp"

#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace gcsim::raytrace {

// A plane with the absolute values classify() reads, laid out as one lane of FourPlanes:
// prepared once for a plane that many regions use (the camera's planes through pixel centres).
struct PreparedPlane {
  Plane plane;
  glm::vec3 abs_normal{0.0f};
  float abs_offset = 0.0f;
  PreparedPlane() = default;
  explicit PreparedPlane(const Plane& p)
      : plane(p), abs_normal(abs_components(p.normal)), abs_offset(std::abs(p.offset)) {}
};

#if defined(__SSE2__)

// Two boxes as FourPlanes::sides reads them, box a in lanes 0 and 1, box b in lanes 2 and 3:
// two children against a subtree's two planes (FourPlanes of c, d, c, d) in one pass.
// |centre| is not kept: clearing the sign bits gives it exactly, and a row's lanes stay a third
// smaller in the cache.
struct BoxLanes {
  __m128 centre[3], half[3];
  BoxLanes(const BoxCentre& a, const BoxCentre& b) {
    for (int k = 0; k < 3; ++k) {
      centre[k] = _mm_setr_ps(a.centre[k], a.centre[k], b.centre[k], b.centre[k]);
      half[k] = _mm_setr_ps(a.half[k], a.half[k], b.half[k], b.half[k]);
    }
  }
};

class FourPlanes {
 public:
  // The same lanes as from the four planes themselves, by two 4 x 4 transposes.
  explicit FourPlanes(const std::array<const PreparedPlane*, 4>& p) {
    static_assert(sizeof(PreparedPlane) == 8 * sizeof(float));
    __m128 a[4], b[4];
    for (int i = 0; i < 4; ++i) {
      a[i] = _mm_loadu_ps(&p[i]->plane.normal.x);
      b[i] = _mm_loadu_ps(&p[i]->abs_normal.x);
    }
    _MM_TRANSPOSE4_PS(a[0], a[1], a[2], a[3]);
    _MM_TRANSPOSE4_PS(b[0], b[1], b[2], b[3]);
    for (int k = 0; k < 4; ++k) lanes_[k] = a[k], lanes_[4 + k] = b[k];
  }
  explicit FourPlanes(const std::array<Plane, 4>& p) {
    alignas(16) float v[8][4];
    for (int i = 0; i < 4; ++i) {
      const glm::vec3 a = abs_components(p[i].normal);
      const float f[8] = {p[i].normal.x, p[i].normal.y, p[i].normal.z, p[i].offset, a.x, a.y, a.z, std::abs(p[i].offset)};
      for (int k = 0; k < 8; ++k) v[k][i] = f[k];
    }
    for (int k = 0; k < 8; ++k) lanes_[k] = _mm_load_ps(v[k]);
  }

  // True if classify(b, plane) == Side::outside for one of the four planes.
  bool any_outside(const BoxCentre& b) const {
    unsigned inside, outside;
    sides(b, inside, outside);
    return outside != 0;
  }

  // Bit i set where classify(b, plane i) is Side::inside, resp. Side::outside (neither: crossing).
  void sides(const BoxCentre& b, unsigned& inside_bits, unsigned& outside_bits) const {
    const auto dot = [](__m128 x, __m128 y, __m128 z, glm::vec3 v) {  // (x v.x + y v.y) + z v.z, as glm::dot
      return _mm_add_ps(_mm_add_ps(_mm_mul_ps(x, _mm_set1_ps(v.x)), _mm_mul_ps(y, _mm_set1_ps(v.y))),
                        _mm_mul_ps(z, _mm_set1_ps(v.z)));
    };
    const __m128 s = _mm_sub_ps(dot(lanes_[0], lanes_[1], lanes_[2], b.centre), lanes_[3]);
    const __m128 r = dot(lanes_[4], lanes_[5], lanes_[6], b.half);
    finish(s, r, dot(lanes_[4], lanes_[5], lanes_[6], b.abs_centre), inside_bits, outside_bits);
  }

  // The same with box lane i against plane i: the same operations, lane by lane.
  void sides(const BoxLanes& b, unsigned& inside_bits, unsigned& outside_bits) const {
    const auto dot = [](__m128 x, __m128 y, __m128 z, const __m128 v[3]) {
      return _mm_add_ps(_mm_add_ps(_mm_mul_ps(x, v[0]), _mm_mul_ps(y, v[1])), _mm_mul_ps(z, v[2]));
    };
    const __m128 s = _mm_sub_ps(dot(lanes_[0], lanes_[1], lanes_[2], b.centre), lanes_[3]);
    const __m128 r = dot(lanes_[4], lanes_[5], lanes_[6], b.half);
    const __m128 sign = _mm_set1_ps(-0.0f);
    const __m128 abs_centre[3] = {_mm_andnot_ps(sign, b.centre[0]), _mm_andnot_ps(sign, b.centre[1]),
                                  _mm_andnot_ps(sign, b.centre[2])};
    finish(s, r, dot(lanes_[4], lanes_[5], lanes_[6], abs_centre), inside_bits, outside_bits);
  }

 private:
  // classify()'s comparisons from s = n . c - offset, r = |n| . half and |n| . |c|.
  void finish(__m128 s, __m128 r, __m128 abs_dot, unsigned& inside_bits, unsigned& outside_bits) const {
    const __m128 inside = _mm_cmpgt_ps(_mm_sub_ps(s, r), _mm_setzero_ps());
    const __m128 sum = _mm_add_ps(_mm_add_ps(lanes_[7], abs_dot), r);
    const __m128 margin = _mm_mul_ps(_mm_set1_ps(1e-5f), sum);
    const __m128 outside = _mm_cmplt_ps(_mm_add_ps(s, r), _mm_xor_ps(margin, _mm_set1_ps(-0.0f)));
    inside_bits = unsigned(_mm_movemask_ps(inside));
    outside_bits = unsigned(_mm_movemask_ps(_mm_andnot_ps(inside, outside)));
  }

  __m128 lanes_[8];  // normal x, y, z, offset, |normal| x, y, z, |offset|
};

#else

struct BoxLanes {
  BoxCentre box[4];
  BoxLanes(const BoxCentre& a, const BoxCentre& b) : box{a, a, b, b} {}
};

class FourPlanes {
 public:
  explicit FourPlanes(const std::array<const PreparedPlane*, 4>& p)
      : planes_{p[0]->plane, p[1]->plane, p[2]->plane, p[3]->plane} {}
  explicit FourPlanes(const std::array<Plane, 4>& p) : planes_(p) {}
  bool any_outside(const BoxCentre& b) const {
    for (const Plane& pl : planes_)
      if (classify(b, pl, abs_components(pl.normal)) == Side::outside) return true;
    return false;
  }
  void sides(const BoxCentre& b, unsigned& inside_bits, unsigned& outside_bits) const {
    inside_bits = outside_bits = 0;
    for (int i = 0; i < 4; ++i) {
      const Side s = classify(b, planes_[i], abs_components(planes_[i].normal));
      inside_bits |= unsigned(s == Side::inside) << i;
      outside_bits |= unsigned(s == Side::outside) << i;
    }
  }
  void sides(const BoxLanes& b, unsigned& inside_bits, unsigned& outside_bits) const {
    inside_bits = outside_bits = 0;
    for (int i = 0; i < 4; ++i) {
      const Side s = classify(b.box[i], planes_[i], abs_components(planes_[i].normal));
      inside_bits |= unsigned(s == Side::inside) << i;
      outside_bits |= unsigned(s == Side::outside) << i;
    }
  }

 private:
  std::array<Plane, 4> planes_;
};

#endif

}  // namespace gcsim::raytrace
