#pragma once
// Pinhole camera. Pixel (x, y) has its centre at image coordinates (x + 0.5, y + 0.5), y down.
// Primary rays start at the eye with unit directions, so their t is the distance from the eye:
// the uniformity test and ray classification compare it with box distances.
#include <cmath>

#include <glm/glm.hpp>

#include "apps/common/geometry/ray.hpp"
#include "apps/raytrace/geometry_names.hpp"
#include "apps/raytrace/scene.hpp"

namespace gcsim::raytrace {

// A plane through the eye, n . (p - eye) >= 0 on the inside.
struct Plane {
  glm::vec3 normal{0.0f};
  float offset = 0.0f;  // n . p >= offset inside
  float signed_distance(glm::vec3 p) const { return glm::dot(normal, p) - offset; }
};

class Camera {
 public:
  // The scene's camera, its eye, look_at, up and field of view rounded to float: every ray
  // computation below is in float.
  Camera(const scene::Camera& spec, int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  glm::vec3 eye() const { return eye_; }

  // Unit direction through image point (sx, sy) (pixel units, y down).
  glm::vec3 direction(float sx, float sy) const {
    const float u = (sx * two_over_width_ - 1.0f) * half_w_;
    const float v = (1.0f - sy * two_over_height_) * half_h_;
    const glm::vec3 d = forward_ + u * right_ + v * up_;
    return d * (1.0f / std::sqrt(glm::dot(d, d)));
  }
  Ray pixel_ray(int x, int y) const { return Ray(eye_, direction(x + 0.5f, y + 0.5f)); }
  // out[i] = pixel_ray(x[i], y[i]) for i < n, bit for bit, eight or four at a time (packets: the square
  // root and divisions of one ray alone are a long chain of latency).
  void pixel_rays(const int* x, const int* y, int n, Ray* out) const;

  // The planes through the eye along pixel boundaries (section 2.2.1): the column boundary
  // x = k with the inside to the right (larger x), and the row boundary y = j with the inside
  // below (larger y). Flip the sign for the other side.
  Plane column_plane(int k) const { return column_plane_at(float(k)); }
  Plane row_plane(int j) const { return row_plane_at(float(j)); }
  // The same through any image coordinate (e.g. pixel centres, x + 0.5).
  Plane column_plane_at(float sx) const;
  Plane row_plane_at(float sy) const;

 private:
  int width_, height_;
  glm::vec3 eye_, forward_, right_, up_;
  float half_w_, half_h_;
  float two_over_width_, two_over_height_;  // multiplications instead of two divisions per ray
};

}  // namespace gcsim::raytrace
