#include "apps/render/error_budget.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "apps/common/scene/description_to_world.hpp"
#include "apps/radiosity/scene.hpp"

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

}  // namespace

BudgetChoice controls_for_budget(const scene::SceneDescription& d, const Plan& plan, double budget) {
  if (!(budget > 0 && budget < 1))
    throw std::invalid_argument(fmt::format("--error-budget {}: expected a relative error between 0 and 1 (e.g. 0.02)", budget));
  BudgetChoice c;
  const RenderControls full;
  if (plan.pass(PassId::radiosity).on) {
    // Unshot energy U would still reach the surfaces as U (1 + rho + rho^2 + ...) = U / (1 - rho)
    // with rho the area-weighted mean reflectance: stop when that is below the budget.
    const double rho = mean_reflectance(radiosity::flatten(scene::to_world(d)));
    c.controls.energy = std::clamp(1.0 - budget * (1.0 - rho), 0.5, full.energy);
    c.reasons.push_back(fmt::format("radiosity: shoots {:.4g} % of the energy instead of {:g} % (unshot energy U still "
                                    "brings U / (1 - {:.3f}) with the mean reflectance {:.3f})",
                                    100 * c.controls.energy, 100 * full.energy, rho, rho));
  }
  if (plan.pass(PassId::specular).on) {
    double w = 0;
    for (const scene::Material& m : d.materials) w = std::max({w, m.mirror, m.transmittance});
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
