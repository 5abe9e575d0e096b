#pragma once
// Which surfaces can exchange light, from geometry alone, conservatively: a one-sided polygon sees
// only what lies (partly) in front of its plane; spheres, boxes and meshes are treated as seeing every
// direction; only a mesh may see itself (it may be concave). No occlusion test: two surfaces facing
// each other are taken to exchange light. Used by the plan to tell direct light from interreflection.
#include <vector>

#include "apps/common/scene/scene_description.hpp"

namespace gcsim::render {

// One side of a shape that light can reach: a polygon's front, its back if it has a back material,
// or a whole closed shape. Invisible medium boundaries (index 1, nothing reflected) are left out.
struct SurfaceSide {
  int shape = 0;
  int material = 0;
  bool back = false;
};

std::vector<SurfaceSide> visible_sides(const scene::SceneDescription& d);

// Some point of side b lies strictly in front of side a (always true if a is not a polygon).
bool faces(const scene::SceneDescription& d, const SurfaceSide& a, const SurfaceSide& b);
// A point strictly in front of side a (always true if a is not a polygon).
bool faces_point(const scene::SceneDescription& d, const SurfaceSide& a, const glm::dvec3& p);
// Light can travel from a to b: they face each other (or a is a mesh seeing itself).
bool exchange(const scene::SceneDescription& d, const SurfaceSide& a, const SurfaceSide& b);

// The material only bounds a medium: nothing reflected, emitted or refracted at its surface.
bool invisible_boundary(const scene::Material& m);
// The material bounds a medium and does nothing else of its own (its index may refract).
bool only_bounds_medium(const scene::Material& m);

}  // namespace gcsim::render
