#include "apps/raytrace/camera.hpp"

#include <cmath>
#include <stdexcept>

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

}  // namespace gcsim::raytrace
