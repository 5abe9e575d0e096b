#include "apps/media/lower_media_scene.hpp"

#include <stdexcept>
#include <string_view>

#include <fmt/format.h>

#include "apps/common/scene/scene_catalogue.hpp"

namespace gcsim::media {
namespace {

[[noreturn]] void lacks(const scene::SceneDescription& d, std::string_view what) {
  throw std::invalid_argument(fmt::format("media scene '{}': {}", d.name, what));
}

// The media renderer works in luminance: a grey colour is its value (exactly), another its luminance.
double grey(const scene::Rgb& c) {
  if (c.r == c.g && c.g == c.b) return c.g;
  return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

Phase lower_phase(const scene::Medium& m) {
  switch (m.phase) {
    case scene::PhaseKind::isotropic: return Phase::isotropic();
    case scene::PhaseKind::schlick: return Phase::schlick(m.phase_g);
    case scene::PhaseKind::henyey_greenstein: return Phase::henyey_greenstein(m.phase_g);
  }
  return Phase::isotropic();
}

HomogeneousMedium lower_medium(const scene::Medium& m) {
  const double sigma_s = grey(m.sigma_s);
  return {sigma_s + grey(m.sigma_a), sigma_s, 0.0, lower_phase(m)};
}

std::string shape_label(const scene::SceneDescription& d, std::size_t index) {
  const scene::Shape& s = d.shapes[index];
  const std::string line = s.source_line > 0 ? fmt::format(" (line {})", s.source_line) : "";
  return fmt::format("shape {}{}, material '{}'", index + 1, line, d.materials.at(std::size_t(s.material)).name);
}

// The fog's box and the object, each with its medium; any other shape is an error naming it.
void lower_shapes(const scene::SceneDescription& d, MediaScene& s) {
  bool any_medium = false;
  for (const scene::Material& m : d.materials) any_medium |= m.medium.has_value();
  if (!any_medium)
    lacks(d, "no participating medium: the media renderer needs a box of fog (a box shape whose material has a "
             "[medium]) and at most one medium object (a sphere or a closed mesh) in it");
  bool fog = false;
  for (std::size_t i = 0; i < d.shapes.size(); ++i) {
    const scene::Shape& shape = d.shapes[i];
    const scene::Material& m = d.materials.at(std::size_t(shape.material));
    if (!m.medium) lacks(d, shape_label(d, i) + " has no medium: the media renderer draws media and their boundaries only");
    if (scene::largest(m.emission) > 0.0) lacks(d, shape_label(d, i) + " emits: the media renderer's lights are a point or a disk light");
    if (const auto* box = std::get_if<scene::Box>(&shape.geometry)) {
      if (fog) lacks(d, shape_label(d, i) + " is a second box of fog: expected one");
      if (m.medium->boundary_ior != 1.0) lacks(d, shape_label(d, i) + ": the fog's box must not refract (ior 1)");
      fog = true;
      s.fog_box = {box->lo, box->hi, {1, 1, 1}};
      s.outside = lower_medium(*m.medium);
      continue;
    }
    if (s.object) lacks(d, shape_label(d, i) + " is a second medium object: expected at most one besides the fog's box");
    if (const auto* sphere = std::get_if<scene::Sphere>(&shape.geometry)) {
      s.object = std::make_shared<SphereBoundary>(sphere->center, sphere->radius);
    } else if (const auto* mesh = std::get_if<scene::Mesh>(&shape.geometry)) {
      s.object = std::make_shared<MeshBoundary>(mesh->mesh, fmt::format("media scene '{}', {}", d.name, shape_label(d, i)));
    } else {
      lacks(d, shape_label(d, i) + " is a polygon: a medium object is a sphere or a closed mesh");
    }
    s.inside = lower_medium(*m.medium);
    s.ior = m.medium->boundary_ior;
  }
  if (!fog) lacks(d, "no box of fog: the media renderer needs a box shape whose material has a medium");
}

void lower_light(const scene::SceneDescription& d, MediaScene& s) {
  if (d.lights.size() != 1)
    lacks(d, fmt::format("{} lights: the media renderer lights by exactly one point or disk light", d.lights.size()));
  if (const auto* p = std::get_if<scene::PointLight>(&d.lights[0])) {
    s.light = {p->position, grey(p->intensity)};
  } else if (const auto* disk = std::get_if<scene::DiskLight>(&d.lights[0])) {
    s.area_light = DirectionalAreaLight{disk->position, disk->normal, disk->radius, disk->exponent, grey(disk->power)};
  } else {
    lacks(d, "a spot light: the media renderer lights by one point or disk light");
  }
}

}  // namespace

MediaScene lower_media_scene(const scene::SceneDescription& d) {
  MediaScene s;
  s.name = d.name;
  lower_shapes(d, s);
  lower_light(d, s);
  if (!d.camera) lacks(d, "no camera: the media renderer does not frame a scene itself");
  s.camera = *d.camera;
  s.image = {d.image.width, d.image.height};
  const scene::MediaSettings settings = d.media.value_or(scene::MediaSettings{});
  s.photons_emitted = settings.photons_emitted;
  s.k_nearest = settings.k_nearest;
  s.max_photon_events = settings.max_photon_events;
  s.max_specular_depth = settings.max_specular_depth;
  return s;
}


}  // namespace gcsim::media
