#pragma once
// The media pass of the unified renderer on the simulated nodes: each node traces its share of the
// photons through the scene's surfaces and media (volume_photons.hpp), charged at the machine's
// `[ops]` cycles, then all nodes exchange them (parix all-gather), so every node holds the whole
// photon map for its tiles of the view. Its SH grids (anisotropic media) are built once on the
// host and each node is charged its slice of that work, as the media app's nodes build theirs.
// With a radiosity pass, the pass also sums what the media scatter onto the walls (wall_deposits.hpp)
// over the nodes, for radiosity to carry on: it runs before the radiosity pass.
#include <cstdint>
#include <memory>
#include <vector>

#include "apps/common/geometry/bvh.hpp"
#include "apps/common/media/photon_map.hpp"
#include "apps/common/media/radiance_grid.hpp"
#include "apps/raytrace/raytrace.hpp"
#include "apps/render/medium_region.hpp"
#include "apps/render/view_medium.hpp"
#include "apps/render/volume_photons.hpp"
#include "apps/render/wall_deposits.hpp"
#include "parix/processor.hpp"

namespace gcsim::render {

// What the media pass and the view's media need, built once before the run.
struct MediaSetup {
  std::vector<MediumRegion> regions;
  bool photon_pass = false;       // the plan's media pass (or --force-pass media)
  std::size_t photons = 20000;    // emitted, over all nodes
  // Photons actually traced, over all nodes (0: all): `gcsim plan`'s sample. Each node traces the
  // first of its share, the very photons a full pass traces, at the same power each.
  std::size_t traced = 0;
  std::uint64_t seed = 1;
  raytrace::Scene surfaces;       // what photons bounce off: the lowered scene without the media's bounds
  geometry::Bvh bvh;
  PhotonLights lights;
  ViewMediumSettings view;        // display_scale is set by the view pass (it knows the exposure)
  std::unique_ptr<ElementLookup> walls;  // the radiosity elements photons deposit on (null: no radiosity pass)
};

// lowered: raytrace::lower_scene(split.surfaces); regions: the media the view applies; photon_pass:
// whether photons are traced.
std::unique_ptr<MediaSetup> make_media_setup(const SplitScene& split, raytrace::Scene lowered, std::vector<MediumRegion> regions,
                                             bool photon_pass, bool radiance_estimate, std::size_t photons);

struct GatheredPhotons {
  std::vector<std::vector<media::Photon>> per_region;  // everybody's, in node order
  std::uint64_t flights = 0, surface_events = 0;       // this node's
  std::vector<parix::MemoryReservation> held;          // the photon map's node memory
  // With MediaSetup::walls: the power the media scattered onto each radiosity element, summed over
  // every node (identical on all; empty without walls), and the hits over all nodes.
  std::vector<radiosity::Rgb> wall_power;
  std::uint64_t wall_deposits = 0, wall_missed = 0;
  double media_absorbed = 0.0;  // this node's photons' luminance power absorbed in the media
};

// On every node: its share of the photons, charged, then the all-gather. on_traced: host-side
// progress, the photons this node traced (nothing of it is simulated).
// host_threads: how many host threads trace the node's share (the same photons on any number).
GatheredPhotons photon_pass(parix::Processor& p, const MediaSetup& s, const PhotonsTraced& on_traced = {},
                            int host_threads = 1);

// This node's slice of the SH grids' construction (all: the whole grids' counts).
void charge_grid_share(parix::Processor& p, const media::GridBuildCounts& all);

}  // namespace gcsim::render
