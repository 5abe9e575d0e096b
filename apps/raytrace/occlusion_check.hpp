#pragma once
// The occlusion half of A4's uniformity test (section 2.2.3): can anything in a subregion's
// subtree be hit nearer than primitive P by a ray of a pixel region whose corner rays all hit P?
// What depends only on the camera and on P (the planes through pixel centres, the plane behind
// which P hides everything, how far a sphere's visible side can be) is worked out once per
// tracer, where the test used to work it out again for every region.
#include <cstdint>
#include <vector>

#include "apps/raytrace/camera.hpp"
#include "apps/raytrace/geometry_names.hpp"
#include "apps/raytrace/plane_classification4.hpp"
#include "apps/raytrace/scene.hpp"
#include "apps/raytrace/subtree.hpp"

namespace gcsim::raytrace {

class OcclusionCheck {
 public:
  OcclusionCheck(const Scene& scene, const Bvh& bvh, const Camera& camera);

  // An upper bound of the distance from the eye at which a ray meets sphere `prim`: the near side
  // is never farther than the centre (eye outside), or than the centre plus the radius (eye
  // inside); scaled up by 1e-5 for rounding.
  float sphere_distance_bound(int prim);

  // True if no primitive of `subtree` other than prim can be hit nearer than P by a ray through
  // the pixel centres of [rx0, rx1] x [ry0, ry1] (inclusive), P being nowhere farther from the
  // eye than max_distance. `checks` counts the boxes and primitives looked at.
  bool nothing_in_front(const Subtree& subtree, int prim, float max_distance, int rx0, int ry0, int rx1, int ry1,
                        std::int64_t& checks);

 private:
  // What P hides: everything wholly beyond `behind` (inside = the side away from the eye).
  struct Shade {
    Plane behind;
    glm::vec3 behind_abs{0.0f};
    bool has_behind = false;
    bool ready = false;
    float sphere_bound = 0.0f;
    // A triangle P's own plane in double, for triangle_behind (eye_side 0: P is a sphere).
    struct {
      glm::dvec3 p0{0.0}, normal{0.0};
      double eye_side = 0.0, scale = 0.0;
    } plane;
    bool has_plane() const { return plane.eye_side != 0.0; }
  };
  const Shade& shade_of(int prim);
  bool triangle_behind(const Shade& p, int q) const;

  const Scene& scene_;
  const Bvh& bvh_;
  glm::vec3 eye_;
  std::vector<Shade> shades_;  // per primitive, filled on first use
  // The camera's planes through pixel centres, x + 0.5 and y + 0.5, facing in and flipped.
  std::vector<PreparedPlane> columns_, flipped_columns_, rows_, flipped_rows_;
};

}  // namespace gcsim::raytrace
