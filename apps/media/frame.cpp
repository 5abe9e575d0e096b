#include "apps/media/frame.hpp"

#include <chrono>
#include <stdexcept>
#include <string>

#include "parix/host/interruption.hpp"

namespace gcsim::media {
namespace {

double cycles(const machine::MachineConfig& m, const std::string& op) {
  auto it = m.cycles_per_op.find(op);
  if (it == m.cycles_per_op.end())
    throw std::invalid_argument("machine file '" + m.source + "': no [ops] cost for '" + op + "'");
  return it->second;
}

double ops_cycles(const std::vector<parix::OpCount>& ops, const machine::MachineConfig& m) {
  double total = 0.0;
  for (const parix::OpCount& op : ops) total += double(op.count) * cycles(m, std::string(op.op));
  return total;
}

}  // namespace

std::vector<parix::OpCount> render_ops(const RenderCounters& c, std::size_t k) {
  auto n = [](std::uint64_t v) { return static_cast<std::int64_t>(v); };
  return {{"media_camera_ray", n(c.pixels + c.surface_events)},
          {"media_march_sample", n(c.march.samples)},
          {"media_knn_lookup", n(c.march.samples)},  // each sample's Li is a k-NN estimate
          {"media_knn_photon", n(c.march.samples * k)},
          {"media_sh_eval", n(c.march.sh_evals)}};
}

std::vector<parix::OpCount> boundary_ops(const BoundaryTally& t) {
  // The analytic sphere: its test is part of media_camera_ray and media_photon_step, and the mesh
  // ops are not even read, so sphere runs need not list them.
  if (!t.any()) return {};
  return {{"media_bvh_node", static_cast<std::int64_t>(t.node_tests)},
          {"media_triangle_test", static_cast<std::int64_t>(t.triangle_tests)}};
}

double render_seconds(const RenderCounters& c, std::size_t k, const machine::MachineConfig& m) {
  return (ops_cycles(render_ops(c, k), m) + ops_cycles(boundary_ops(c.boundary), m)) / m.clock_hz;
}

double grid_build_seconds(const GridBuildCounts& c, const machine::MachineConfig& m) {
  return ops_cycles(grid_build_ops(c), m) / m.clock_hz;
}

Frame render_frame(const MediaScene& scene, const SceneCaches& caches, const MarchSettings& settings,
                   std::uint64_t seed, const machine::MachineConfig& m, int stride) {
  const auto start = std::chrono::steady_clock::now();
  Frame f;
  f.image = apps::Image(scene.image.width, scene.image.height);
  for (int y = 0; y < scene.image.height; y += stride) {
    // Renders on the host, outside the simulated machine: SIGINT/SIGTERM is polled here, a row apart.
    parix::host::throw_if_interrupted();
    for (int x = 0; x < scene.image.width; x += stride)
      f.image.at(x, y) = glm::vec3(static_cast<float>(render_pixel(scene, caches, settings, seed, x, y, f.counters)));
  }
  f.simulated_seconds = render_seconds(f.counters, scene.k_nearest, m);
  f.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return f;
}

}  // namespace gcsim::media
