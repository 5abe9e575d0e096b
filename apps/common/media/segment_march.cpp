#include "apps/common/media/segment_march.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace gcsim::media {
namespace {

std::vector<double> stratified_numbers(int count, apps::Rng& rng) {
  std::vector<double> jitter(static_cast<std::size_t>(count));
  for (double& j : jitter) j = rng.uniform_double();
  return stratified(count, jitter);
}

// Draws M by stochastic rounding; returns the factor that keeps the estimate unbiased (1/M when M < 1
// leaves a single sample, 1 otherwise since the mean of the drawn samples is already unbiased). With
// at_least_one, M < 1 takes one sample of weight 1 instead ([A12]: less noise on thin segments).
int sample_count(double m, bool at_least_one, apps::Rng& rng, double& scale) {
  scale = 1.0;
  if (at_least_one && m < 1.0) return 1;
  const int n = stochastic_round(m, rng.uniform_double());
  scale = (m < 1.0 && n > 0) ? 1.0 / m : 1.0;
  return n;
}

// Whether the grid's voxels are thin enough, in mean free paths, for h to follow Li along a ray
// (MarchSettings::max_voxel_optical_depth).
bool grid_resolves_transmittance(const RadianceGrid& grid, const HomogeneousMedium& m, const MarchSettings& s) {
  const glm::dvec3 size = grid.grid().cell_size();
  return m.sigma_t * std::cbrt(size.x * size.y * size.z) <= s.max_voxel_optical_depth;
}

}  // namespace

double march_segment_in_scatter(const SegmentQuery& q, const MarchSettings& s,
                                const std::function<double(const glm::dvec3&)>& li, apps::Rng& rng,
                                MarchCounters& counters) {
  const HomogeneousMedium& m = *q.medium;
  if (q.length <= 0.0 || m.sigma_s <= 0.0) return 0.0;
  ++counters.segments;
  const Segment seg{q.length, m.sigma_t};
  const double s_int = segment_integral(m.sigma_t, q.length);
  counters.integral_s += s_int;
  auto li_at = [&](double t) {
    ++counters.samples;
    return li(q.origin + t * q.direction);
  };

  std::unique_ptr<HistogramDistance> hist;
  if (s.estimator == Estimator::radiance || s.estimator == Estimator::mis || s.estimator == Estimator::grid) {
    RayHistogram h = q.grid->histogram(q.origin, q.direction, 0.0, q.length);
    counters.sh_evals += h.values.size();
    // Where the segment leaves the grid, h = 0 (the defensive mixture still samples there).
    if (h.values.empty()) h = {{0.0, q.length}, {0.0}};
    if (h.edges.front() > 0.0) h.edges.insert(h.edges.begin(), 0.0), h.values.insert(h.values.begin(), 0.0);
    if (h.edges.back() < q.length) h.edges.push_back(q.length), h.values.push_back(0.0);
    h.edges.front() = 0.0, h.edges.back() = q.length;
    hist = std::make_unique<HistogramDistance>(seg, h.edges, h.values, s.defensive_alpha);
    counters.integral_s_h += std::max(0.0, hist->s_h());
  }
  if (s.estimator == Estimator::grid) return m.sigma_s * hist->s_h();  // eq. (17), S_h as corrected (18)

  double m_real = s.b * s_int;
  if (s.estimator == Estimator::radiance && s.b_histogram > 0.0 && hist->s_h() > 0.0)
    m_real = s.b_histogram * hist->s_h();  // eq. (22)
  double scale = 1.0;
  const int count = sample_count(m_real, s.at_least_one_sample, rng, scale);
  if (count == 0) return 0.0;

  std::optional<EquiangularDistance> eq;
  if (q.light) eq = equiangular_for(*q.light, q.origin, q.direction, seg);
  switch (s.estimator) {
    case Estimator::uniform:
      return scale * m.sigma_s * estimate_in_scatter(UniformDistance(seg), stratified_numbers(count, rng), li_at);
    case Estimator::transmittance:
      return scale * m.sigma_s * estimate_in_scatter(TransmittanceDistance(seg), stratified_numbers(count, rng), li_at);
    case Estimator::radiance:
      if (!grid_resolves_transmittance(*q.grid, m, s))
        return scale * m.sigma_s * estimate_in_scatter(TransmittanceDistance(seg), stratified_numbers(count, rng), li_at);
      return scale * m.sigma_s * estimate_in_scatter(*hist, stratified_numbers(count, rng), li_at);
    case Estimator::equiangular:
      if (eq) return scale * m.sigma_s * estimate_in_scatter(*eq, stratified_numbers(count, rng), li_at);
      return scale * m.sigma_s * estimate_in_scatter(TransmittanceDistance(seg), stratified_numbers(count, rng), li_at);
    case Estimator::mis: {
      // The M samples are shared out over the techniques (the radiance density first: with its
      // defensive part it is positive wherever the transmittance is, so a technique left with no
      // sample never leaves a gap); the balance heuristic weighs each by the counts actually drawn.
      TransmittanceDistance tr(seg);
      std::vector<const DistanceSampler*> techniques{hist.get(), &tr};
      if (eq) techniques.push_back(&*eq);
      const int n = static_cast<int>(techniques.size());
      std::vector<std::vector<double>> u;
      for (int i = 0; i < n; ++i) u.push_back(stratified_numbers(count / n + (i < count % n ? 1 : 0), rng));
      return scale * m.sigma_s * estimate_in_scatter_mis(techniques, u, li_at);
    }
    case Estimator::grid: break;
  }
  return 0.0;
}

}  // namespace gcsim::media
