#pragma once
// The photon pass of the unified renderer (the media paper's section 2, in a scene with surfaces):
// photons leave the scene's lights in proportion to their flux, fly through the media by
// transmittance sampling, are stored at every medium interaction before the albedo roulette (the
// media app's reading [A4]) and scatter by the medium's phase; at surfaces they are reflected
// diffusely, by a mirror, or reflected or refracted by glass, by Russian roulette on the surface's
// (luminance) weights, so light that walls reflect into the fog is in the map too.
// Each photon also carries an RGB tint (its RGB flux over its luminance flux: the emitter's chroma,
// then the ratio weights of the luminance sampling at coloured walls and media), read only where a
// flight that began at a scattering ends on a diffuse surface (WallHit): the light the media scatter
// onto the walls, which radiosity then carries on (wall_deposits.hpp).
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec3.hpp>

#include "apps/common/geometry/bvh.hpp"
#include "apps/common/geometry/primitive_intersection.hpp"
#include "apps/common/scene/scene_description.hpp"
#include "apps/common/media/medium.hpp"
#include "apps/common/media/photon_map.hpp"
#include "apps/raytrace/raytrace.hpp"
#include "apps/render/medium_region.hpp"

namespace gcsim::render {

// Where photons start: emissive polygons (front, and back with an emitting back material), point and
// spot lights, chosen in proportion to their luminance flux.
struct PhotonLights {
  struct Emitter {
    enum class Kind { triangle, point, spot } kind;
    glm::dvec3 a{0.0}, b{0.0}, c{0.0};  // triangle corners; a: a point or spot light's position
    glm::dvec3 axis{0.0};               // a triangle's emitting side, a spot's direction
    double cos_cone = -1.0;             // spot
    double flux = 0.0;                  // luminance
    glm::dvec3 chroma{1.0};             // RGB flux over luminance flux
  };
  std::vector<Emitter> emitters;
  std::vector<double> cumulative;  // running sums of flux, for the choice
  double total_flux = 0.0;         // luminance
  glm::dvec3 chroma{1.0};          // the lights' colour: RGB flux over luminance flux (luminance 1)
};

// Throws std::invalid_argument naming the shape for emitting spheres, boxes or meshes.
PhotonLights photon_lights(const scene::SceneDescription& surfaces);

// One medium as the photon map reads it: luminance coefficients [A8] and the phase.
media::HomogeneousMedium luminance_medium(const scene::Medium& m);

struct VolumePhotons {
  std::vector<std::vector<media::Photon>> per_region;  // one list per MediumRegion
  std::uint64_t flights = 0, surface_events = 0;
  std::uint64_t wall_hits = 0;   // flights from a scattering that ended on a diffuse surface (WallHit calls)
  double media_absorbed = 0.0;   // luminance power the media absorbed (the albedo roulette's losses)
  geometry::TestTally tests;     // the surface hits' box and triangle tests
};

// A photon's flight that began at a scattering in a medium (or at a mirror or glass such a flight
// reached) meets a surface that is neither mirror nor glass, from `origin` along `direction`
// (unit): power is its RGB flux (luminance power times tint). Called before the surface's roulette.
using WallHit = std::function<void(const glm::dvec3& origin, const glm::dvec3& direction, const glm::dvec3& power)>;

// Host-side progress: `photons` more were traced (called every kPhotonsPerReport and at the end).
using PhotonsTraced = std::function<void(std::size_t photons)>;
inline constexpr std::size_t kPhotonsPerReport = 4096;

// Photons [first, last) of `total`; photon i draws from its own stream (seed, i), so any split of the
// range over nodes gives the same photons. Each carries total_flux / total. jobs > 1: batches of
// the range on that many host threads, joined in photon order and on_wall called in that order on
// the calling thread, so photons, sums and calls are the same as on one (on_traced per batch).
VolumePhotons trace_volume_photons(const raytrace::Scene& surfaces, const geometry::Bvh& bvh, const PhotonLights& lights,
                                   const std::vector<MediumRegion>& media, std::size_t first, std::size_t last,
                                   std::size_t total, std::uint64_t seed, const WallHit& on_wall = {},
                                   const PhotonsTraced& on_traced = {}, int jobs = 1);
inline constexpr std::size_t kPhotonBatchesPerThread = 4;  // batches per host thread, for balance

}  // namespace gcsim::render
