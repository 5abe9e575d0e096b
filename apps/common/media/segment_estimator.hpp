#pragma once
// Monte Carlo estimates of the in-scattering integral I = ∫_0^{Δx} e^{−σt t} Li(t) dt of one segment
// (eq. 6 without the σs factor), with one distance sampler or a multiple-importance combination.
#include <cmath>
#include <span>
#include <vector>

#include "apps/common/media/distance_sampling.hpp"

namespace gcsim::media {

// (1/M) Σ_j e^{−σt t_j} Li(t_j) / P(t_j) with t_j drawn from u_j.
template <class Radiance>
double estimate_in_scatter(const DistanceSampler& sampler, std::span<const double> u, Radiance&& li) {
  if (u.empty()) return 0.0;
  double sum = 0.0;
  for (double uj : u) {
    const double t = sampler.sample(uj);
    sum += sampler.weight(t) * li(t);
  }
  return sum / static_cast<double>(u.size());
}

// Multi-sample MIS with the balance heuristic (Veach): technique i draws n_i = u[i].size() samples,
// each contributes e^{−σt t} Li(t) / Σ_k n_k P_k(t).
template <class Radiance>
double estimate_in_scatter_mis(std::span<const DistanceSampler* const> techniques,
                               std::span<const std::vector<double>> u, Radiance&& li) {
  double sum = 0.0;
  for (std::size_t i = 0; i < techniques.size(); ++i) {
    for (double uj : u[i]) {
      const double t = techniques[i]->sample(uj);
      double denominator = 0.0;
      for (std::size_t k = 0; k < techniques.size(); ++k)
        denominator += static_cast<double>(u[k].size()) * techniques[k]->pdf(t);
      if (denominator > 0.0)
        sum += std::exp(-techniques[i]->segment().sigma_t * t) * li(t) / denominator;
    }
  }
  return sum;
}

}  // namespace gcsim::media
