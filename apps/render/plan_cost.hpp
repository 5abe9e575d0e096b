#pragma once
// A deliberately simple estimate of each pass's simulated time and memory per node, from the plan's
// counts and the machine file's [ops] table (cycles per operation) and clock. It is an estimate: work
// is taken to split evenly over the nodes, communication is not counted, and the unknowns (shots per
// patch, specular depth, march samples, photons) are the constants below. The radiosity pass can
// instead be measured by sampling its first loops (radiosity_seconds_per_loop), which counts its
// communication and waiting too; the media and the view (with specular and shadows) by sampling
// their photons and tiles.
#include <cstdint>
#include <string>

#include "apps/render/plan.hpp"
#include "machine/machine_config.hpp"

namespace gcsim::render {

struct CostModel {
  int hemicube_resolution = 256;  // radiosity's default (--hemicube)
  // Shots until 99.9 % of the energy is shot: CORNELL takes 254 loops of 2 shooters for 112 patches.
  double shots_per_patch = 4.5;
  int shooters_per_loop = 2;      // the render's radiosity pass shoots two patches per loop
  // > 0: the radiosity pass's simulated seconds per loop measured on the machine by running its
  // first loops (radiosity_sample.hpp); the estimate is then this times the expected loops.
  double radiosity_seconds_per_loop = 0;
  double radiosity_loops = 0;     // > 0: the loops to convergence forecast (loop_forecast.hpp)
  double radiosity_uncertainty = 0;  // relative, of the measured radiosity time
  int specular_depth = 4;         // upper bound: every camera ray meets mirrors or glass this deep
  // Distance samples per free path: the view takes 32 (1 - T) on a segment of transmittance T, so
  // a camera ray takes about 32 x SceneFacts::media_opacity (per pixel, CORNELL-FOG: 10 predicted,
  // 6.8 measured; MEDIA-EXP1: 63 predicted, 105 measured: the sphere's reflected and refracted
  // rays march too).
  int march_samples = 32;
  // > 0: the media pass measured on the machine by a sample of its photons and of the view's tiles
  // (media_sample.hpp): its simulated seconds and the photon map's bytes; the counts below then
  // only describe the fallback.
  double media_seconds = 0;
  std::int64_t media_bytes = 0;
  std::string media_measured;     // how that sample ran, for the report
  double media_photon_seconds = 0, media_grid_seconds = 0, media_march_seconds = 0;  // its parts
  // view_sampled: the view, specular and shadows passes measured on the machine by a sample of the
  // view's tiles (view_sample.hpp): each row's simulated seconds and the view's bytes.
  bool view_sampled = false;
  double view_seconds = 0, specular_seconds = 0, shadow_seconds = 0;
  std::int64_t view_bytes = 0;
  std::string view_measured;      // how that sample ran, for the report
  // Relative uncertainties of the measured figures (0: exact or not measured): the view's and the
  // media's from their sampled fractions, the radiosity's from its sample's loop times.
  double view_uncertainty = 0, media_uncertainty = 0;
  std::int64_t radiosity_peak_bytes = 0;  // > 0: the most a node held in the radiosity sample
  bool radiosity_deposits = false;  // the radiosity sample started from the photons' wall deposits
  int photons = 50000;            // `gcsim render --photons`' default (render_setup.hpp)
  int k_nearest = 50;             // photons per radiance estimate
  int max_photon_events = 64;
};

// The passes a view sample measures (view_sample.hpp): the view and the rays it adds.
inline bool measured_by_view_sample(PassId id) {
  return id == PassId::view || id == PassId::specular || id == PassId::shadows;
}

struct PassCost {
  double seconds_per_node = 0.0;     // simulated compute time on the slowest node
  std::int64_t bytes_per_node = 0;   // the pass's data on one node
};

// Cost of one pass (zero for a pass that is off). Throws std::invalid_argument naming an operation
// the machine file's [ops] table lacks.
PassCost estimate_pass(const PassPlan& pass, const SceneFacts& facts, const machine::MachineConfig& machine,
                       int nodes, const CostModel& model = {});
// The relative uncertainty of a pass's estimate (0 for a counted pass: it has none to give).
double pass_uncertainty(PassId id, const CostModel& m);

// What one node holds for a pass: the radiosity sample's measured peak where it ran (the count
// misses the replica's and hemicube's real size), else the count's estimate.
std::int64_t pass_bytes_per_node(const PassPlan& pass, const SceneFacts& f, const machine::MachineConfig& machine,
                                 int nodes, const CostModel& m);

// The most one node holds during the render: the photon map (kept from the media pass to the view's
// end) plus the larger of the radiosity pass's replica and hemicube and the view's scene, tree and
// image (the radiosity pass frees its own before the view). uncertainty: relative, the photon map's
// share times the media's.
struct PeakMemory {
  std::int64_t bytes = 0;
  double uncertainty = 0;
};
PeakMemory predicted_peak(const Plan& plan, const machine::MachineConfig& machine, int nodes, const CostModel& m);

// The relative uncertainty of a figure scaled from a sampled fraction `sampled` of its work: none for
// all of it, else the largest miss measured with one run of tiles in 4 (8.5 %) scaled by
// sqrt(1 - sampled).
double sampled_fraction_uncertainty(double sampled);

// The radiosity loops the estimate assumes: shots_per_patch x patches / shooters_per_loop.
double expected_loops(const SceneFacts& f, const CostModel& m);

}  // namespace gcsim::render
