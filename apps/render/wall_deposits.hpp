#pragma once
// The light the media scatter onto the walls, as the radiosity pass receives it. The photon pass
// (volume_photons.hpp) reports each flight that began at a scattering and ends on a diffuse
// surface (WallHit): the paths ...M->W, which radiosity's W->W transport through the media
// (PathTransmittance) does not contain, so nothing is counted twice. Each such hit finds the
// radiosity element it meets (a ray through a tree of the elements, its box and triangle tests
// charged) and adds its RGB power there in fixed point: integer sums add exactly, so the all-reduce
// over the nodes gives the same bits on any node count and in any order. The sums become radiosity's
// SolverOptions::received: each element reflects rho of them and the solve carries that on (W->W).
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "apps/common/geometry/bvh.hpp"
#include "apps/common/geometry/primitive_arrays.hpp"
#include "apps/common/geometry/primitive_intersection.hpp"
#include "apps/common/scene/scene_description.hpp"
#include "apps/radiosity/radiosity.hpp"
#include "parix/processor.hpp"

namespace gcsim::render {

// The radiosity elements as a photon's ray meets them: each element fanned into triangles, an
// element and the one on the same corners facing the other way (a polygon's back) sharing them.
// Elements of mirror or glass surfaces are left out (photons do not deposit on them).
class ElementLookup {
 public:
  ElementLookup(const radiosity::Scene& mesh, const scene::SceneDescription& description);
  // The element whose front the ray origin + t direction (unit) meets first, or -1 (none, or the
  // back of a one-sided polygon). tally: the box and triangle tests made.
  int find(const glm::dvec3& origin, const glm::dvec3& direction, geometry::TestTally& tally) const;
  std::size_t element_count() const { return elements_; }

 private:
  std::size_t elements_ = 0;
  geometry::PrimitiveArrays triangles_;
  geometry::Bvh bvh_;
  std::vector<int> front_, back_;  // per triangle: the element on the side its normal faces, the other side's (-1: none)
};

// One node's deposits, per element and channel, in units of `quantum` watts (of the scene's units).
struct DepositSums {
  double quantum = 0.0;
  std::vector<std::int64_t> units;  // 3 per element
  std::uint64_t deposits = 0;       // hits that found an element
  std::uint64_t missed = 0;         // hits that found none (the tessellation missed, a polygon's bare back)

  DepositSums(std::size_t elements, double photon_power);
  // Throws std::overflow_error if one deposit exceeds the fixed-point range.
  void add(int element, const glm::dvec3& power);
  std::vector<radiosity::Rgb> power() const;  // per element, watts per channel
};

// Every node's sums added (an all-reduce; each merge of one node's sums into another's charged
// `deposit_merge` per element): identical on every node.
DepositSums all_reduce(parix::Processor& p, DepositSums mine);

}  // namespace gcsim::render
