#pragma once
// A scene: spheres and triangles with one id space (spheres first), a material per primitive,
// point lights and the camera that frames it.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "apps/raytrace/bounds.hpp"
#include "apps/raytrace/material.hpp"
#include "apps/raytrace/sphere.hpp"
#include "apps/raytrace/triangle.hpp"

namespace gcsim::raytrace {

struct CameraSpec {
  glm::vec3 eye{0.0f, 0.0f, 5.0f};
  glm::vec3 look_at{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_degrees = 40.0f;  // vertical field of view
};

// Where a ray hit, what is needed to shade and spawn secondary rays.
struct SurfacePoint {
  glm::vec3 position{0.0f};
  glm::vec3 position_error{0.0f};  // bound on the rounding error of position, per axis
  glm::vec3 geometric_normal{0.0f};  // unit, facing the side the ray came from
  glm::vec3 shading_normal{0.0f};    // unit, same side as geometric_normal
  bool entering = true;              // the ray hit the front (outward) side
};

class Scene {
 public:
  std::string name;
  std::vector<Sphere> spheres;
  std::vector<Triangle> triangles;
  // Optional per-vertex normals of triangles (for smooth shading); empty or one per triangle.
  struct VertexNormals { glm::vec3 n0, n1, n2; };
  std::vector<VertexNormals> triangle_normals;
  std::vector<Material> materials;
  std::vector<std::uint16_t> prim_material;  // per primitive id
  std::vector<PointLight> lights;
  glm::vec3 background{0.05f, 0.06f, 0.09f};
  glm::vec3 ambient{0.12f};
  CameraSpec camera;

  int sphere_count() const { return static_cast<int>(spheres.size()); }
  int prim_count() const { return static_cast<int>(spheres.size() + triangles.size()); }
  bool is_sphere(int prim) const { return prim < sphere_count(); }
  const Triangle& triangle(int prim) const { return triangles[prim - sphere_count()]; }
  const Material& material_of(int prim) const { return materials[prim_material[prim]]; }
  bool has_secondary_effects() const;

  Bounds3 prim_bounds(int prim) const {
    return is_sphere(prim) ? spheres[prim].bounds() : triangle(prim).bounds();
  }
  Bounds3 bounds() const;

  // Adds primitives with a material (returns the material's index).
  int add_material(const Material& m);
  void add_sphere(const Sphere& s, int material);
  void add_triangle(const Triangle& t, int material);
  void add_triangle(const Triangle& t, const VertexNormals& n, int material);

  // The geometry at a hit (prim, t, barycentrics) of ray.
  SurfacePoint surface_point(const Ray& ray, int prim, float t, float b1, float b2) const;

  // Throws std::invalid_argument naming what is wrong (no primitives, NaN coordinates, ...).
  void validate() const;
};

}  // namespace gcsim::raytrace
