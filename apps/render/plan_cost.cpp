#include "apps/render/plan_cost.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gcsim::render {

namespace {

class Ops {
 public:
  explicit Ops(const machine::MachineConfig& m) : m_(m) {}
  double operator()(const char* op) const {
    auto it = m_.cycles_per_op.find(op);
    if (it == m_.cycles_per_op.end())
      throw std::invalid_argument("machine '" + m_.name + "' has no cost for operation '" + op + "' in [ops]");
    return it->second;
  }

 private:
  const machine::MachineConfig& m_;
};

// A ray's traversal of the box tree: about two box tests per level and a few primitive tests.
double traversal_cycles(const Ops& op, const SceneFacts& f) {
  const double levels = std::log2(double(std::max(f.primitives, 1)) + 1.0);
  return 2.0 * levels * op("ray_box") + 4.0 * op("ray_triangle");
}

PassCost radiosity(const Ops& op, const SceneFacts& f, int nodes, const CostModel& m) {
  // Hemicube-fixed (4.3): every node projects all elements and Z-buffers its share of the 3 R^2
  // cells, sums its form factors, and updates every element of its replica.
  const double cells = 3.0 * m.hemicube_resolution * m.hemicube_resolution;
  const double per_shot = f.elements * (op("polygon_project") + op("element_update")) +
                          cells / nodes * (op("hemicube_pixel") + op("form_factor_sum")) + f.patches * op("patch_select");
  PassCost c;
  c.seconds_per_node = m.shots_per_patch * f.patches * per_shot;
  // A replica of the mesh (vertices, patches, elements with their radiosities) and the cell buffer.
  c.bytes_per_node = std::int64_t(f.elements) * 160 + std::int64_t(f.patches) * 120 + std::int64_t(cells / nodes) * 8;
  return c;
}

// Rays split evenly; the scene and its box tree replicated on every node.
PassCost rays(double rays_total, double cycles_per_ray, const SceneFacts& f, int nodes, std::int64_t extra_bytes) {
  PassCost c;
  c.seconds_per_node = rays_total / nodes * cycles_per_ray;
  c.bytes_per_node = std::int64_t(f.primitives) * (64 + 2 * 32) + extra_bytes;
  return c;
}

PassCost media(const Ops& op, const SceneFacts& f, int nodes, const CostModel& m) {
  // Photon pass: each photon scatters about 1 / (1 - albedo) times; then every camera ray marches.
  const double events = std::min<double>(m.max_photon_events, 1.0 / std::max(1e-3, 1.0 - f.largest_albedo));
  const bool estimate = f.media_sampling == MediaSampling::radiance_estimate;
  // The SH grid (apps/media/radiance_grid.hpp): n k = a N voxel-photon pairs, a = 125 (eq. 13); each
  // pair is about 1.9 photons returned by the voxel's bounded radius search (measured on exp1) and
  // one accumulation, and each photon is projected once.
  constexpr double kVoxelsPerPhoton = 125.0, kCandidatesPerPair = 1.9;
  const double grid_cycles = op("media_sh_project") +
                             kVoxelsPerPhoton * (op("media_sh_accumulate") + kCandidatesPerPair * op("media_range_candidate"));
  const double photon_cycles = op("media_photon_step") + (estimate ? grid_cycles : 0.0);
  // Every sample reads Li from the photon map (k nearest); the radiance estimate also reconstructs
  // the SH histogram along the segment (about one bin per sample).
  const double per_sample = op("media_march_sample") + op("media_knn_lookup") + m.k_nearest * op("media_knn_photon") +
                            (estimate ? op("media_sh_eval") : 0.0);
  const double camera_rays = double(f.pixels) * f.samples_per_pixel;
  PassCost c;
  c.seconds_per_node = (m.photons * events * photon_cycles + camera_rays * (op("media_camera_ray") + m.march_samples * f.media_opacity * per_sample)) / nodes;
  c.bytes_per_node = std::int64_t(m.photons * events) * 32;  // the photon map, replicated
  return c;
}

}  // namespace

double expected_loops(const SceneFacts& f, const CostModel& m) {
  if (m.radiosity_loops > 0) return m.radiosity_loops;
  return std::ceil(m.shots_per_patch * f.patches / std::max(m.shooters_per_loop, 1));
}

PassCost estimate_pass(const PassPlan& pass, const SceneFacts& f, const machine::MachineConfig& machine, int nodes,
                       const CostModel& m) {
  if (!pass.on) return {};
  const Ops op(machine);
  nodes = std::max(nodes, 1);
  const double camera_rays = double(f.pixels) * f.samples_per_pixel;
  const double trace = traversal_cycles(op, f);
  PassCost c;
  if (m.view_sampled && measured_by_view_sample(pass.id)) {
    const double s = pass.id == PassId::view ? m.view_seconds : pass.id == PassId::specular ? m.specular_seconds : m.shadow_seconds;
    return {s, m.view_bytes};  // measured: one pass on the machine, its scene and tree held once
  }
  switch (pass.id) {
    case PassId::view:
      c = rays(camera_rays, op("rt_camera_ray") + trace + op("rt_shade"), f, nodes, f.pixels * 12 / nodes);
      break;
    case PassId::radiosity:
      c = radiosity(op, f, nodes, m);
      if (m.radiosity_seconds_per_loop > 0) {  // measured: no cycles to convert
        c.seconds_per_node = m.radiosity_seconds_per_loop * expected_loops(f, m);
        return c;
      }
      break;
    case PassId::specular:
      c = rays(camera_rays * m.specular_depth, op("rt_secondary_ray") + trace + op("rt_shade"), f, nodes, 0);
      break;
    case PassId::media:
      if (m.media_seconds > 0) return {m.media_seconds, m.media_bytes};  // measured
      c = media(op, f, nodes, m);
      break;
    case PassId::shadows: {
      const int lights = f.point_lights + f.emitters;
      c = rays(camera_rays * lights, op("rt_secondary_ray") + trace, f, nodes, 0);
      break;
    }
  }
  c.seconds_per_node /= machine.clock_hz;
  return c;
}

double sampled_fraction_uncertainty(double sampled) {
  if (!(sampled < 1)) return 0;
  return 0.085 * std::sqrt((1 - std::max(sampled, 0.0)) / 0.75);
}

double pass_uncertainty(PassId id, const CostModel& m) {
  if (id == PassId::radiosity) return m.radiosity_seconds_per_loop > 0 ? m.radiosity_uncertainty : 0;
  if (id == PassId::media) return m.media_seconds > 0 ? m.media_uncertainty : 0;
  return m.view_sampled ? m.view_uncertainty : 0;
}

std::int64_t pass_bytes_per_node(const PassPlan& pass, const SceneFacts& f, const machine::MachineConfig& machine,
                                 int nodes, const CostModel& m) {
  if (pass.id == PassId::radiosity && pass.on && m.radiosity_peak_bytes > 0) return m.radiosity_peak_bytes;
  return estimate_pass(pass, f, machine, nodes, m).bytes_per_node;
}

PeakMemory predicted_peak(const Plan& plan, const machine::MachineConfig& machine, int nodes, const CostModel& m) {
  auto bytes = [&](PassId id) { return pass_bytes_per_node(plan.pass(id), plan.facts, machine, nodes, m); };
  const std::int64_t media = bytes(PassId::media);
  PeakMemory p;
  p.bytes = media + std::max(bytes(PassId::radiosity), bytes(PassId::view));
  if (p.bytes > 0) p.uncertainty = double(media) / double(p.bytes) * m.media_uncertainty;
  return p;
}

}  // namespace gcsim::render
