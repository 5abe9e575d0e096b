#include "apps/raytrace/camera.hpp"

#include <algorithm>
#include <cmath>
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
// direction() and Ray::prepare() for four pixels, operation by operation in the same order (no
// contraction: the build has no FMA), so each lane rounds as the scalar code does.
void Camera::pixel_rays(const int* x, const int* y, int n, Ray* out) const {
  for (int first = 0; first < n; first += 4) {
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
    alignas(16) float dir[3][4], inv[3][4];
    for (int a = 0; a < 3; ++a) {
      const __m128 unit = _mm_mul_ps(d[a], scale);
      _mm_store_ps(dir[a], unit);
      _mm_store_ps(inv[a], _mm_div_ps(_mm_set1_ps(1.0f), unit));
    }
    for (int i = 0; i < m; ++i) {
      Ray& r = out[first + i];
      r.origin = eye_;
      r.direction = glm::vec3(dir[0][i], dir[1][i], dir[2][i]);
      r.tmin = 0.0f;
      r.inv_direction = glm::vec3(inv[0][i], inv[1][i], inv[2][i]);
      // The rest of Ray::prepare().
      const glm::vec3 abs_d = abs_components(r.direction);
      r.kz = abs_d.x > abs_d.y ? (abs_d.x > abs_d.z ? 0 : 2) : (abs_d.y > abs_d.z ? 1 : 2);
      r.kx = r.kz == 2 ? 0 : r.kz + 1;
      r.ky = r.kx == 2 ? 0 : r.kx + 1;
      if (r.direction[r.kz] < 0.0f) std::swap(r.kx, r.ky);
      r.shear_z = r.inv_direction[r.kz];
      r.shear_x = -r.direction[r.kx] * r.shear_z;
      r.shear_y = -r.direction[r.ky] * r.shear_z;
    }
  }
}
#else
void Camera::pixel_rays(const int* x, const int* y, int n, Ray* out) const {
  for (int i = 0; i < n; ++i) out[i] = pixel_ray(x[i], y[i]);
}
#endif

}  // namespace gcsim::raytrace
