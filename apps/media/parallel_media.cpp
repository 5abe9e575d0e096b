#include "apps/media/parallel_media.hpp"

#include <algorithm>
#include <cstring>
#include <optional>

#include "apps/common/tile_farm.hpp"
#include "apps/media/frame.hpp"
#include "parix/collectives.hpp"
#include "parix/processor.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::media {
namespace {

std::size_t share_begin(std::size_t total, int node, int nodes) {
  return total * static_cast<std::size_t>(node) / static_cast<std::size_t>(nodes);
}

// The photon map of the gathered photons: the one another node built from the same photons, or a new one.
std::shared_ptr<const PhotonMap> photon_map_of(const parix::GatheredBytes& photons, std::shared_ptr<const PhotonMap>* shared) {
  if (shared && *shared && photons.same_as(std::as_bytes(std::span((*shared)->photons())))) return *shared;
  auto map = std::make_shared<const PhotonMap>(parix::concatenated<Photon>(photons));
  if (shared) *shared = map;
  return map;
}

// The same for the grid's gathered voxels over the region's photon map.
std::shared_ptr<const RadianceGrid> radiance_grid_of(const UniformGrid& grid, const parix::GatheredBytes& voxels,
                                                     const PhotonMap* map, MediaHostThreads::SharedRegion* shared) {
  if (shared && shared->grid && shared->map.get() == map && voxels.same_as(std::as_bytes(std::span(shared->grid->voxels()))))
    return shared->grid;
  auto built = std::make_shared<const RadianceGrid>(grid, parix::concatenated<ShCoefficients>(voxels));
  if (shared) shared->grid = built;
  return built;
}

// One region's photon map (replicated) and SH grid (each node builds a slice, then all-gather).
RegionCache build_region_parallel(parix::Processor& p, const std::vector<Photon>& mine,
                                  const HomogeneousMedium& medium, std::size_t k, std::uint64_t& photon_bytes,
                                  std::uint64_t& grid_bytes, std::vector<parix::MemoryReservation>& held,
                                  RenderCounters& counts, int jobs, MediaHostThreads::SharedRegion* shared) {
  RegionCache region;
  {  // the gathered packet goes before the grid's all-gather, where every node waits holding its own
    const parix::GatheredBytes photons = parix::allgather_views(p, std::as_bytes(std::span(mine)));
    const std::size_t gathered_bytes = photons.size();
    held.push_back(p.reserve_memory(std::int64_t(gathered_bytes), "photon map"));
    photon_bytes += gathered_bytes;
    if (gathered_bytes == 0) return region;
    region.map = photon_map_of(photons, shared ? &shared->map : nullptr);
  }
  const UniformGrid grid = grid_for_photons(region.map->photons(), k);
  const std::size_t voxels = grid.voxel_count();
  const std::size_t first = share_begin(voxels, p.id(), p.count()), last = share_begin(voxels, p.id() + 1, p.count());
  const parix::MemoryReservation slice_held =
      p.reserve_memory(std::int64_t((last - first) * sizeof(ShCoefficients)), "radiance grid slice");
  std::vector<ShCoefficients> my_voxels;
  {
    const parix::MemoryReservation projections_held =
        p.reserve_memory(std::int64_t(region.map->photons().size() * sizeof(ShCoefficients)), "photon SH projections");
    GridBuildCounts mine_built;
    my_voxels = build_voxel_range(grid, *region.map, medium, k, first, last, mine_built, jobs);
    const auto ops = grid_build_ops(mine_built);
    const double start = p.now_seconds();
    p.compute(std::span<const parix::OpCount>(ops));
    counts.grid_seconds += p.now_seconds() - start;
    counts.grid_build.add(mine_built);
  }
  held.push_back(p.reserve_memory(std::int64_t(voxels * sizeof(ShCoefficients)), "radiance grid"));
  const parix::GatheredBytes pieces = parix::allgather_views(p, std::as_bytes(std::span(my_voxels)));
  region.grid = radiance_grid_of(grid, pieces, region.map.get(), shared);
  grid_bytes += voxels * sizeof(ShCoefficients);
  return region;
}

// The image in kTileSize² tiles, row-major.
struct Tiling {
  int width, height;
  int across() const { return (width + kTileSize - 1) / kTileSize; }
  int count() const { return across() * ((height + kTileSize - 1) / kTileSize); }
  int x0(int t) const { return (t % across()) * kTileSize; }
  int y0(int t) const { return (t / across()) * kTileSize; }
  int x1(int t) const { return std::min(width, x0(t) + kTileSize); }
  int y1(int t) const { return std::min(height, y0(t) + kTileSize); }
};

// A mesh object's box-tree nodes and triangle tests; nothing for the sphere, so its runs keep their times.
void charge_boundary(parix::Processor& p, const BoundaryTally& t) {
  const auto ops = boundary_ops(t);
  if (!ops.empty()) p.compute(std::span<const parix::OpCount>(ops));
}

// Charges a tile's counted work; returns the simulated seconds it took.
double charge_render(parix::Processor& p, const RenderCounters& c, std::size_t k) {
  const double start = p.now_seconds();
  const auto ops = render_ops(c, k);
  p.compute(std::span<const parix::OpCount>(ops));
  charge_boundary(p, c.boundary);
  return p.now_seconds() - start;
}

// Tile t of the image: its pixels' luminance and what they counted.
PixelTile render_pixel_tile(const MediaScene& scene, const SceneCaches& caches, const MarchSettings& settings,
                            std::uint64_t seed, int t) {
  const Tiling tiling{scene.image.width, scene.image.height};
  PixelTile out;
  for (int y = tiling.y0(t); y < tiling.y1(t); ++y)
    for (int x = tiling.x0(t); x < tiling.x1(t); ++x)
      out.pixels.push_back(static_cast<float>(render_pixel(scene, caches, settings, seed, x, y, out.counters)));
  return out;
}

// Node 0, with host threads: workers that render the tiles ahead from node 0's caches, in the
// order the farm hands them out.
void start_workers(MediaHostThreads& host, const MediaScene& scene, const SceneCaches& caches,
                   const MarchSettings& settings, std::uint64_t seed, int tiles) {
  std::vector<apps::WorkAhead<PixelTile>::Compute> computes(std::size_t(host.workers), [&, tiles](int t) {
    return render_pixel_tile(scene, caches, settings, seed, t);
  });
  std::vector<int> order(static_cast<std::size_t>(tiles));
  for (int t = 0; t < tiles; ++t) order[std::size_t(t)] = t;
  host.ahead = std::make_unique<apps::WorkAhead<PixelTile>>(tiles, std::move(order), std::move(computes));
}

// The farm's settings for media: single tiles in index order, one int32 per assignment, stops
// once every result is in, tag 41; a record is [int32 tile][its pixels' luminance as floats].
constexpr int kTileTag = 41;

apps::TileFarmStats render_tiles(parix::Processor& p, const MediaScene& scene, const SceneCaches& caches,
                                 const MarchSettings& settings, std::uint64_t seed, apps::Image& image,
                                 std::vector<RenderCounters>& per_node, MediaHostThreads* host) {
  const Tiling tiling{scene.image.width, scene.image.height};
  const int tiles = tiling.count();
  apps::TileFarm farm{.tag = kTileTag, .format = apps::AssignmentFormat::single_tile, .stops = apps::StopTiming::at_end};
  // Node 0's workers read its caches: they stop when this returns, even on a cancelled run.
  struct StopWorkers {
    MediaHostThreads* host;
    ~StopWorkers() {
      if (!host || !host->ahead) return;
      host->tiles_by_workers = host->ahead->by_workers();
      host->ahead.reset();
    }
  } stop{p.id() == 0 ? host : nullptr};
  if (host && host->workers > 0 && p.id() == 0) start_workers(*host, scene, caches, settings, seed, tiles);
  int next = 0;
  farm.next_run = [&next, tiles]() -> std::optional<apps::TileRun> {
    if (next >= tiles) return std::nullopt;
    return apps::TileRun{next++, 1};
  };
  farm.render = [&](parix::Processor& q, int t) {
    const auto here = [&](int tile) { return render_pixel_tile(scene, caches, settings, seed, tile); };
    PixelTile r = host && host->ahead ? host->ahead->take(t, here) : here(t);
    r.counters.tile_seconds = charge_render(q, r.counters, scene.k_nearest);
    per_node[static_cast<std::size_t>(q.id())].add(r.counters);
    const std::int32_t tile = t;
    parix::Bytes record(sizeof tile + r.pixels.size() * sizeof(float));
    std::memcpy(record.data(), &tile, sizeof tile);
    if (!r.pixels.empty()) std::memcpy(record.data() + sizeof tile, r.pixels.data(), r.pixels.size() * sizeof(float));
    return record;
  };
  farm.assemble = [&](parix::Processor& q, std::span<const std::byte> record) {
    std::int32_t t;
    if (record.size() < sizeof t) throw parix::ParixError("media: truncated tile record");
    std::memcpy(&t, record.data(), sizeof t);
    if (t < 0 || t >= tiles) throw parix::ParixError("media: tile record names no tile");
    const std::span<const std::byte> pixels = record.subspan(sizeof t);
    const std::size_t expected =
        std::size_t(tiling.x1(t) - tiling.x0(t)) * std::size_t(tiling.y1(t) - tiling.y0(t)) * sizeof(float);
    if (pixels.size() != expected) throw parix::ParixError("media: tile record of the wrong size");
    const std::byte* at = pixels.data();
    for (int y = tiling.y0(t); y < tiling.y1(t); ++y)
      for (int x = tiling.x0(t); x < tiling.x1(t); ++x, at += sizeof(float)) {
        float v;
        std::memcpy(&v, at, sizeof v);
        image.at(x, y) = glm::vec3(v);
      }
    q.compute("memcpy_byte", static_cast<std::int64_t>(pixels.size()));
  };
  return apps::run_tile_farm(p, farm);  // on node 0: every tile is assembled, nothing is left to take
}

}  // namespace

void media_program(parix::Processor& p, const MediaScene& scene, const MarchSettings& settings, std::uint64_t seed,
                   ParallelMediaResult& result, std::vector<RenderCounters>& per_node, MediaHostThreads* host) {
  const int width = scene.image.width, height = scene.image.height;
  const int id = p.id(), nodes = p.count();
  // Host threads also trace this node's photons and build its grid slices (byte-identical results).
  const int jobs = host ? host->workers + 1 : 1;
  PhotonPassResult photons = trace_photons(scene, share_begin(scene.photons_emitted, id, nodes),
                                           share_begin(scene.photons_emitted, id + 1, nodes), jobs);
  p.compute("media_photon_step", static_cast<std::int64_t>(photons.flights + photons.surface_events));
  charge_boundary(p, photons.boundary);
  std::uint64_t photon_bytes = 0, grid_bytes = 0;
  const std::uint64_t my_photon_bytes = (photons.outside.size() + photons.inside.size()) * sizeof(Photon);
  SceneCaches caches;
  std::vector<parix::MemoryReservation> held;  // node memory of the photon maps and grids
  RenderCounters& built = per_node[static_cast<std::size_t>(p.id())];
  caches.outside =
      build_region_parallel(p, photons.outside, scene.outside, scene.k_nearest, photon_bytes, grid_bytes, held, built,
                            jobs, host ? &host->outside : nullptr);
  caches.inside =
      build_region_parallel(p, photons.inside, scene.inside, scene.k_nearest, photon_bytes, grid_bytes, held, built,
                            jobs, host ? &host->inside : nullptr);
  // Node 0 assembles the whole image; the others hold a tile at a time.
  const std::int64_t image_bytes = id == 0 ? std::int64_t(width) * height * std::int64_t(sizeof(glm::vec3)) : 0;
  const parix::MemoryReservation image_held = p.reserve_memory(image_bytes, "image");
  const apps::TileFarmStats farm = render_tiles(p, scene, caches, settings, seed, result.image, per_node, host);
  if (id != 0) return;
  result.tiles = static_cast<std::size_t>(Tiling{width, height}.count());
  result.tile_messages = farm.assignments;
  result.tile_result_bytes = farm.result_bytes;
  result.photon_bytes = my_photon_bytes;
  result.photon_bytes_all = photon_bytes;
  result.grid_bytes_all = grid_bytes;
  result.outside_photons = caches.outside.map ? caches.outside.map->photons().size() : 0;
  result.inside_photons = caches.inside.map ? caches.inside.map->photons().size() : 0;
  if (caches.outside.grid) result.outside_dims = caches.outside.grid->grid().dims;
  if (caches.inside.grid) result.inside_dims = caches.inside.grid->grid().dims;
}

ParallelMediaResult render_media_parallel(const MediaScene& scene, const MarchSettings& settings, std::uint64_t seed,
                                          const parix::SimulationOptions& sim, int host_threads) {
  ParallelMediaResult result;
  result.image = apps::Image(scene.image.width, scene.image.height);
  std::vector<RenderCounters> per_node(static_cast<std::size_t>(sim.config.nodes));
  MediaHostThreads host{host_threads - 1, nullptr, 0, {}, {}};
  result.run = parix::run_simulated(
      sim, [&](parix::Processor& p) { media_program(p, scene, settings, seed, result, per_node, &host); });
  result.tiles_by_workers = host.tiles_by_workers;
  for (const RenderCounters& c : per_node) result.counters.add(c);
  return result;
}

}  // namespace gcsim::media
