#pragma once
// The media as the radiosity pass sees them: the light a patch shoots to an element is attenuated
// by the transmittance of the segment between their centres through every medium that changes
// something (radiosity::PathTransmittance). What the media scatter onto surfaces is not added here:
// the photon pass deposits it on the elements (wall_deposits.hpp), radiosity's received power.
#include <memory>
#include <vector>

#include "apps/radiosity/radiosity.hpp"
#include "apps/render/medium_region.hpp"

namespace gcsim::render {

class RadiosityMedia final : public radiosity::PathTransmittance {
 public:
  // Keeps the regions that change something; empty() when none does.
  explicit RadiosityMedia(const std::vector<MediumRegion>& regions);
  // What the radiosity pass should see of `regions`: null when none changes anything.
  static std::unique_ptr<RadiosityMedia> of(const std::vector<MediumRegion>& regions);
  bool empty() const { return regions_.empty(); }
  radiosity::Rgb between(const radiosity::Vec3& from, const radiosity::Vec3& to) const override;

 private:
  std::vector<MediumRegion> regions_;
};

}  // namespace gcsim::render
