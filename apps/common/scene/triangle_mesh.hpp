#pragma once
// A triangle mesh of the scene description, in double precision: positions and index triples.
// Each renderer lowers it to its own primitives (the ray tracer to float triangles).
#include <array>
#include <vector>

#include <glm/glm.hpp>

namespace gcsim::scene {

struct TriangleMesh {
  std::vector<glm::dvec3> positions;
  std::vector<std::array<int, 3>> triangles;  // indices into positions
};

}  // namespace gcsim::scene
