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
  // Exitance the front side emits (an area light of a scene file), shown as it is: what radiosity
  // shows on an emitter that reflects nothing. Not sampled as a light.
  glm::vec3 emission{0.0f};
  // The surface's outgoing radiance is given per triangle vertex (Scene::triangle_radiance), as the
  // unified renderer's radiosity pass supplies it: no ambient term; point and spot lights add
  // their direct light with `diffuse` on the front and `back_diffuse` on the back.
  bool given_radiance = false;
  glm::vec3 back_diffuse{0.0f};

  bool spawns_secondary() const { return reflectance > 0.0f || transmittance > 0.0f; }
  bool operator==(const Material&) const = default;  // (memcmp would read the padding after the bool)
};

struct PointLight {
  glm::vec3 position{0.0f};
  glm::vec3 intensity{1.0f};  // radiant intensity; falls off with the square of the distance
  // A spot light lights only inside the cone of half-angle acos(spot_cos) about spot_direction
  // (unit); spot_cos = -1: a point light, every direction.
  glm::vec3 spot_direction{0.0f, -1.0f, 0.0f};
  float spot_cos = -1.0f;
  bool lights_direction(const glm::vec3& towards_point) const {
    return spot_cos <= -1.0f || glm::dot(towards_point, spot_direction) >= spot_cos;
  }
};

}  // namespace gcsim::raytrace
