#include "apps/render/view_scene.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <stdexcept>

#include "apps/radiosity/radiosity.hpp"
#include "apps/raytrace/raytrace.hpp"

namespace gcsim::render {

bool is_specular(const scene::Material& m) { return m.mirror > 0 || m.transmittance > 0; }

namespace {

// The lowered scene's mirror and glass primitives, with their materials and normals: spheres
// first, as the ray tracer's id space wants them.
void add_specular_primitives(const raytrace::Scene& lowered, raytrace::Scene& view) {
  std::vector<int> material_in_view(lowered.materials.size(), -1);
  auto material = [&](int prim) {
    int& m = material_in_view[lowered.prim_material[std::size_t(prim)]];
    if (m < 0) m = view.add_material(lowered.material_of(prim));
    return m;
  };
  for (int p = 0; p < lowered.sphere_count(); ++p)
    if (lowered.material_of(p).spawns_secondary()) view.add_sphere(lowered.spheres[std::size_t(p)], material(p));
  for (int p = lowered.sphere_count(); p < lowered.prim_count(); ++p) {
    if (!lowered.material_of(p).spawns_secondary()) continue;
    const std::size_t t = std::size_t(p - lowered.sphere_count());
    if (lowered.triangle_normals.empty()) view.add_triangle(lowered.triangles[t], material(p));
    else view.add_triangle(lowered.triangles[t], lowered.triangle_normals[t], material(p));
  }
}

glm::vec3 display(const radiosity::Rgb& b, double exposure) {
  return glm::vec3(float(b.r * exposure), float(b.g * exposure), float(b.b * exposure));
}

// The element on the same vertices facing the other way (a polygon's back side), or -1.
std::vector<int> back_twins(const radiosity::Scene& mesh) {
  std::map<std::array<int, 4>, int> by_vertices;
  std::vector<int> twin(mesh.elements.size(), -1);
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    const radiosity::SceneElement& el = mesh.elements[e];
    // A triangle's unused fourth slot sorts last; sorting all four keeps GCC 12 from a false -Warray-bounds.
    std::array<int, 4> key;
    key.fill(std::numeric_limits<int>::max());
    std::copy_n(el.vertex.begin(), std::clamp(int(el.count), 0, 4), key.begin());
    std::sort(key.begin(), key.end());
    auto [it, added] = by_vertices.emplace(key, int(e));
    if (added || glm::dot(mesh.elements[std::size_t(it->second)].normal, el.normal) >= 0) continue;
    twin[e] = it->second;
    twin[std::size_t(it->second)] = int(e);
  }
  return twin;
}

// Every element of a non-specular surface, fanned into triangles (0, k, k+1) with the radiosity
// at its corners on its front and its back twin's (or none: black) on its back. A twin is not
// added again: two coincident triangles would make the hit between them arbitrary.
void add_radiosity_elements(const scene::SceneDescription& d, const radiosity::Scene& mesh,
                            const std::vector<radiosity::Rgb>& b, double exposure, raytrace::Scene& view) {
  if (b.size() != mesh.elements.size())
    throw std::invalid_argument("view scene: one radiosity per element expected");
  const auto corners = radiosity::element_corner_radiosity(mesh, b);
  const std::vector<int> twin = back_twins(mesh);
  auto shown = [&](std::size_t e) {
    const int m = mesh.surface_of_element(int(e)).material;
    return m < 0 || !is_specular(d.materials[std::size_t(m)]);
  };
  // The radiosity of element e at vertex index v (black if e < 0).
  auto at_vertex = [&](int e, int v) {
    if (e < 0) return glm::vec3(0.0f);
    const radiosity::SceneElement& el = mesh.elements[std::size_t(e)];
    for (int k = 0; k < el.count; ++k)
      if (el.vertex[std::size_t(k)] == v) return display(corners[std::size_t(e)][std::size_t(k)], exposure);
    return glm::vec3(0.0f);
  };
  // One material per front and back reflectance: point and spot lights shade the elements with it.
  std::map<std::pair<std::array<float, 3>, std::array<float, 3>>, int> materials;
  auto material_of = [&](int e, int back) {
    auto rho = [&](int x) {
      if (x < 0) return glm::vec3(0.0f);
      return glm::vec3(mesh.surface_of_element(x).reflectance);
    };
    const glm::vec3 f = rho(e), r = rho(back);
    const auto key = std::make_pair(std::array<float, 3>{f.r, f.g, f.b}, std::array<float, 3>{r.r, r.g, r.b});
    if (const auto it = materials.find(key); it != materials.end()) return it->second;
    raytrace::Material lit;
    lit.diffuse = f;
    lit.back_diffuse = r;
    lit.given_radiance = true;
    return materials[key] = view.add_material(lit);
  };
  view.triangle_radiance.resize(view.triangles.size(), {});  // the specular triangles: unused
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    if (!shown(e) || (twin[e] >= 0 && twin[e] < int(e) && shown(std::size_t(twin[e])))) continue;
    const radiosity::SceneElement& el = mesh.elements[e];
    const int back = twin[e] >= 0 && shown(std::size_t(twin[e])) ? twin[e] : -1;
    const int material = material_of(int(e), back);
    auto vertex = [&](int k) { return el.vertex[std::size_t(k)]; };
    auto position = [&](int k) { return glm::vec3(mesh.vertices[std::size_t(vertex(k))]); };
    for (int k = 1; k + 1 < el.count; ++k) {
      view.add_triangle(raytrace::Triangle{position(0), position(k), position(k + 1)}, material);
      const int e_ = int(e);
      view.triangle_radiance.push_back(
          {{at_vertex(e_, vertex(0)), at_vertex(e_, vertex(k)), at_vertex(e_, vertex(k + 1))},
           {at_vertex(back, vertex(0)), at_vertex(back, vertex(k)), at_vertex(back, vertex(k + 1))}});
    }
  }
}

}  // namespace

raytrace::Scene make_view_scene(const scene::SceneDescription& description, const radiosity::Scene& mesh,
                                const std::vector<radiosity::Rgb>& element_radiosity, double exposure) {
  raytrace::Scene lowered = raytrace::lower_scene(description);
  raytrace::Scene view;
  view.name = lowered.name;
  view.camera = lowered.camera;
  view.background = lowered.background;
  view.ambient = lowered.ambient;
  add_specular_primitives(lowered, view);
  add_radiosity_elements(description, mesh, element_radiosity, exposure, view);
  // Point and spot lights add their direct light to what radiosity shows, at the same exposure.
  for (raytrace::PointLight light : lowered.lights) {
    light.intensity *= float(exposure);
    view.lights.push_back(light);
  }
  view.validate();
  return view;
}

}  // namespace gcsim::render
