#pragma once
// What a participating medium takes from the light between a shooting patch and a receiving
// element: exp(-integral of sigma_t) per channel along the segment between them. Radiosity knows
// no media; a renderer that holds them (apps/render) supplies this, and the solver then delivers
// F * T of a shot instead of F (the zonal method's attenuation, one segment per pair: from the
// patch's centre to the element's centre) and books the rest as taken by the media.
#include "apps/radiosity/scene.hpp"

namespace gcsim::radiosity {

class PathTransmittance {
 public:
  virtual ~PathTransmittance() = default;
  // In [0, 1] per channel; exactly 1 where nothing on the segment attenuates.
  virtual Rgb between(const Vec3& from, const Vec3& to) const = 0;
};

}  // namespace gcsim::radiosity
