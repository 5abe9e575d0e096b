#pragma once
// The per-processor program of the unified renderer: the passes of the plan that run, one after
// the other on every node. First the media pass's photons (media_pass.hpp): they do not depend on
// radiosity, and what they find the media scatter onto the walls is light the radiosity pass
// receives before it starts (wall_deposits.hpp). Then the radiosity pass (the thesis's parallel
// progressive refinement, the radiosity app's own program), the SH grid's share, then the view
// pass (view_pass.hpp).
#include <functional>
#include <memory>
#include <vector>

#include "apps/common/scene/scene_description.hpp"
#include "apps/radiosity/radiosity.hpp"
#include "apps/render/view_pass.hpp"
#include "parix/processor.hpp"

namespace gcsim::render {

struct UnifiedRender {
  radiosity::ParallelOutcome radiosity;  // node 0's replica (empty without a radiosity pass)
  // Built on the host by the first node whose radiosity pass ends: every replica holds the same
  // radiosities bit for bit, so which node does not matter; under MPI each rank builds its own.
  std::unique_ptr<ViewPass> view;
  std::vector<double> radiosity_end_s;   // per node (its own slot): when its radiosity pass ended
  std::vector<double> media_end_s;       // per node: when its photons (tracing, exchanges) ended
  std::vector<double> view_start_s;      // per node: when its view pass started (after the SH grid's share)
  std::uint64_t photon_flights = 0, photon_surface_events = 0;  // summed over the nodes
  double media_absorbed = 0.0;           // the photons' luminance power absorbed in the media, summed
  // What the media scattered onto the radiosity elements (identical on every node; empty without a
  // radiosity pass or photons), and the hits that found an element or none.
  std::vector<radiosity::Rgb> wall_power;
  std::uint64_t wall_deposits = 0, wall_missed = 0;
  // Host-side progress of the view pass (tiles rendered, of all): nothing of it is simulated.
  std::function<void(int done, int total)> on_view_tile;
  // Host-side progress of the media pass: photons traced so far over every node, of all emitted.
  std::function<void(std::uint64_t traced, std::uint64_t total)> on_photons;
  std::uint64_t photons_traced = 0;  // host-side, for on_photons

  explicit UnifiedRender(int nodes)
      : radiosity_end_s(std::size_t(nodes), 0.0), media_end_s(std::size_t(nodes), 0.0), view_start_s(std::size_t(nodes), 0.0) {}
  double radiosity_seconds() const;      // the last node's end of the radiosity pass
  double media_seconds() const;          // the last node's end of the photons
  double view_start_seconds() const;     // the last node's start of the view pass
};

// mesh: radiosity::flatten(to_world(description)), or nullptr when the plan skips radiosity.
// description: without the media's bounding shapes (split_media); media: null without media.
void unified_render_program(parix::Processor& p, const scene::SceneDescription& description,
                            const radiosity::Scene* mesh, const radiosity::ParallelOptions& options, ViewSettings view,
                            const MediaSetup* media, UnifiedRender& out);

// After the run, on the host: merges the view pass's per-node counters and hit ids.
void finish(UnifiedRender& out);

// The light a radiosity solution adds to what a view without it shows: B - E, the reflected part of
// each element's radiosity (the lowered scene shows the emission E itself). Where the plan skips
// radiosity, a forced pass must find exactly zero everywhere.
struct ReflectedLight {
  double largest = 0.0;  // the largest channel of B - E over the elements
  int element = -1;      // where (-1: every element reflects exactly nothing)
  int material = -1;     // that element's material in the scene description (-1: none)
};
ReflectedLight reflected_light(const radiosity::Scene& mesh, const std::vector<radiosity::Rgb>& element_radiosity);

// The area-weighted mean radiosity (mean of the channels) of the elements that emit nothing: how
// bright the walls are, for comparing renders of one mesh.
double mean_wall_radiosity(const radiosity::Scene& mesh, const std::vector<radiosity::Rgb>& element_radiosity);

}  // namespace gcsim::render
