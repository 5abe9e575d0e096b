#include "apps/render/plan.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>
#include <type_traits>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "apps/common/scene/description_to_world.hpp"
#include "apps/render/medium_region.hpp"
#include "apps/render/light_paths.hpp"

namespace gcsim::render {

const char* pass_name(PassId id) {
  static constexpr const char* kNames[] = {"view", "radiosity", "specular", "media", "shadows"};
  return kNames[static_cast<int>(id)];
}

const char* to_string(MediaSampling s) {
  switch (s) {
    case MediaSampling::none: return "none";
    case MediaSampling::isotropic: return "isotropic";
    case MediaSampling::radiance_estimate: return "radiance estimate";
  }
  return "?";
}

namespace {

using scene::Material;
using scene::SceneDescription;


std::string quoted_list(const std::set<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "'" : ", '") + n + "'";
  return out;
}

// Everything the decisions read, gathered once.
struct Analysis {
  const SceneDescription& d;
  std::vector<SurfaceSide> sides;
  std::vector<glm::dvec3> light_positions;  // point and spot lights that emit
  bool emits = false;
  std::vector<bool> lit;                      // per side: emitted light reaches it directly
  std::vector<bool> lit_by_area;              // per side: an emissive surface's light reaches it directly
  std::set<int> used_materials;

  const Material& material(const SurfaceSide& s) const { return d.materials[s.material]; }
  bool diffuse(const SurfaceSide& s) const { return scene::largest(material(s).diffuse) > 0.0; }
  bool emitter(const SurfaceSide& s) const { return scene::largest(material(s).emission) > 0.0; }
};

Analysis analyse(const SceneDescription& d) {
  Analysis a{d, visible_sides(d), {}, false, {}, {}, {}};
  for (const auto& light : d.lights)
    std::visit([&](const auto& l) {
      if constexpr (std::is_same_v<std::decay_t<decltype(l)>, scene::DiskLight>) {
        if (scene::largest(l.power) > 0.0) a.light_positions.push_back(l.position);
      } else if (scene::largest(l.intensity) > 0.0) {
        a.light_positions.push_back(l.position);
      }
    }, light);
  for (const auto& s : d.shapes) {
    a.used_materials.insert(s.material);
    if (s.back_material >= 0) a.used_materials.insert(s.back_material);
  }
  a.emits = !a.light_positions.empty() || std::any_of(a.sides.begin(), a.sides.end(), [&](auto& s) { return a.emitter(s); });
  for (const SurfaceSide& b : a.sides) {
    const bool by_point = std::any_of(a.light_positions.begin(), a.light_positions.end(),
                                      [&](const glm::dvec3& p) { return faces_point(d, b, p); });
    bool by_area = false;
    for (const SurfaceSide& e : a.sides)
      if (!by_area && a.emitter(e) && !(e.shape == b.shape && e.back == b.back) && exchange(d, e, b)) by_area = true;
    a.lit.push_back(by_point || by_area);
    a.lit_by_area.push_back(by_area);
  }
  return a;
}

PassPlan plan_radiosity(const Analysis& a) {
  PassPlan p;
  p.id = PassId::radiosity;
  int diffuse = 0, lit_diffuse = 0, area_lit = 0;
  bool interreflection = false;
  for (std::size_t i = 0; i < a.sides.size(); ++i) {
    if (!a.diffuse(a.sides[i])) continue;
    ++diffuse;
    if (!a.lit[i]) continue;
    ++lit_diffuse;
    area_lit += a.lit_by_area[i];
    for (const SurfaceSide& c : a.sides)
      if (a.diffuse(c) && exchange(a.d, a.sides[i], c)) interreflection = true;
  }
  if (diffuse == 0) {
    p.reason = "no surface has a reflectance above 0: radiosity skipped";
  } else if (!a.emits) {
    p.reason = "nothing emits light (no emissive surface, point or spot light): radiosity skipped";
  } else if (lit_diffuse == 0) {
    p.reason = "no emitted light reaches a surface with a reflectance above 0: radiosity skipped";
  } else if (area_lit == 0 && !interreflection) {
    p.reason = fmt::format("point or spot light reaches {} diffuse surface(s) directly, but no two diffuse surfaces "
                           "face each other: the view's direct lighting is exact, radiosity skipped",
                           lit_diffuse);
  } else if (area_lit == 0) {
    // The thesis's radiosity shoots from emissive patches: it has nothing to shoot here.
    p.reason = fmt::format("only point or spot lights reach the {} diffuse surface(s): the view lights them directly "
                           "and their interreflection is not computed (radiosity shoots from emissive surfaces only), "
                           "radiosity skipped",
                           lit_diffuse);
  } else if (!interreflection) {
    // The view has no area-light sampling: the radiosity solution is how area light reaches it.
    p.on = true;
    p.reason = fmt::format("area light reaches {} diffuse surface side(s), none of which faces another: radiosity "
                           "gives their direct lighting (the view samples no area light)",
                           area_lit);
  } else {
    p.on = true;
    p.reason = fmt::format("{} surface side(s) reflect diffusely, {} receive emitted light and pass it on to "
                           "others: diffuse interreflection by progressive radiosity",
                           diffuse, lit_diffuse);
  }
  return p;
}

PassPlan plan_specular(const Analysis& a) {
  PassPlan p;
  p.id = PassId::specular;
  std::set<std::string> mirrors, glass, boundaries;
  for (int m : a.used_materials) {
    const Material& mat = a.d.materials[m];
    if (mat.mirror > 0) mirrors.insert(mat.name);
    if (mat.transmittance > 0) glass.insert(mat.name);
    if (mat.medium && mat.medium->boundary_ior != 1.0) boundaries.insert(mat.name);
  }
  std::vector<std::string> parts;
  if (!mirrors.empty()) parts.push_back("mirror " + quoted_list(mirrors));
  if (!glass.empty()) parts.push_back("glass " + quoted_list(glass));
  if (!boundaries.empty()) parts.push_back("refracting medium boundary " + quoted_list(boundaries));
  if (parts.empty()) {
    p.reason = "no mirror, glass or refracting medium boundary: specular ray tracing skipped";
  } else {
    p.on = true;
    p.reason = fmt::format("{}: reflected and refracted paths need ray tracing", fmt::join(parts, "; "));
  }
  return p;
}

// "medium 'a'" or "media 'a', 'b'".
std::string media_named(const std::set<std::string>& names) {
  return (names.size() > 1 ? "media " : "medium ") + quoted_list(names);
}

// The fraction of the image a ball covers (1 with the eye inside it or no camera): its solid angle
// pi r^2 / d^2 over the view's, 4 tan(fov_x / 2) tan(fov_y / 2).
double coverage(const SceneDescription& d, const glm::dvec3& centre, double radius) {
  if (!d.camera) return 1.0;
  const double dist2 = glm::dot(centre - d.camera->eye, centre - d.camera->eye);
  if (dist2 <= radius * radius) return 1.0;
  const double tan_y = std::tan(d.camera->fov_y_degrees * 3.14159265358979323846 / 360.0);
  const double tan_x = tan_y * double(d.image.width) / double(std::max(1, d.image.height));
  return std::min(1.0, 3.14159265358979323846 * radius * radius / dist2 / (4 * tan_x * tan_y));
}

// 1 - e^-tau over the mean chord of the shapes material m fills (4 V / S; a box's or a sphere's),
// times the fraction of the image each covers.
double opacity(const SceneDescription& d, int m) {
  const scene::Medium& md = *d.materials[std::size_t(m)].medium;
  const double sigma_t = luminance(md.sigma_s + md.sigma_a);
  double sum = 0;
  for (const scene::Shape& s : d.shapes) {
    if (s.material != m) continue;
    double chord = 0, covered = 1;
    if (const auto* box = std::get_if<scene::Box>(&s.geometry)) {
      const glm::dvec3 e = box->hi - box->lo;
      chord = 4 * e.x * e.y * e.z / (2 * (e.x * e.y + e.y * e.z + e.z * e.x));
      covered = coverage(d, 0.5 * (box->lo + box->hi), 0.5 * glm::length(e));
    } else if (const auto* sphere = std::get_if<scene::Sphere>(&s.geometry)) {
      chord = 4 * sphere->radius / 3;
      covered = coverage(d, sphere->center, sphere->radius);
    }
    sum += -std::expm1(-sigma_t * chord) * covered;
  }
  return sum;
}

// The largest fraction of the image a shape of material m covers.
double largest_coverage(const SceneDescription& d, int m) {
  double most = 0;
  for (const scene::Shape& s : d.shapes) {
    if (s.material != m) continue;
    if (const auto* box = std::get_if<scene::Box>(&s.geometry))
      most = std::max(most, coverage(d, 0.5 * (box->lo + box->hi), 0.5 * glm::length(box->hi - box->lo)));
    else if (const auto* sphere = std::get_if<scene::Sphere>(&s.geometry))
      most = std::max(most, coverage(d, sphere->center, sphere->radius));
  }
  return most;
}

PassPlan plan_media(const Analysis& a, SceneFacts& facts) {
  PassPlan p;
  p.id = PassId::media;
  std::set<std::string> scattering, absorbing, empty, anisotropic;
  for (int m : a.used_materials) {
    const Material& mat = a.d.materials[m];
    if (!mat.medium) continue;
    const scene::Medium& md = *mat.medium;
    if (scene::largest(md.sigma_s) > 0) {
      scattering.insert(mat.name);
      facts.media_opacity += opacity(a.d, m);
      facts.media_coverage = std::max(facts.media_coverage, largest_coverage(a.d, m));
      const scene::Rgb sigma_t = md.sigma_s + md.sigma_a;
      for (int c = 0; c < 3; ++c)
        if (sigma_t[c] > 0) facts.largest_albedo = std::max(facts.largest_albedo, md.sigma_s[c] / sigma_t[c]);
      if (md.phase != scene::PhaseKind::isotropic && md.phase_g != 0.0) anisotropic.insert(mat.name);
    } else if (scene::largest(md.sigma_a) > 0) {
      absorbing.insert(mat.name);
    } else {
      empty.insert(mat.name);
    }
  }
  facts.media_sampling = scattering.empty() ? MediaSampling::none
                         : anisotropic.empty() ? MediaSampling::isotropic
                                               : MediaSampling::radiance_estimate;
  p.detail = "importance sampling: " + std::string(to_string(facts.media_sampling));
  if (scattering.empty() && absorbing.empty() && empty.empty()) {
    p.reason = "no participating medium: media pass skipped";
  } else if (scattering.empty() && absorbing.empty()) {
    p.reason = fmt::format("medium {} has sigma_s = sigma_a = 0 and changes nothing: media pass skipped", quoted_list(empty));
  } else if (scattering.empty()) {
    p.reason = fmt::format("medium {} only absorbs (sigma_s = 0): no photons needed, the view applies its "
                           "transmittance; media pass skipped",
                           quoted_list(absorbing));
    p.detail += " (transmittance only)";
  } else if (!a.emits) {
    p.reason = fmt::format("{} {} but nothing emits light: media pass skipped", media_named(scattering),
                           scattering.size() > 1 ? "scatter" : "scatters");
  } else {
    p.on = true;
    p.reason = fmt::format("{} {} (sigma_s > 0): photon pass, then ray marching along camera rays",
                           media_named(scattering), scattering.size() > 1 ? "scatter" : "scatters");
    p.detail += anisotropic.empty() ? " (phase g = 0)" : fmt::format(" (anisotropic phase in {})", quoted_list(anisotropic));
  }
  return p;
}

PassPlan plan_shadows(const Analysis& a, bool radiosity_on) {
  PassPlan p;
  p.id = PassId::shadows;
  const int area = int(std::count_if(a.sides.begin(), a.sides.end(), [&](auto& s) { return a.emitter(s); }));
  std::set<int> shapes;
  bool mesh = false;
  for (const SurfaceSide& s : a.sides) {
    shapes.insert(s.shape);
    mesh = mesh || std::holds_alternative<scene::Mesh>(a.d.shapes[s.shape].geometry);
  }
  const bool occluders = shapes.size() >= 2 || mesh;
  if (!a.emits) {
    p.reason = "nothing emits light: no shadows to trace";
  } else if (!occluders) {
    p.reason = "a single planar or convex surface cannot shadow anything: shadow rays skipped";
  } else if (!a.light_positions.empty()) {
    p.on = true;
    p.reason = fmt::format("{} point or spot light(s) and {} surfaces that may occlude them: shadow rays",
                           a.light_positions.size(), shapes.size());
  } else if (radiosity_on) {
    p.reason = fmt::format("the {} area light(s)' shadows are part of the radiosity solution (hemicube visibility): "
                           "shadow rays skipped",
                           area);
  } else {
    p.reason = fmt::format("the {} area light(s) light no diffuse surface (so no radiosity), and the view casts shadow "
                           "rays towards point and spot lights only: shadow rays skipped",
                           area);
  }
  return p;
}

void count_meshes(const SceneDescription& d, SceneFacts& f) {
  const scene::World w = scene::to_world(without_invisible_boundaries(d));  // a medium's bound is no surface
  f.objects = int(w.entities.size());
  for (const scene::Entity& e : w.entities) f.patches += int(e.patches.size()), f.elements += int(e.elements.size());
  for (const scene::Shape& s : d.shapes) {
    if (const auto* p = std::get_if<scene::Polygon>(&s.geometry)) f.primitives += p->count - 2;
    else if (std::holds_alternative<scene::Sphere>(s.geometry)) f.primitives += 1;
    else if (std::holds_alternative<scene::Box>(s.geometry)) f.primitives += 12;
    else f.primitives += int(std::get<scene::Mesh>(s.geometry).mesh.triangles.size());
  }
}

}  // namespace

Plan make_plan(const SceneDescription& d) {
  for (const scene::Shape& s : d.shapes)
    if (s.material < 0 || s.material >= int(d.materials.size()) || s.back_material >= int(d.materials.size()))
      throw std::invalid_argument("scene '" + d.name + "': a shape names a material that does not exist");
  Plan plan;
  plan.scene_name = d.name;
  SceneFacts& f = plan.facts;
  f.shapes = int(d.shapes.size());
  f.pixels = static_cast<long long>(d.image.width) * d.image.height;
  f.samples_per_pixel = d.image.samples_per_pixel;
  count_meshes(d, f);
  const Analysis a = analyse(d);
  f.point_lights = int(a.light_positions.size());
  for (const SurfaceSide& s : a.sides) f.emitters += a.emitter(s), f.diffuse_surfaces += a.diffuse(s);

  PassPlan view;
  view.id = PassId::view;
  view.on = true;
  view.reason = fmt::format("the camera sees the scene: {} x {} pixels x {} sample(s) of primary rays with direct "
                            "lighting{}",
                            d.image.width, d.image.height, d.image.samples_per_pixel,
                            d.camera ? "" : " (no camera given: the view frames the scene itself)");
  PassPlan radiosity = plan_radiosity(a);
  PassPlan specular = plan_specular(a);
  PassPlan media = plan_media(a, f);
  PassPlan shadows = plan_shadows(a, radiosity.on);
  if (radiosity.on) view.depends_on.push_back(PassId::radiosity);  // diffuse illumination at hits
  for (PassPlan* p : {&specular, &media, &shadows})
    if (p->on) p->depends_on.push_back(PassId::view);
  if (specular.on && radiosity.on) specular.depends_on.push_back(PassId::radiosity);
  plan.passes = {view, radiosity, specular, media, shadows};
  return plan;
}

}  // namespace gcsim::render
