#include "apps/media/photon_tracer_infinite.hpp"

#include <cmath>

#include "apps/common/rng.hpp"
#include "apps/common/media/sampling.hpp"

namespace gcsim::media {

InfiniteMediumPhotons trace_point_light_infinite(const HomogeneousMedium& medium, const glm::dvec3& light,
                                                 double power, std::size_t emitted, int max_interactions,
                                                 std::uint64_t seed) {
  InfiniteMediumPhotons out;
  apps::Rng rng(seed, 0x6d65646961ULL);
  const auto photon_power = static_cast<float>(power / static_cast<double>(emitted));
  for (std::size_t i = 0; i < emitted; ++i) {
    glm::dvec3 x = light;
    glm::dvec3 w = uniform_sphere(rng.uniform_double(), rng.uniform_double());
    for (int bounce = 0; bounce < max_interactions; ++bounce) {
      const double distance = -std::log1p(-rng.uniform_double()) / medium.sigma_t;
      x += distance * w;
      ++out.flights;
      out.photons.push_back({glm::vec3(x), glm::vec3(w), photon_power});
      if (rng.uniform_double() >= medium.albedo()) break;  // absorbed
      w = direction_around(w, medium.phase.sample_cos(rng.uniform_double()), rng.uniform_double());
    }
  }
  return out;
}

}  // namespace gcsim::media
