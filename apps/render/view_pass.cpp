#include "apps/render/view_pass.hpp"

#include "apps/radiosity/radiosity.hpp"
#include "apps/raytrace/raytrace.hpp"
#include "apps/render/view_scene.hpp"

namespace gcsim::render {
namespace {

// What the view will show on each element with the point and spot lights' direct light added
// (unshadowed, at the element's centre), so the automatic exposure accounts for them too.
std::vector<radiosity::Rgb> with_point_lights(const scene::SceneDescription& d, const radiosity::Scene& mesh,
                                              const std::vector<radiosity::Rgb>& b) {
  const std::vector<raytrace::PointLight> lights = raytrace::lower_lights(d);
  if (lights.empty()) return b;
  std::vector<radiosity::Rgb> shown = b;
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    const radiosity::SceneElement& el = mesh.elements[e];
    const radiosity::Rgb rho = mesh.surface_of_element(int(e)).reflectance;
    for (const raytrace::PointLight& light : lights) {
      const glm::dvec3 to = glm::dvec3(light.position) - glm::dvec3(el.center);
      const double d2 = glm::dot(to, to), cos = glm::dot(glm::dvec3(el.normal), to) / std::sqrt(d2);
      if (cos <= 0 || !light.lights_direction(glm::vec3(-to / std::sqrt(d2)))) continue;
      shown[e] += rho * glm::dvec3(light.intensity) * (cos / d2);
    }
  }
  return shown;
}

}  // namespace

std::unique_ptr<ViewPass> make_view_pass(const scene::SceneDescription& d, const radiosity::Scene* mesh,
                                         const std::vector<radiosity::Rgb>* b, ViewSettings view, int nodes,
                                         const MediaSetup* media, std::vector<std::vector<media::Photon>> photons) {
  auto v = std::make_unique<ViewPass>();
  if (mesh && b) {
    radiosity::RenderOptions ro;
    ro.width = d.image.width;
    ro.height = d.image.height;
    const radiosity::Camera camera = mesh->camera ? *mesh->camera : radiosity::default_camera(*mesh);
    v->exposure = view.exposure > 0 ? view.exposure : radiosity::auto_exposure(*mesh, with_point_lights(d, *mesh, *b), camera, ro);
    v->scene = make_view_scene(d, *mesh, *b, v->exposure);
  } else {
    v->scene = raytrace::lower_scene(d);
  }
  v->bvh = geometry::build_bvh_by_clustering(v->scene);
  v->settings.width = d.image.width;
  v->settings.height = d.image.height;
  v->settings.shading = raytrace::Shading::whitted;
  v->settings.secondary_rays = view.secondary;
  v->settings.shadow_rays = view.shadows;
  v->settings.max_depth = view.max_depth;
  if (media) {
    ViewMediumSettings ms = media->view;
    ms.display_scale = 3.14159265358979323846 * v->exposure;  // the display shows exitance, pi L
    ms.grid_jobs = view.host_threads;
    v->medium = std::make_unique<ViewMedium>(media->regions, std::move(photons), ms);
    v->settings.media = v->medium.get();
    v->settings.media_seed = media->seed;
  }
  v->job = std::make_unique<raytrace::ParallelRenderJob>(v->scene, v->bvh, v->settings, raytrace::Distribution::dynamic);
  v->result = v->job->new_result(nodes);
  v->prefetch = v->job->make_prefetch(nodes, view.host_threads);
  return v;
}

}  // namespace gcsim::render
