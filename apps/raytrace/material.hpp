#pragma once
// Surface description for Whitted shading: diffuse colour (optionally a checkerboard), a Phong
// highlight, and the weights of the mirror and refracted rays.
#include <glm/glm.hpp>

namespace gcsim::raytrace {

struct Material {
  glm::vec3 diffuse{0.8f};
  glm::vec3 checker_other{-1.0f};  // second checker colour; negative: no checkerboard
  float checker_size = 1.0f;
  float specular = 0.0f;           // Phong highlight weight
  float shininess = 32.0f;
  float reflectance = 0.0f;        // mirror weight (for dielectrics the Fresnel term replaces it)
  float transmittance = 0.0f;      // > 0: a dielectric that refracts with index ior
  float ior = 1.5f;

  bool spawns_secondary() const { return reflectance > 0.0f || transmittance > 0.0f; }
};

struct PointLight {
  glm::vec3 position{0.0f};
  glm::vec3 intensity{1.0f};  // radiant intensity; falls off with the square of the distance
};

}  // namespace gcsim::raytrace
