#include "apps/raytrace/camera.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <utility>
#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace gcsim::raytrace {

Camera::Camera(const scene::Camera& spec, int width, int height)
    : width_(width), height_(height), eye_(glm::vec3(spec.eye)) {
  if (width <= 0 || height <= 0) throw std::invalid_argument("image size must be positive");
  const glm::vec3 look_at(spec.look_at), up(spec.up);
  const float fov_y_degrees = static_cast<float>(spec.fov_y_degrees);
  glm::vec3 f = look_at - eye_;
  if (glm::length(f) == 0) throw std::invalid_argument("camera eye and look_at coincide");
  forward_ = glm::normalize(f);
  glm::vec3 r = glm::cross(forward_, up);
  if (glm::length(r) < 1e-6f) r = glm::cross(forward_, std::abs(forward_.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0));
  right_ = glm::normalize(r);
  up_ = glm::cross(right_, forward_);
  half_h_ = std::tan(glm::radians(fov_y_degrees) * 0.5f);
  half_w_ = half_h_ * float(width) / float(height);
  two_over_width_ = 2.0f / float(width);
  two_over_height_ = 2.0f / float(height);
}

// For a direction forward + u right + v up, (right - u_k forward) . d = u - u_k: positive right of
// the boundary. Likewise (v_j forward - up) . d = v_j - v: positive below row boundary j.
Plane Camera::column_plane_at(float k) const {
  const float uk = (k * two_over_width_ - 1.0f) * half_w_;
  const glm::vec3 n = right_ - uk * forward_;
  return {n, glm::dot(n, eye_)};
}

Plane Camera::row_plane_at(float j) const {
  const float vj = (1.0f - j * two_over_height_) * half_h_;
  const glm::vec3 n = vj * forward_ - up_;
  return {n, glm::dot(n, eye_)};
}

#if defined(__SSE2__)
namespace {

// The rest of Ray::prepare() for four rays, lane by lane, and the rays written whole: the
// dominant axis kz (the first of the largest |component|s, as prepare's comparisons pick it), kx
// and ky after it, swapped where the direction runs down kz, and the shear (-d[kx] * inv[kz] is
// prepare's -direction[kx] * shear_z: the same two exact or rounded steps). A Ray is sixteen
// 4-byte fields, so four 4 x 4 transposes lay four rays out as four 16-byte stores each, where
// the per-ray code made sixteen scalar stores and three data-dependent branches.
void store_rays(glm::vec3 eye, const __m128 unit[3], const __m128 inv[3], int m, Ray* out) {
  static_assert(sizeof(Ray) == 16 * sizeof(float) && offsetof(Ray, inv_direction) == 7 * sizeof(float) &&
                offsetof(Ray, kx) == 10 * sizeof(float) && offsetof(Ray, shear_x) == 13 * sizeof(float));
  const auto select = [](__m128 mask, __m128 a, __m128 b) { return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b)); };
  const auto ints = [](int v) { return _mm_castsi128_ps(_mm_set1_epi32(v)); };
  const __m128 sign = _mm_set1_ps(-0.0f);
  const __m128 ax = _mm_andnot_ps(sign, unit[0]), ay = _mm_andnot_ps(sign, unit[1]), az = _mm_andnot_ps(sign, unit[2]);
  const __m128 x_over_y = _mm_cmpgt_ps(ax, ay);
  const __m128 kz0 = _mm_and_ps(x_over_y, _mm_cmpgt_ps(ax, az));
  const __m128 kz1 = _mm_andnot_ps(x_over_y, _mm_cmpgt_ps(ay, az));
  // Per lane by kz = 0, 1, 2: d[kz], inv[kz], and d, kx, ky before the swap ((1, 2), (2, 0), (0, 1)).
  const auto by_kz = [&](__m128 if0, __m128 if1, __m128 if2) { return select(kz0, if0, select(kz1, if1, if2)); };
  const __m128 d_kz = by_kz(unit[0], unit[1], unit[2]);
  const __m128 shear_z = by_kz(inv[0], inv[1], inv[2]);
  __m128 d_kx = by_kz(unit[1], unit[2], unit[0]), d_ky = by_kz(unit[2], unit[0], unit[1]);
  __m128 kx = by_kz(ints(1), ints(2), ints(0)), ky = by_kz(ints(2), ints(0), ints(1));
  const __m128 kz = by_kz(ints(0), ints(1), ints(2));
  const __m128 down = _mm_cmplt_ps(d_kz, _mm_setzero_ps());
  const __m128 swapped_x = select(down, d_ky, d_kx), swapped_kx = select(down, ky, kx);
  d_ky = select(down, d_kx, d_ky), ky = select(down, kx, ky);
  d_kx = swapped_x, kx = swapped_kx;
  const __m128 shear_x = _mm_mul_ps(_mm_xor_ps(d_kx, sign), shear_z);
  const __m128 shear_y = _mm_mul_ps(_mm_xor_ps(d_ky, sign), shear_z);
  // Fields 0-15 of the four rays, four at a time.
  __m128 f[16] = {_mm_set1_ps(eye.x), _mm_set1_ps(eye.y), _mm_set1_ps(eye.z), unit[0], unit[1], unit[2],
                  _mm_setzero_ps(), inv[0], inv[1], inv[2], kx, ky, kz, shear_x, shear_y, shear_z};
  for (int q = 0; q < 4; ++q) {
    _MM_TRANSPOSE4_PS(f[4 * q], f[4 * q + 1], f[4 * q + 2], f[4 * q + 3]);
    for (int i = 0; i < m; ++i) _mm_storeu_ps(reinterpret_cast<float*>(&out[i]) + 4 * q, f[4 * q + i]);
  }
}

}  // namespace

// direction() and Ray::prepare() for four pixels, operation by operation in the same order (no
// contraction: the build has no FMA), so each lane rounds as the scalar code does.
void Camera::pixel_rays(const int* x, const int* y, int n, Ray* out) const {
  int first = 0;
#if defined(__AVX__)
  // Eight at a time where there are eight: one square root and four divisions for eight rays, the
  // same operations lane by lane, so the same rays.
  for (; first + 8 <= n; first += 8) {
    const int* xs = x + first;
    const int* ys = y + first;
    const __m256 sx = _mm256_add_ps(_mm256_setr_ps(float(xs[0]), float(xs[1]), float(xs[2]), float(xs[3]), float(xs[4]),
                                                   float(xs[5]), float(xs[6]), float(xs[7])),
                                    _mm256_set1_ps(0.5f));
    const __m256 sy = _mm256_add_ps(_mm256_setr_ps(float(ys[0]), float(ys[1]), float(ys[2]), float(ys[3]), float(ys[4]),
                                                   float(ys[5]), float(ys[6]), float(ys[7])),
                                    _mm256_set1_ps(0.5f));
    const __m256 u = _mm256_mul_ps(_mm256_sub_ps(_mm256_mul_ps(sx, _mm256_set1_ps(two_over_width_)), _mm256_set1_ps(1.0f)),
                                   _mm256_set1_ps(half_w_));
    const __m256 v = _mm256_mul_ps(_mm256_sub_ps(_mm256_set1_ps(1.0f), _mm256_mul_ps(sy, _mm256_set1_ps(two_over_height_))),
                                   _mm256_set1_ps(half_h_));
    __m256 d[3];
    for (int a = 0; a < 3; ++a)
      d[a] = _mm256_add_ps(_mm256_add_ps(_mm256_set1_ps(forward_[a]), _mm256_mul_ps(u, _mm256_set1_ps(right_[a]))),
                           _mm256_mul_ps(v, _mm256_set1_ps(up_[a])));
    const __m256 len2 =
        _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(d[0], d[0]), _mm256_mul_ps(d[1], d[1])), _mm256_mul_ps(d[2], d[2]));
    const __m256 scale = _mm256_div_ps(_mm256_set1_ps(1.0f), _mm256_sqrt_ps(len2));
    __m128 unit[2][3], inv[2][3];
    for (int a = 0; a < 3; ++a) {
      const __m256 ua = _mm256_mul_ps(d[a], scale);
      const __m256 ia = _mm256_div_ps(_mm256_set1_ps(1.0f), ua);
      unit[0][a] = _mm256_castps256_ps128(ua), unit[1][a] = _mm256_extractf128_ps(ua, 1);
      inv[0][a] = _mm256_castps256_ps128(ia), inv[1][a] = _mm256_extractf128_ps(ia, 1);
    }
    store_rays(eye_, unit[0], inv[0], 4, out + first);
    store_rays(eye_, unit[1], inv[1], 4, out + first + 4);
  }
#endif
  for (; first < n; first += 4) {
    const int m = std::min(4, n - first);
    // Set from registers, not stored and reloaded: a vector load of four scalar stores stalls.
    float xf[4] = {}, yf[4] = {};
    for (int i = 0; i < m; ++i) xf[i] = float(x[first + i]), yf[i] = float(y[first + i]);
    const __m128 sx = _mm_add_ps(_mm_setr_ps(xf[0], xf[1], xf[2], xf[3]), _mm_set1_ps(0.5f));
    const __m128 sy = _mm_add_ps(_mm_setr_ps(yf[0], yf[1], yf[2], yf[3]), _mm_set1_ps(0.5f));
    const __m128 u = _mm_mul_ps(_mm_sub_ps(_mm_mul_ps(sx, _mm_set1_ps(two_over_width_)), _mm_set1_ps(1.0f)), _mm_set1_ps(half_w_));
    const __m128 v = _mm_mul_ps(_mm_sub_ps(_mm_set1_ps(1.0f), _mm_mul_ps(sy, _mm_set1_ps(two_over_height_))), _mm_set1_ps(half_h_));
    __m128 d[3];
    for (int a = 0; a < 3; ++a)
      d[a] = _mm_add_ps(_mm_add_ps(_mm_set1_ps(forward_[a]), _mm_mul_ps(u, _mm_set1_ps(right_[a]))),
                        _mm_mul_ps(v, _mm_set1_ps(up_[a])));
    const __m128 len2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(d[0], d[0]), _mm_mul_ps(d[1], d[1])), _mm_mul_ps(d[2], d[2]));
    const __m128 scale = _mm_div_ps(_mm_set1_ps(1.0f), _mm_sqrt_ps(len2));
    __m128 unit[3], inv[3];
    for (int a = 0; a < 3; ++a) {
      unit[a] = _mm_mul_ps(d[a], scale);
      inv[a] = _mm_div_ps(_mm_set1_ps(1.0f), unit[a]);
    }
    store_rays(eye_, unit, inv, m, out + first);
  }
}

#else
void Camera::pixel_rays(const int* x, const int* y, int n, Ray* out) const {
  for (int i = 0; i < n; ++i) out[i] = pixel_ray(x[i], y[i]);
}
#endif

}  // namespace gcsim::raytrace
