#pragma once
// A scene: spheres and triangles with one id space (spheres first), a material per primitive,
// point lights and the camera that frames it (the scene layer's one camera type).
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "apps/common/geometry/bounds.hpp"
#include "apps/common/scene/camera.hpp"
#include "apps/raytrace/material.hpp"
#include "apps/common/geometry/sphere.hpp"
#include "apps/common/geometry/triangle.hpp"
#include "apps/common/geometry/primitive_arrays.hpp"
#include "apps/common/geometry/surface_point.hpp"
#include "apps/raytrace/geometry_names.hpp"

namespace gcsim::raytrace {

class Scene : public PrimitiveArrays {
 public:
  std::string name;
  // Optional per-vertex normals of triangles (for smooth shading); empty or one per triangle.
  struct VertexNormals { glm::vec3 n0, n1, n2; };
  std::vector<VertexNormals> triangle_normals;
  // Per-vertex outgoing radiance of triangles whose material has given_radiance (displayed colour,
  // linear), on the side the geometric normal faces and on the back: empty, or one per triangle.
  // Interpolated with the hit's barycentrics.
  struct VertexRadiance { glm::vec3 r0, r1, r2; };
  struct GivenRadiance { VertexRadiance front, back; };
  std::vector<GivenRadiance> triangle_radiance;
  std::vector<Material> materials;
  std::vector<std::uint16_t> prim_material;  // per primitive id
  std::vector<PointLight> lights;
  glm::vec3 background{0.05f, 0.06f, 0.09f};
  glm::vec3 ambient{0.12f};
  scene::Camera camera;  // the shared camera; raytrace::Camera converts it to float

  const Material& material_of(int prim) const { return materials[prim_material[prim]]; }
  // The given radiance at barycentrics (b1, b2) of triangle primitive prim, on the side ray comes from.
  glm::vec3 given_radiance(const Ray& ray, int prim, float b1, float b2) const;
  bool has_secondary_effects() const;

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
