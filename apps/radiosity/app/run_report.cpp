// What `gcsim run radiosity` prints and writes after the run: table 4.2's loops, the loop CSV, the
// Gauss-Seidel check and the images.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>

#include "apps/common/image.hpp"
#include "machine/output_file.hpp"
#include "apps/radiosity/app/radiosity_experiment.hpp"
#include "apps/radiosity/gauss_seidel.hpp"
#include "apps/radiosity/gouraud_renderer.hpp"
#include "apps/radiosity/thesis_tables.hpp"

namespace gcsim::radiosity::app {

void print_loops_table(const ParallelOutcome& r, const std::string& scene_name, int shooters) {
  const thesis::SceneFigures* fig = thesis::figures_for(scene_name);
  fmt::print("\nloops to shoot a fraction of the energy (thesis table 4.2{})\n",
             shooters == 2 ? "" : "; the thesis used 2 shooters per loop");
  fmt::print("  {:>7}  {:>7}  {:>7}\n", "energy%", "loops", "thesis");
  for (std::size_t i = 0; i < thesis::kEnergyPercent.size(); ++i) {
    const double frac = thesis::kEnergyPercent[i] / 100;
    int loops = -1;
    for (const auto& s : r.steps)
      if (s.shot_fraction >= frac) {
        loops = s.step;
        break;
      }
    const std::string ours = loops < 0 ? "-" : fmt::format("{}", loops);
    const std::string theirs = fig && fig->loops_for_energy[i] >= 0 ? fmt::format("{}", fig->loops_for_energy[i]) : "-";
    fmt::print("  {:>7}  {:>7}  {:>7}\n", thesis::kEnergyPercent[i], ours, theirs);
  }
}

void write_steps_csv(const std::string& path, const ParallelOutcome& r) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write CSV file '" + path + "'");
  out << "step,shot_fraction,shooters\n";
  for (const auto& s : r.steps) {
    out << s.step << ',' << fmt::format("{:.9f}", s.shot_fraction) << ',';
    for (std::size_t k = 0; k < s.shooters.size(); ++k) out << (k ? " " : "") << s.shooters[k];
    out << '\n';
  }
  machine::close_checked(out, path, "CSV file");
}

double compare_with_gauss_seidel(const Scene& scene, const HemicubeOptions& hemicube, const ParallelOutcome& r) {
  const auto gs = solve_gauss_seidel(scene, hemicube);
  double worst = 0, mean = 0, area = 0;
  for (std::size_t e = 0; e < scene.elements.size(); ++e) {
    mean += channel_sum(gs.element_radiosity[e]) / 3 * scene.elements[e].area;
    area += scene.elements[e].area;
  }
  mean /= area;
  for (std::size_t e = 0; e < scene.elements.size(); ++e) {
    const Rgb d = glm::abs(r.element_radiosity[e] - gs.element_radiosity[e]);
    worst = std::max({worst, d.r, d.g, d.b});
  }
  fmt::print("gauss-seidel {} sweeps; largest element difference from progressive: {:.3g} ({:.3g}% of the mean)\n",
             gs.iterations, worst, mean > 0 ? 100 * worst / mean : 0.0);
  return worst;
}

namespace {

// The thesis's rooms were photographed at 4:3; other scenes are square.
int default_image_height(const Scene& scene) { return scene.name == "ROOM" || scene.name == "PICROOM" ? 384 : 512; }

}  // namespace

void write_images(const Scene& scene, const ParallelOutcome& r, const RunOutputs& o, const Camera& camera) {
  RenderOptions ro;
  ro.width = o.width > 0 ? o.width : 512;
  ro.height = o.height > 0 ? o.height : default_image_height(scene);
  ro.exposure = o.exposure;
  apps::write_png(o.image, render_gouraud(scene, r.element_radiosity, camera, ro));
  fmt::print("image     {}\n", o.image);
  if (r.snapshots.empty()) return;
  // Same exposure as the final image, so that the images show light arriving.
  if (ro.exposure <= 0) ro.exposure = auto_exposure(scene, r.element_radiosity, camera, ro);
  for (const auto& [loop, b] : r.snapshots) {
    const std::string p = snapshot_path(o.image, loop);
    apps::write_png(p, render_gouraud(scene, b, camera, ro));
    fmt::print("snapshot  {} (after loop {})\n", p, loop);
  }
}

std::string snapshot_path(const std::string& image, int loop) {
  const std::filesystem::path base(image);
  return (base.parent_path() / fmt::format("{}_loop{}{}", base.stem().string(), loop, base.extension().string())).string();
}

}  // namespace gcsim::radiosity::app
