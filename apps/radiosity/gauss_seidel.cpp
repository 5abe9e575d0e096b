#include "apps/radiosity/gauss_seidel.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "parix/host/interruption.hpp"

namespace gcsim::radiosity {

GaussSeidelResult solve_gauss_seidel(const Scene& scene, const HemicubeOptions& hc, double tolerance,
                                     int max_iterations, std::size_t max_entries) {
  const std::size_t np = scene.patches.size(), ne = scene.elements.size();
  if (np * ne > max_entries)
    throw std::invalid_argument(fmt::format(
        "Gauss-Seidel needs the full {} x {} form factor matrix; that is over the limit of {} entries", np, ne,
        max_entries));
  HemicubeRenderer renderer(scene, hc);
  OpCounts ops;
  std::vector<std::vector<double>> f(np);  // f[q][e] = F(q -> e)
  for (std::size_t q = 0; q < np; ++q) {
    // A plain loop outside the simulated machine: it polls SIGINT/SIGTERM itself (one hemicube apart).
    parix::host::throw_if_interrupted();
    f[q] = renderer.form_factor_row(int(q), ops);
  }
  // K[p][q] = rho_p F_qp A_q / A_p (rho applied per channel below).
  std::vector<double> k(np * np, 0.0);
  for (std::size_t q = 0; q < np; ++q)
    for (std::size_t e = 0; e < ne; ++e) {
      if (f[q][e] == 0) continue;
      std::size_t p = scene.elements[e].patch;
      k[p * np + q] += f[q][e] * scene.patches[q].area / scene.patches[p].area;
    }
  GaussSeidelResult r;
  r.patch_radiosity.assign(np, Rgb(0.0));
  std::vector<Rgb> emit(np);
  for (std::size_t p = 0; p < np; ++p) r.patch_radiosity[p] = emit[p] = scene.surfaces[scene.patches[p].surface].exitance;
  for (r.iterations = 1; r.iterations <= max_iterations; ++r.iterations) {
    r.max_change = 0;
    for (std::size_t p = 0; p < np; ++p) {
      Rgb gathered(0.0);
      for (std::size_t q = 0; q < np; ++q)
        if (k[p * np + q] != 0) gathered += k[p * np + q] * r.patch_radiosity[q];
      Rgb b = emit[p] + scene.surfaces[scene.patches[p].surface].reflectance * gathered;
      Rgb d = glm::abs(b - r.patch_radiosity[p]);
      r.max_change = std::max({r.max_change, d.r, d.g, d.b});
      r.patch_radiosity[p] = b;
    }
    if (r.max_change <= tolerance) break;
  }
  r.element_radiosity.assign(ne, Rgb(0.0));
  for (std::size_t e = 0; e < ne; ++e) {
    const SceneElement& el = scene.elements[e];
    Rgb gathered(0.0);
    for (std::size_t q = 0; q < np; ++q)
      if (f[q][e] != 0) gathered += f[q][e] * scene.patches[q].area / el.area * r.patch_radiosity[q];
    const Surface& s = scene.surface_of_element(int(e));
    r.element_radiosity[e] = s.exitance + s.reflectance * gathered;
  }
  return r;
}

}  // namespace gcsim::radiosity
