#include "apps/media/parallel_media.hpp"

#include <cstring>

#include "parix/collectives.hpp"
#include "parix/processor.hpp"

namespace gcsim::media {
namespace {

std::size_t share_begin(std::size_t total, int node, int nodes) {
  return total * static_cast<std::size_t>(node) / static_cast<std::size_t>(nodes);
}

template <class T>
std::vector<T> concatenate(const std::vector<std::vector<T>>& parts) {
  std::vector<T> all;
  for (const auto& part : parts) all.insert(all.end(), part.begin(), part.end());
  return all;
}

// One region's photon map (replicated) and SH grid (each node builds a slice, then all-gather).
RegionCache build_region_parallel(parix::Processor& p, const std::vector<Photon>& mine,
                                  const HomogeneousMedium& medium, std::size_t k, std::uint64_t& photon_bytes,
                                  std::uint64_t& grid_bytes, std::vector<parix::MemoryReservation>& held) {
  const auto parts = parix::allgather_vectors<Photon>(p, std::span<const Photon>(mine));
  std::size_t photons = 0;
  for (const auto& part : parts) photons += part.size();
  held.push_back(p.reserve_memory(std::int64_t(photons * sizeof(Photon)), "photon map"));
  std::vector<Photon> all = concatenate(parts);
  photon_bytes += all.size() * sizeof(Photon);
  RegionCache region;
  if (all.empty()) return region;
  const UniformGrid grid = grid_for_photons(all, k);
  region.map = std::make_unique<PhotonMap>(std::move(all));
  const std::size_t voxels = grid.voxel_count();
  const std::size_t first = share_begin(voxels, p.id(), p.count()), last = share_begin(voxels, p.id() + 1, p.count());
  held.push_back(p.reserve_memory(std::int64_t(voxels * sizeof(ShCoefficients)), "radiance grid"));
  const parix::MemoryReservation slice_held = p.reserve_memory(std::int64_t(voxels * sizeof(ShCoefficients)), "radiance grid slice");
  RadianceGrid slice(grid, *region.map, medium, k, first, last);
  p.compute({{"media_knn_lookup", static_cast<std::int64_t>(last - first)},
             {"media_knn_photon", static_cast<std::int64_t>(slice.photon_adds())},
             {"media_sh_add", static_cast<std::int64_t>(slice.photon_adds())}});
  std::vector<ShCoefficients> my_voxels(slice.voxels().begin() + first, slice.voxels().begin() + last);
  region.grid = std::make_unique<RadianceGrid>(grid);
  region.grid->voxels() = concatenate(parix::allgather_vectors<ShCoefficients>(p, std::span<const ShCoefficients>(my_voxels)));
  grid_bytes += voxels * sizeof(ShCoefficients);
  return region;
}

void charge_render(parix::Processor& p, const RenderCounters& c, std::size_t k) {
  p.compute({{"media_camera_ray", static_cast<std::int64_t>(c.pixels + c.surface_events)},
             {"media_march_sample", static_cast<std::int64_t>(c.march.samples)},
             {"media_knn_lookup", static_cast<std::int64_t>(c.march.samples)},
             {"media_knn_photon", static_cast<std::int64_t>(c.march.samples * k)},
             {"media_sh_eval", static_cast<std::int64_t>(c.march.sh_evals)}});
}

}  // namespace

void media_program(parix::Processor& p, const MediaScene& scene, const MarchSettings& settings, std::uint64_t seed,
                   ParallelMediaResult& result, std::vector<RenderCounters>& per_node) {
    const int width = scene.camera.width, height = scene.camera.height;
    const int id = p.id(), nodes = p.count();
    PhotonPassResult photons = trace_photons(scene, share_begin(scene.photons_emitted, id, nodes),
                                             share_begin(scene.photons_emitted, id + 1, nodes));
    p.compute("media_photon_step", static_cast<std::int64_t>(photons.flights + photons.surface_events));
    std::uint64_t photon_bytes = 0, grid_bytes = 0;
    const std::uint64_t my_photon_bytes = (photons.outside.size() + photons.inside.size()) * sizeof(Photon);
    SceneCaches caches;
    std::vector<parix::MemoryReservation> held;  // node memory of the photon maps and grids
    caches.outside = build_region_parallel(p, photons.outside, scene.outside, scene.k_nearest, photon_bytes, grid_bytes, held);
    caches.inside = build_region_parallel(p, photons.inside, scene.inside, scene.k_nearest, photon_bytes, grid_bytes, held);
    // Rows interleaved: row y on node y mod N, each pixel on its own random stream.
    const parix::MemoryReservation image_held = p.reserve_memory(std::int64_t(width) * height * sizeof(glm::vec3), "image");
    apps::Image local(width, height);
    RenderCounters counters;
    std::vector<float> rows;
    for (int y = id; y < height; y += nodes) {
      render_rows(scene, caches, settings, seed, y, y + 1, local, counters);
      for (int x = 0; x < width; ++x) rows.push_back(local.at(x, y).x);
    }
    charge_render(p, counters, scene.k_nearest);
    per_node[static_cast<std::size_t>(id)] = counters;
    auto gathered = parix::gather(p, 0, std::as_bytes(std::span<const float>(rows)));
    if (id != 0) return;
    for (int node = 0; node < nodes; ++node) {
      const auto& bytes = gathered[static_cast<std::size_t>(node)];
      std::vector<float> values(bytes.size() / sizeof(float));
      std::memcpy(values.data(), bytes.data(), bytes.size());
      std::size_t i = 0;
      for (int y = node; y < height; y += nodes)
        for (int x = 0; x < width; ++x) result.image.at(x, y) = glm::vec3(values[i++]);
    }
    result.photon_bytes = my_photon_bytes;
    result.photon_bytes_all = photon_bytes;
    result.grid_bytes_all = grid_bytes;
    result.outside_photons = caches.outside.map ? caches.outside.map->photons().size() : 0;
    result.inside_photons = caches.inside.map ? caches.inside.map->photons().size() : 0;
    if (caches.outside.grid) result.outside_dims = caches.outside.grid->grid().dims;
    if (caches.inside.grid) result.inside_dims = caches.inside.grid->grid().dims;
}

ParallelMediaResult render_media_parallel(const MediaScene& scene, const MarchSettings& settings, std::uint64_t seed,
                                          const parix::SimulationOptions& sim) {
  ParallelMediaResult result;
  result.image = apps::Image(scene.camera.width, scene.camera.height);
  std::vector<RenderCounters> per_node(static_cast<std::size_t>(sim.nodes));
  result.run = parix::run_simulated(
      sim, [&](parix::Processor& p) { media_program(p, scene, settings, seed, result, per_node); });
  for (const RenderCounters& c : per_node) result.counters.add(c);
  return result;
}

}  // namespace gcsim::media
