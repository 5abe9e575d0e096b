#include "apps/render/radiosity_media.hpp"

#include <glm/geometric.hpp>

namespace gcsim::render {

RadiosityMedia::RadiosityMedia(const std::vector<MediumRegion>& regions) {
  for (const MediumRegion& r : regions)
    if (!r.changes_nothing()) regions_.push_back(r);
}

std::unique_ptr<RadiosityMedia> RadiosityMedia::of(const std::vector<MediumRegion>& regions) {
  auto media = std::make_unique<RadiosityMedia>(regions);
  return media->empty() ? nullptr : std::move(media);
}

radiosity::Rgb RadiosityMedia::between(const radiosity::Vec3& from, const radiosity::Vec3& to) const {
  const glm::dvec3 d = to - from;
  const double length = glm::length(d);
  if (length <= 0) return radiosity::Rgb(1.0);
  return segment_transmittance(regions_, from, d / length, length);
}

}  // namespace gcsim::render
