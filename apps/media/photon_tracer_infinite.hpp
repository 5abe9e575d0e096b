#pragma once
// Photons from a point light in an infinite homogeneous medium (the analytic test case of the photon
// map, notes test 7): free flights by transmittance sampling, a photon stored at every interaction
// before Russian roulette [A4], survival with probability equal to the albedo (analog, equal powers).
#include <cstdint>
#include <vector>

#include "apps/common/media/medium.hpp"
#include "apps/common/media/photon_map.hpp"

namespace gcsim::media {

struct InfiniteMediumPhotons {
  std::vector<Photon> photons;
  std::uint64_t flights = 0;  // counted free-flight steps (the photon pass's cost)
};

// Emits `emitted` photons of power Φ/emitted; max_interactions = 1 keeps first collisions only.
InfiniteMediumPhotons trace_point_light_infinite(const HomogeneousMedium& medium, const glm::dvec3& light,
                                                 double power, std::size_t emitted, int max_interactions,
                                                 std::uint64_t seed);

}  // namespace gcsim::media
