#include "apps/render/view_medium.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "apps/common/media/radiance_grid.hpp"
#include "apps/render/volume_photons.hpp"

namespace gcsim::render {

struct ViewMedium::Region {
  media::HomogeneousMedium lum;      // what the photon map and the march read
  glm::dvec3 sigma_t_rgb{0.0};       // the transmittance's, per channel
  glm::dvec3 in_scatter_colour{0.0}; // displayed colour per unit of in-scattered luminance
  std::unique_ptr<media::PhotonMap> map;
  std::unique_ptr<media::RadianceGrid> grid;
};

ViewMedium::ViewMedium(std::vector<MediumRegion> regions, std::vector<std::vector<media::Photon>> photons,
                       ViewMediumSettings s)
    : bounds_(regions), settings_(s) {
  for (std::size_t i = 0; i < regions.size(); ++i) {
    const scene::Medium& medium = regions[i].medium;
    Region r;
    r.lum = luminance_medium(medium);
    r.sigma_t_rgb = medium.sigma_s + medium.sigma_a;
    if (r.lum.sigma_s > 0) r.in_scatter_colour = s.display_scale * s.light_chroma * medium.sigma_s / r.lum.sigma_s;
    if (i < photons.size() && !photons[i].empty() && r.lum.sigma_s > 0) {
      const media::UniformGrid grid = media::grid_for_photons(photons[i], s.k_nearest);
      r.map = std::make_unique<media::PhotonMap>(std::move(photons[i]));
      if (s.radiance_estimate) r.grid = std::make_unique<media::RadianceGrid>(grid, *r.map, r.lum, s.k_nearest, s.grid_jobs);
    }
    regions_.push_back(std::move(r));
  }
}

ViewMedium::~ViewMedium() = default;

std::size_t ViewMedium::photons() const {
  std::size_t n = 0;
  for (const Region& r : regions_) n += r.map ? r.map->photons().size() : 0;
  return n;
}

media::GridBuildCounts ViewMedium::grid_build() const {
  media::GridBuildCounts c;
  for (const Region& r : regions_)
    if (r.grid) c.add(r.grid->build_counts());
  return c;
}

glm::vec3 ViewMedium::along(const geometry::Ray& ray, float t_end, glm::vec3 behind, apps::Rng& rng,
                            raytrace::TraceCounters& counters) const {
  const glm::dvec3 d(ray.direction);
  const double scale = glm::length(d);
  const glm::dvec3 o(ray.origin), u = d / scale;
  const std::vector<MediumInterval> parts = medium_intervals(bounds_, o, u, double(t_end) * scale);
  if (parts.empty()) return behind;
  glm::dvec3 radiance(0.0), through(1.0);
  for (const MediumInterval& part : parts) {
    const Region& r = regions_[part.region];
    const double length = part.t1 - part.t0;
    if (r.map) {
      media::MarchSettings march;
      march.estimator = r.grid ? media::Estimator::radiance : media::Estimator::transmittance;
      march.defensive_alpha = settings_.defensive_alpha;
      march.b = settings_.samples_per_free_path * r.lum.sigma_t;  // M = b S = samples (1 - T)
      const media::SegmentQuery q{o + part.t0 * u, u, length, &r.lum, r.grid.get(), std::nullopt};
      auto li = [&](const glm::dvec3& p) {
        return settings_.look_up_li ? r.map->in_scattered(p, -u, r.lum, settings_.k_nearest) : 0.0;
      };
      media::MarchCounters mc;
      const double in = media::march_segment_in_scatter(q, march, li, rng, mc);
      radiance += through * r.in_scatter_colour * in;
      ++counters.media_segments;
      counters.media_samples += std::int64_t(mc.samples);
      counters.media_knn_photons += std::int64_t(mc.samples * settings_.k_nearest);
      counters.media_sh_evals += std::int64_t(mc.sh_evals);
    }
    through *= channel_transmittance(r.sigma_t_rgb, length);
  }
  return glm::vec3(radiance + through * glm::dvec3(behind));
}

glm::vec3 ViewMedium::transmittance(const geometry::Ray& ray, float t_end) const {
  const glm::dvec3 d(ray.direction);
  const double scale = glm::length(d);
  return glm::vec3(segment_transmittance(bounds_, glm::dvec3(ray.origin), d / scale, double(t_end) * scale));
}

}  // namespace gcsim::render
