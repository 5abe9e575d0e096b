#include "apps/render/error_budget.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "apps/common/scene/description_to_world.hpp"
#include "apps/radiosity/radiosity.hpp"
#include "apps/render/medium_region.hpp"

namespace gcsim::render {

namespace {

double mean_reflectance(const radiosity::Scene& mesh) {
  double sum = 0, area = 0;
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    const radiosity::Rgb& r = mesh.surface_of_element(int(e)).reflectance;
    sum += mesh.elements[e].area * (r.r + r.g + r.b) / 3;
    area += mesh.elements[e].area;
  }
  return area > 0 ? std::clamp(sum / area, 0.0, 0.99) : 0.0;
}

// How much brighter the brightest emitter is than the mean surface, whose exitance is about the
// emitted flux over the area times 1 / (1 - rho); 1 without emissive surfaces (point lights).
double light_contrast(const radiosity::Scene& mesh) {
  double flux = 0, area = 0, brightest = 0;
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    const double exitance = luminance(mesh.surface_of_element(int(e)).exitance);
    flux += exitance * mesh.elements[e].area;
    area += mesh.elements[e].area;
    brightest = std::max(brightest, exitance);
  }
  if (flux <= 0 || area <= 0) return 1.0;
  const double mean = flux / area / (1 - mean_reflectance(mesh));
  return std::max(1.0, brightest / mean);
}

struct Thickness {
  double depth = 0, albedo = 0;
};

// The largest optical depth of a medium that changes anything, along its bound's longest chord
// (a box's diagonal, a sphere's diameter), with the largest albedo; none without such a medium.
std::optional<Thickness> thickest_medium(const scene::SceneDescription& d) {
  std::optional<Thickness> tau;
  for (const scene::Shape& s : d.shapes) {
    const scene::Material& m = d.materials.at(std::size_t(s.material));
    if (!m.medium) continue;
    const scene::Rgb sigma_t = m.medium->sigma_s + m.medium->sigma_a;
    const double largest = std::max({sigma_t.r, sigma_t.g, sigma_t.b});
    if (largest <= 0) continue;
    double chord = 0;
    if (const auto* box = std::get_if<scene::Box>(&s.geometry)) chord = glm::length(box->hi - box->lo);
    else if (const auto* sphere = std::get_if<scene::Sphere>(&s.geometry)) chord = 2 * sphere->radius;
    else continue;  // refused by the render anyway
    Thickness t = tau.value_or(Thickness{});
    t.depth = std::max(t.depth, largest * chord);
    for (int c = 0; c < 3; ++c)
      if (sigma_t[c] > 0) t.albedo = std::max(t.albedo, m.medium->sigma_s[c] / sigma_t[c]);
    tau = t;
  }
  return tau;
}

}  // namespace

BudgetChoice controls_for_budget(const scene::SceneDescription& d, const Plan& plan, double budget) {
  if (!(budget > 0 && budget < 1))
    throw std::invalid_argument(fmt::format("--error-budget {}: expected a relative error between 0 and 1 (e.g. 0.02)", budget));
  BudgetChoice c;
  const RenderControls full;
  // The scene's surfaces as radiosity meshes them (without the media's bounds), made once.
  std::optional<radiosity::Scene> mesh;
  auto surfaces = [&]() -> const radiosity::Scene& {
    if (!mesh) mesh = radiosity::flatten(scene::to_world(without_invisible_boundaries(d)));
    return *mesh;
  };
  // Media first: a medium of optical depth tau along its longest chord dims what lies behind it by
  // at most 1 - e^-tau; the light it scatters in is that times its albedo times how much brighter
  // the lights are than the mean surface (near a lamp the glow outshines the walls: CORNELL with a
  // haze of tau = 0.0096 changed the image by a relative RMSE of 0.024). Below half the budget, the
  // media pass and the view's media are left out, and what they took of the budget is not left to
  // the other controls (the errors may add).
  if (const auto tau = thickest_medium(d)) {
    const double contrast = light_contrast(surfaces());
    const double effect = -std::expm1(-tau->depth) * (1 + tau->albedo * contrast);
    c.controls.media = !(effect < 0.5 * budget);
    if (!c.controls.media) budget -= effect;
    c.reasons.push_back(fmt::format("media: {} (the thickest medium's optical depth along its longest chord is {:.3g}, "
                                    "albedo {:.3g}, lights {:.3g} times the mean surface: it changes a pixel by about "
                                    "{:.3g}, {} half the budget){}",
                                    c.controls.media ? "stay" : "dropped", tau->depth, tau->albedo, contrast, effect,
                                    c.controls.media ? "not below" : "below",
                                    c.controls.media ? "" : fmt::format("; {:.3g} of the budget is left", budget)));
  }
  if (plan.pass(PassId::radiosity).on) {
    // Unshot energy U would still reach the surfaces as U (1 + rho + rho^2 + ...) = U / (1 - rho)
    // with rho the area-weighted mean reflectance: stop when that is below the budget.
    const double rho = mean_reflectance(surfaces());
    c.controls.energy = std::clamp(1.0 - budget * (1.0 - rho), 0.5, full.energy);
    c.reasons.push_back(fmt::format("radiosity: shoots {:.4g} % of the energy instead of {:g} % (unshot energy U still "
                                    "brings U / (1 - {:.3f}) with the mean reflectance {:.3f})",
                                    100 * c.controls.energy, 100 * full.energy, rho, rho));
  }
  if (plan.pass(PassId::specular).on) {
    double w = 0;
    for (const scene::Material& m : d.materials) {
      w = std::max({w, m.mirror, m.transmittance});
      if (m.medium && m.medium->boundary_ior != 1.0) w = 1;  // a medium's dielectric bound: all of it
    }
    const int depth = w < 1 ? int(std::ceil(std::log(budget) / std::log(w))) : full.max_depth;
    c.controls.max_depth = std::clamp(depth, 1, full.max_depth);
    c.reasons.push_back(c.controls.max_depth < full.max_depth
                            ? fmt::format("specular: rays stop at depth {} instead of {} ({:g}^{} < {:g})", c.controls.max_depth,
                                          full.max_depth, w, c.controls.max_depth, budget)
                            : fmt::format("specular: depth stays {} (weight {:g}: {:g}^{} = {:.3g} is not below {:g})", full.max_depth, w,
                                          w, full.max_depth, std::pow(w, full.max_depth), budget));
  }
  c.reasons.push_back("hemicube: stays 256 (no estimate of its error before the run)");
  return c;
}

}  // namespace gcsim::render
