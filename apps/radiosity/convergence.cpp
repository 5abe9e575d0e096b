#include "apps/radiosity/convergence.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "apps/radiosity/op_counts.hpp"

namespace gcsim::radiosity {

void check_energy_can_be_absorbed(const Scene& scene, const HemicubeOptions& hemicube) {
  static const char* const kChannel[] = {"red", "green", "blue"};
  for (int k = 0; k < 3; ++k) {
    int brightest = -1, lossless_surface = -1;
    double most = 0;
    bool absorbs = false;
    for (std::size_t p = 0; p < scene.patches.size(); ++p) {
      const Surface& s = scene.surfaces[scene.patches[p].surface];
      if (s.reflectance[k] < 1) absorbs = true;
      else if (lossless_surface < 0) lossless_surface = scene.patches[p].surface;
      const double emitted = s.exitance[k] * scene.patches[p].area;
      if (emitted > most) most = emitted, brightest = int(p);
    }
    if (absorbs || brightest < 0) continue;
    // Every surface is lossless in this channel: only an opening can take light away.
    HemicubeRenderer renderer(scene, hemicube);
    OpCounts ops;
    double caught = 0;
    for (double f : renderer.form_factor_row(brightest, ops)) caught += f;
    if (caught < 1 - 1e-9) continue;
    throw std::invalid_argument(fmt::format(
        "surface {} of scene '{}' has reflectance 1 in {}, as every surface of this closed scene does: no light is "
        "ever absorbed or escapes, so progressive refinement would never shoot the required share of the energy; "
        "give the surfaces a reflectance below 1 (e.g. 0.99)",
        lossless_surface, scene.name, kChannel[k]));
  }
}

std::optional<std::string> convergence_failure(bool converged, double shot_fraction, double threshold, int steps,
                                               int max_steps) {
  if (converged) return std::nullopt;
  if (steps >= max_steps)
    return fmt::format("stopped at the step limit ({} steps) with {:.4f}% of the energy shot, below the threshold "
                       "{:.4f}%; the radiosities are not converged (raise --max-steps, or lower --energy)",
                       max_steps, 100 * shot_fraction, 100 * threshold);
  return fmt::format("stopped after {} steps with {:.4f}% of the energy shot, below the threshold {:.4f}%: no patch "
                     "had energy left to shoot",
                     steps, 100 * shot_fraction, 100 * threshold);
}

}  // namespace gcsim::radiosity
