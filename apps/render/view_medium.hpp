#pragma once
// The media as the view pass sees them (raytrace::RayMedia): along every ray segment inside a
// medium, the radiance behind is attenuated by the transmittance (per RGB channel) and the light
// the medium scatters into the ray is added, estimated by the media app's distance sampling with
// Li from the region's volume photon map (eq. 4). The estimator is the plan's importance sampling:
// transmittance sampling for isotropic media (eq. 9), the radiance estimate for anisotropic ones
// (eq. 20, with the region's SH grid). The photon map holds luminance [A8]; the in-scattered light
// is given the lights' colour and the medium's scattering colour.
#include <memory>
#include <vector>

#include "apps/common/media/photon_map.hpp"
#include "apps/common/media/radiance_grid.hpp"
#include "apps/common/media/segment_march.hpp"
#include "apps/raytrace/raytrace.hpp"
#include "apps/render/medium_region.hpp"

namespace gcsim::render {

struct ViewMediumSettings {
  bool radiance_estimate = false;  // the plan's importance sampling: SH grid (true) or transmittance
  double samples_per_free_path = 32;  // march samples M = this * (1 - T) on a segment of transmittance T
  std::size_t k_nearest = 50;
  // The radiance estimate's transmittance share [A11]. The media app's 0.03 left bright single pixels
  // under CORNELL-FOG's lamp, where Li changes within a voxel faster than the SH histogram: two
  // renders with other seeds differed by a relative RMS of 0.0299 at 0.03, 0.0295 at 0.3 and 0.0290
  // with transmittance sampling, with largest pixel differences 0.38, 0.15 and 0.18 of white.
  double defensive_alpha = 0.3;
  // Displayed colour per unit radiance: pi (the display shows exitance, as radiosity's B) times the
  // radiosity pass's exposure (1 without one).
  double display_scale = 3.14159265358979323846;
  glm::dvec3 light_chroma{1.0};  // PhotonLights::chroma
  int grid_jobs = 1;             // host threads that build the SH grids (the same grids on any number)
  // false: the march counts its samples' photon look-ups without making them (Li taken as 0). The
  // plan's samples want only the counts, and nothing the march or the tile decides reads Li, so the
  // counts are the render's; on MEDIA-SMALL the look-ups are over half of a plan's host time.
  bool look_up_li = true;
};

class ViewMedium : public raytrace::RayMedia {
 public:
  // photons: per region (empty lists when the photon pass did not run: transmittance only).
  ViewMedium(std::vector<MediumRegion> regions, std::vector<std::vector<media::Photon>> photons, ViewMediumSettings s);
  ~ViewMedium() override;
  glm::vec3 along(const geometry::Ray& ray, float t_end, glm::vec3 behind, apps::Rng& rng,
                  raytrace::TraceCounters& counters) const override;
  glm::vec3 transmittance(const geometry::Ray& ray, float t_end) const override;
  std::size_t photons() const;      // stored, over all regions
  media::GridBuildCounts grid_build() const;  // the work the SH grids took (none without)

 private:
  struct Region;
  std::vector<MediumRegion> bounds_;  // what regions_[i] is built from: its bound and medium
  std::vector<Region> regions_;
  ViewMediumSettings settings_;
};

}  // namespace gcsim::render
