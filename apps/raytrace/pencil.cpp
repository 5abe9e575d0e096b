#include "apps/raytrace/pencil.hpp"

#include <algorithm>
#include <cmath>

namespace gcsim::raytrace {

std::optional<Pencil> make_pencil(const std::array<Ray, 4>& rays) {
  Pencil p;
  glm::vec3 mean(0.0f);
  for (const Ray& r : rays) mean += glm::normalize(r.direction);
  if (glm::length(mean) < 1e-6f) return std::nullopt;
  p.axis = glm::normalize(mean);
  // x along the spread between the first two corners, made perpendicular to the axis.
  glm::vec3 x = rays[1].direction - rays[0].direction;
  x -= glm::dot(x, p.axis) * p.axis;
  if (glm::length(x) < 1e-9f) x = glm::cross(p.axis, std::abs(p.axis.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0));
  p.x_axis = glm::normalize(x);
  p.y_axis = glm::cross(p.axis, p.x_axis);
  // Origin: the start point nearest along the axis is at z = 0.
  int nearest = 0;
  for (int i = 1; i < 4; ++i)
    if (glm::dot(p.axis, rays[i].origin) < glm::dot(p.axis, rays[nearest].origin)) nearest = i;
  p.origin = rays[nearest].origin;
  p.rx_min = p.ry_min = kInfinity;
  p.rx_max = p.ry_max = -kInfinity;
  for (const Ray& r : rays) {
    const glm::vec3 o = r.origin - p.origin;
    const float dz = glm::dot(p.axis, r.direction);
    if (dz <= 1e-3f) return std::nullopt;
    const float sx = glm::dot(p.x_axis, r.direction) / dz, sy = glm::dot(p.y_axis, r.direction) / dz;
    const float z = glm::dot(p.axis, o);
    const float rx = glm::dot(p.x_axis, o) - sx * z, ry = glm::dot(p.y_axis, o) - sy * z;  // at z = 0
    p.rx_min = std::min(p.rx_min, rx);
    p.rx_max = std::max(p.rx_max, rx);
    p.ry_min = std::min(p.ry_min, ry);
    p.ry_max = std::max(p.ry_max, ry);
    p.sx_max = std::max(p.sx_max, std::abs(sx));
    p.sy_max = std::max(p.sy_max, std::abs(sy));
  }
  return p;
}

std::array<Plane, 4> Pencil::planes() const {
  // n . (q - origin) >= c  becomes  n . q >= c + n . origin.
  auto plane = [&](glm::vec3 n, float c) { return Plane{n, c + glm::dot(n, origin)}; };
  return {plane(x_axis + sx_max * axis, rx_min), plane(-(x_axis - sx_max * axis), -rx_max),
          plane(y_axis + sy_max * axis, ry_min), plane(-(y_axis - sy_max * axis), -ry_max)};
}

bool Pencil::contains(const Ray& ray) const {
  const float dz = glm::dot(axis, ray.direction);
  if (dz <= 0.0f) return false;
  const glm::vec3 o = ray.origin - origin;
  const float z = glm::dot(axis, o), x = glm::dot(x_axis, o), y = glm::dot(y_axis, o);
  const float sx = glm::dot(x_axis, ray.direction) / dz, sy = glm::dot(y_axis, ray.direction) / dz;
  // A small relative margin keeps rounding from admitting a ray that grazes a plane.
  const float m = 1e-4f * (1.0f + std::abs(x) + std::abs(y) + std::abs(z) + std::abs(rx_min) + std::abs(rx_max) +
                           std::abs(ry_min) + std::abs(ry_max));
  const float ms = 1e-4f * (1.0f + sx_max + sy_max);
  return x + sx_max * z >= rx_min + m && x - sx_max * z <= rx_max - m && y + sy_max * z >= ry_min + m &&
         y - sy_max * z <= ry_max - m && std::abs(sx) <= sx_max - ms && std::abs(sy) <= sy_max - ms;
}

}  // namespace gcsim::raytrace
