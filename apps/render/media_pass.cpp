#include "apps/render/media_pass.hpp"

#include <algorithm>
#include <optional>
#include <span>

#include "apps/common/media/grid_build_ops.hpp"
#include "parix/collectives.hpp"

namespace gcsim::render {
namespace {

std::size_t share_begin(std::size_t total, int node, int nodes) {
  return total * std::size_t(node) / std::size_t(nodes);
}

std::uint64_t share(std::uint64_t total, int node, int nodes) {
  return share_begin(total, node + 1, nodes) - share_begin(total, node, nodes);
}

}  // namespace

std::unique_ptr<MediaSetup> make_media_setup(const SplitScene& split, raytrace::Scene lowered, std::vector<MediumRegion> regions,
                                             bool photon_pass, bool radiance_estimate, std::size_t photons) {
  auto s = std::make_unique<MediaSetup>();
  s->regions = std::move(regions);
  s->photon_pass = photon_pass;
  s->photons = photons;
  s->view.radiance_estimate = radiance_estimate;
  if (!photon_pass) return s;
  s->surfaces = std::move(lowered);
  s->bvh = geometry::build_bvh_by_clustering(s->surfaces);
  s->lights = photon_lights(split.surfaces);
  s->view.light_chroma = s->lights.chroma;
  return s;
}

namespace {

// This node's share of the photons, with what they deposit on the walls when there are walls.
VolumePhotons trace_share(parix::Processor& p, const MediaSetup& s, std::optional<DepositSums>& sums,
                          geometry::TestTally& lookups, const PhotonsTraced& on_traced, int host_threads) {
  const std::size_t first = share_begin(s.photons, p.id(), p.count());
  const std::size_t end = share_begin(s.photons, p.id() + 1, p.count());
  const std::size_t last = s.traced > 0 ? std::min<std::size_t>(end, first + share(s.traced, p.id(), p.count())) : end;
  WallHit on_wall;
  if (s.walls) {
    DepositSums& d = sums.emplace(s.walls->element_count(), s.lights.total_flux / double(s.photons));
    on_wall = [&](const glm::dvec3& origin, const glm::dvec3& direction, const glm::dvec3& power) {
      const int e = s.walls->find(origin, direction, lookups);
      if (e < 0) ++d.missed;
      else d.add(e, power);
    };
  }
  return trace_volume_photons(s.surfaces, s.bvh, s.lights, s.regions, first, last, s.photons, s.seed, on_wall, on_traced,
                              host_threads);
}

}  // namespace

GatheredPhotons photon_pass(parix::Processor& p, const MediaSetup& s, const PhotonsTraced& on_traced, int host_threads) {
  GatheredPhotons out;
  out.per_region.resize(s.regions.size());
  if (!s.photon_pass) return out;
  std::optional<DepositSums> sums;
  geometry::TestTally lookups;  // the element lookups' tests
  const VolumePhotons mine = trace_share(p, s, sums, lookups, on_traced, host_threads);
  out.flights = mine.flights, out.surface_events = mine.surface_events, out.media_absorbed = mine.media_absorbed;
  const parix::OpCount ops[] = {{"media_photon_step", std::int64_t(mine.flights + mine.surface_events)},
                                {"ray_box", mine.tests.boxes + lookups.boxes},
                                {"ray_triangle", mine.tests.triangles + lookups.triangles},
                                {"ray_sphere", mine.tests.spheres},
                                {"photon_deposit", sums ? std::int64_t(sums->deposits) : 0}};
  p.compute(std::span<const parix::OpCount>(ops));
  for (std::size_t r = 0; r < s.regions.size(); ++r) {
    for (auto& part : parix::allgather_vectors<media::Photon>(p, std::span<const media::Photon>(mine.per_region[r])))
      out.per_region[r].insert(out.per_region[r].end(), part.begin(), part.end());
    out.held.push_back(p.reserve_memory(std::int64_t(out.per_region[r].size() * sizeof(media::Photon)), "photon map"));
  }
  if (sums) {
    const DepositSums all = all_reduce(p, std::move(*sums));
    out.wall_power = all.power();
    out.wall_deposits = all.deposits, out.wall_missed = all.missed;
  }
  return out;
}

void charge_grid_share(parix::Processor& p, const media::GridBuildCounts& all) {
  const int id = p.id(), n = p.count();
  media::GridBuildCounts mine;
  mine.knn_queries = share(all.knn_queries, id, n), mine.knn_photons = share(all.knn_photons, id, n);
  mine.range_queries = share(all.range_queries, id, n), mine.range_candidates = share(all.range_candidates, id, n);
  mine.projections = share(all.projections, id, n), mine.photon_adds = share(all.photon_adds, id, n);
  const auto ops = media::grid_build_ops(mine);
  p.compute(std::span<const parix::OpCount>(ops));
}

}  // namespace gcsim::render
