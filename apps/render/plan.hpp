#pragma once
// The effects plan: from the scene description alone, which passes a render needs, each
// on or off with the reason in words and what it depends on. Passes:
//   view       primary rays from the camera with direct lighting (always on)
//   radiosity  diffuse interreflection, the thesis's progressive refinement (view-independent)
//   specular   ray tracing of mirror and glass paths (and refracting medium boundaries)
//   media      photon pass and ray marching through participating media
//   shadows    shadow rays towards point, spot and (without radiosity) area lights
// The costs are estimated separately (plan_cost.hpp) so that the decisions depend on nothing else.
#include <string>
#include <vector>

#include "apps/common/scene/scene_description.hpp"

namespace gcsim::render {

enum class PassId { view, radiosity, specular, media, shadows };
const char* pass_name(PassId id);

// How the media pass samples scattering, after the medium's phase function.
enum class MediaSampling { none, isotropic, radiance_estimate };
const char* to_string(MediaSampling s);

struct PassPlan {
  PassId id = PassId::view;
  bool on = false;
  std::string reason;                 // why on or off, in words
  std::string detail;                 // e.g. the media pass's importance sampling
  std::vector<PassId> depends_on;     // passes (that are on) whose results this one reads
};

// What the plan counted in the scene (also the inputs of the cost model).
struct SceneFacts {
  int shapes = 0, objects = 0;
  int patches = 0, elements = 0;      // radiosity mesh (description_to_world)
  int primitives = 0;                 // ray tracer primitives: triangles and spheres
  int emitters = 0;                   // shapes with emission > 0
  int point_lights = 0;               // point and spot lights with intensity > 0
  int diffuse_surfaces = 0;           // surface sides with reflectance > 0
  long long pixels = 0;
  int samples_per_pixel = 1;
  MediaSampling media_sampling = MediaSampling::none;
  double largest_albedo = 0.0;        // of the scattering media
  // Sum over the media of 1 - e^-tau, tau = sigma_t (luminance) times the bound's mean chord (Cauchy:
  // 4 V / S), times the fraction of the image the bound covers: the fraction of a full march (32
  // samples per free path) a camera ray takes in each, on average.
  double media_opacity = 0.0;
  // The largest fraction of the image a scattering medium's bound covers (its bounding ball's solid
  // angle over the view's, at most 1): at 1 the marching is spread over every tile.
  double media_coverage = 0.0;
};

struct Plan {
  std::string scene_name;
  SceneFacts facts;
  std::vector<PassPlan> passes;  // in PassId order
  const PassPlan& pass(PassId id) const { return passes[static_cast<int>(id)]; }
};

// Throws std::invalid_argument if a shape names a material that does not exist.
Plan make_plan(const scene::SceneDescription& scene);

}  // namespace gcsim::render
