#pragma once
// One homogeneous segment of a camera ray (eq. 6 and its variants): the radiance it adds,
//   L = σa S Le + σs I + e^{−Δx σt} L(x_{k+1}),  I = ∫_0^{Δx} e^{−σt t} Li(t) dt,
// with I estimated by the chosen distance estimator from M = b·S (eq. 21) or b·S_h (eq. 22) samples,
// rounded stochastically [A12]. Li comes from the photon map (eq. 4); the histogram from the SH grid.
#include <cstdint>
#include <functional>
#include <optional>

#include "apps/common/rng.hpp"
#include "apps/common/media/estimator.hpp"
#include "apps/common/media/medium.hpp"
#include "apps/common/media/radiance_grid.hpp"
#include "apps/common/media/single_scattering.hpp"

namespace gcsim::media {

struct MarchSettings {
  Estimator estimator = Estimator::radiance;
  double b = 16.0;                  // samples per unit of S (eq. 21)
  double b_histogram = 0.0;         // > 0: radiance IS takes M = b_h S_h (eq. 22); else M = b S
  // Transmittance share of the radiance density [A11]: any α > 0 keeps the estimate unbiased where h
  // is zero or negative; the share costs variance where h is good (one sample in ten drawn from the
  // transmittance alone at 0.1: dark outliers on dim pixels). 0.03 had equal or lower RMSE on the three
  // accuracy scenes and evener noise (apps/media/README.md, "The defensive share").
  double defensive_alpha = 0.03;
  bool at_least_one_sample = false; // M < 1: one sample (notes [A12]) instead of stochastic rounding
  // Beyond the paper: where the medium's voxels are more than this many mean free paths across
  // (σt times the voxel's mean width), the grid cannot resolve Li where the transmittance puts its
  // mass, and the radiance density only adds variance (its jumps at voxel faces reweight samples by
  // Li/h); such segments draw their distances from the transmittance, with the radiance estimator's
  // M kept. A huge value (1e9): the paper's density everywhere.
  double max_voxel_optical_depth = 1.0;
};

struct MarchCounters {
  std::uint64_t samples = 0;       // Li evaluations (each a k-NN lookup)
  std::uint64_t sh_evals = 0;      // histogram bins reconstructed (16-term dot products)
  std::uint64_t segments = 0;
  double integral_s = 0.0;    // Σ S over the segments (eq. 7)
  double integral_s_h = 0.0;  // Σ max(S_h, 0) over the segments that built a histogram (corrected eq. 18)
  void add(const MarchCounters& o) {
    samples += o.samples, sh_evals += o.sh_evals, segments += o.segments;
    integral_s += o.integral_s, integral_s_h += o.integral_s_h;
  }
};

struct SegmentQuery {
  glm::dvec3 origin, direction;  // the segment is origin + t direction, t in [0, length]
  double length;
  const HomogeneousMedium* medium;
  const RadianceGrid* grid;            // needed by radiance, mis and grid
  std::optional<PointLight> light;     // needed by equiangular (and used by mis)
};

// The in-scattered part σs I (without emission and the transmitted background) of one segment.
double march_segment_in_scatter(const SegmentQuery& q, const MarchSettings& s,
                                const std::function<double(const glm::dvec3&)>& li, apps::Rng& rng,
                                MarchCounters& counters);

}  // namespace gcsim::media
