#pragma once
// The Utah teapot as triangles: each of the 32 Bezier patches is evaluated on a 4 x 4 grid of
// parameters (3 x 3 quads, two triangles each), and the triangles that collapse where a patch
// edge shrinks to a point (the lid's knob, the bottom's centre) are dropped:
// 32 * 18 - 24 = 552 triangles, the count of the paper's photo 4.
#include <vector>

#include <glm/glm.hpp>

#include "apps/raytrace/scene.hpp"

namespace gcsim::raytrace {

struct TeapotMesh {
  std::vector<Triangle> triangles;
  std::vector<Scene::VertexNormals> normals;  // smooth normals, averaged over shared vertices
};

// The teapot in its own frame (z up, about 6.4 x 4 x 3.15 units), with `quads_per_side` quads
// per patch side (3 for the paper's 552 triangles).
TeapotMesh make_teapot(int quads_per_side = 3);

}  // namespace gcsim::raytrace
