#pragma once
// A closed, outward-wound triangle mesh as the media object's boundary (the scanned model of the
// paper's experiments), through the shared float BVH and watertight triangle test of
// apps/common/geometry. The media code works in double: hits are found in float, then the hit
// distance is recomputed in double on the hit triangle's plane, and rays leave the surface from a
// point moved along the triangle's normal by more than the float tests' rounding can reach.
#include <filesystem>
#include <memory>

#include "apps/common/geometry/bvh.hpp"
#include "apps/common/geometry/primitive_arrays.hpp"
#include "apps/common/scene/triangle_mesh.hpp"
#include "apps/media/boundary.hpp"

namespace gcsim::media {

// Where the mesh goes: its bounding-box centre to `centre`, scaled so that its farthest vertex is
// `radius` from there (it fits the sphere it replaces), turned by `rotate_y_degrees` about the
// vertical axis (counter-clockwise seen from above) first.
struct MeshPlacement {
  glm::dvec3 centre{0.0};
  double radius = 1.0;
  double rotate_y_degrees = 0.0;
};

// The mesh moved and scaled to `placement` (in double; the boundary rounds it to float once).
scene::TriangleMesh place_mesh(const scene::TriangleMesh& mesh, const MeshPlacement& placement);

class MeshBoundary final : public Boundary {
 public:
  // The mesh as it is placed in the scene. Throws std::invalid_argument (naming `source`) unless it
  // is closed, consistently wound (every edge used once in each direction) and wound outwards
  // (positive signed volume).
  MeshBoundary(const scene::TriangleMesh& mesh, const std::string& source);

  std::optional<BoundaryHit> intersect(const glm::dvec3& o, const glm::dvec3& d, double t_min, double t_max,
                                       BoundaryTally* tally = nullptr) const override;
  // The majority of three rays in fixed directions: inside when the nearest hit along the ray leaves
  // the mesh (the same geometric normal intersect uses for `entering`), so a ray along an edge or
  // through a vertex cannot change the answer.
  bool inside(const glm::dvec3& p, BoundaryTally* tally = nullptr) const override;
  glm::dvec3 leave_surface(const glm::dvec3& at, const BoundaryHit& hit, const glm::dvec3& direction) const override;

  const geometry::PrimitiveArrays& primitives() const { return prims_; }  // placed, float
  double surface_offset() const { return offset_; }

 private:
  geometry::PrimitiveArrays prims_;
  geometry::Bvh bvh_;
  double offset_ = 0.0;  // how far leave_surface moves a point off the surface
};

// Loads an OBJ file (apps/common/scene/obj_mesh.hpp) and places it; errors name the file.
std::shared_ptr<MeshBoundary> load_mesh_boundary(const std::filesystem::path& file, const MeshPlacement& placement);

}  // namespace gcsim::media
