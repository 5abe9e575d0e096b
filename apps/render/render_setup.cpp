#include "apps/render/render_setup.hpp"

#include <stdexcept>

#include "apps/common/scene/description_to_world.hpp"
#include "apps/raytrace/raytrace.hpp"

namespace gcsim::render {

RenderSetup prepare_render(const scene::SceneDescription& d, const Plan& plan, const std::string& file,
                           ForcedPasses forced, std::size_t photons, bool with_media,
                           std::uint64_t seed) {
  RenderSetup s;
  s.split = split_media(d, file);
  raytrace::Scene lowered;
  try {  // refuses, before any run, what the view pass cannot show
    lowered = raytrace::lower_scene(s.split.surfaces);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(file + ": the view pass cannot render this scene: " + e.what());
  }
  s.radiosity = plan.pass(PassId::radiosity).on || forced.radiosity;
  if (s.radiosity) s.mesh = radiosity::flatten(scene::to_world(s.split.surfaces));
  if (!with_media) return s;
  if (s.radiosity) s.radiosity_media = RadiosityMedia::of(s.split.media);
  std::vector<MediumRegion> regions;
  for (const MediumRegion& r : s.split.media)
    if (forced.media || !r.changes_nothing()) regions.push_back(r);
  const bool photon_pass = forced.media || plan.pass(PassId::media).on;
  if (regions.empty() && !photon_pass) return s;
  try {
    s.media = make_media_setup(s.split, std::move(lowered), std::move(regions), photon_pass,
                               plan.facts.media_sampling == MediaSampling::radiance_estimate, photons);
    s.media->seed = seed;
    // Photons deposit what the media scatter onto the radiosity pass's elements (wall_deposits.hpp).
    if (s.radiosity && photon_pass) s.media->walls = std::make_unique<ElementLookup>(s.mesh, s.split.surfaces);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(file + ": " + e.what());
  }
  return s;
}

}  // namespace gcsim::render
