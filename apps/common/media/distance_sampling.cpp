#include "apps/common/media/distance_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "apps/common/media/medium.hpp"

namespace gcsim::media {

double DistanceSampler::weight(double t) const {
  double p = pdf(t);
  return p > 0.0 ? std::exp(-segment_.sigma_t * t) / p : 0.0;
}

double UniformDistance::sample(double u) const { return u * segment_.length; }
double UniformDistance::pdf(double t) const {
  return (t >= 0.0 && t <= segment_.length && segment_.length > 0.0) ? 1.0 / segment_.length : 0.0;
}

TransmittanceDistance::TransmittanceDistance(Segment s)
    : DistanceSampler(s), s_(media::segment_integral(s.sigma_t, s.length)) {}

double TransmittanceDistance::sample(double u) const {
  const double st = segment_.sigma_t, dx = segment_.length;
  if (st * dx < 1e-12) return u * dx;
  double t = -std::log1p(u * std::expm1(-st * dx)) / st;  // eq. (10), ξ = 1 − u(1 − e^{−Δx σt})
  return std::clamp(t, 0.0, dx);
}

double TransmittanceDistance::pdf(double t) const {
  if (t < 0.0 || t > segment_.length) return 0.0;
  return std::exp(-segment_.sigma_t * t) / s_;
}

HistogramDistance::HistogramDistance(Segment s, std::vector<double> edges, std::vector<double> values,
                                     double alpha)
    : DistanceSampler(s), edges_(std::move(edges)), values_(std::move(values)) {
  if (edges_.size() != values_.size() + 1 || values_.empty())
    throw std::invalid_argument("HistogramDistance: need n+1 edges for n values");
  if (!(alpha >= 0.0 && alpha <= 1.0)) throw std::invalid_argument("HistogramDistance: alpha in [0,1]");
  const double st = s.sigma_t;
  s_ = segment_integral(st, s.length);
  std::size_t first = values_.size();
  for (std::size_t i = 0; i < values_.size(); ++i)
    if (values_[i] > 0.0) { first = i; break; }
  t_ref_ = first < values_.size() ? edges_[first] : 0.0;
  cdf_.assign(values_.size(), 0.0);
  double acc = 0.0;
  for (std::size_t i = 0; i < values_.size(); ++i) {
    const double width = edges_[i + 1] - edges_[i];
    const double bin_s = segment_integral(st, width);
    s_h_ += values_[i] * std::exp(-edges_[i] * st) * bin_s;  // corrected eq. (18)
    if (values_[i] > 0.0) acc += values_[i] * std::exp(-(edges_[i] - t_ref_) * st) * bin_s;
    cdf_[i] = acc;
  }
  total_rel_ = acc;
  alpha_ = total_rel_ > 0.0 ? alpha : 1.0;
  if (total_rel_ > 0.0)
    for (double& c : cdf_) c /= total_rel_;
}

std::size_t HistogramDistance::bin_of(double t) const {
  auto it = std::upper_bound(edges_.begin() + 1, edges_.end() - 1, t);
  return static_cast<std::size_t>(it - (edges_.begin() + 1));
}

double HistogramDistance::sample_in_bin(std::size_t i, double v) const {
  const double st = segment_.sigma_t, width = edges_[i + 1] - edges_[i];
  double local = st * width < 1e-12 ? v * width : -std::log1p(v * std::expm1(-st * width)) / st;
  return std::clamp(edges_[i] + local, edges_[i], edges_[i + 1]);
}

double HistogramDistance::sample(double u) const {
  if (u < alpha_) return TransmittanceDistance(segment_).sample(u / alpha_);
  const double v = (u - alpha_) / (1.0 - alpha_);
  std::size_t i = static_cast<std::size_t>(std::upper_bound(cdf_.begin(), cdf_.end(), v) - cdf_.begin());
  i = std::min(i, cdf_.size() - 1);
  while (values_[i] <= 0.0 && i > 0) --i;  // v on a flat stretch of the CDF: stay in a positive bin
  const double lo = i > 0 ? cdf_[i - 1] : 0.0;
  const double within = cdf_[i] > lo ? std::clamp((v - lo) / (cdf_[i] - lo), 0.0, 1.0) : 0.5;
  return sample_in_bin(i, within);
}

// e^{−σt t}/P(t) = 1 / (α/S + (1 − α) h⁺_i e^{σt t_ref} / total), free of e^{−σt t}.
double HistogramDistance::weight(double t) const {
  if (t < 0.0 || t > segment_.length) return 0.0;
  double inv = alpha_ / s_;
  const double h = values_[bin_of(t)];
  if (alpha_ < 1.0 && h > 0.0)
    inv += (1.0 - alpha_) * h / (total_rel_ * std::exp(-segment_.sigma_t * t_ref_));
  return inv > 0.0 ? 1.0 / inv : 0.0;
}

double HistogramDistance::pdf(double t) const {
  if (t < 0.0 || t > segment_.length) return 0.0;
  double w = weight(t);
  return w > 0.0 ? std::exp(-segment_.sigma_t * t) / w : 0.0;
}

EquiangularDistance::EquiangularDistance(Segment s, double light_along, double light_distance)
    : DistanceSampler(s), delta_(light_along), d_(light_distance) {
  degenerate_ = !(d_ > 1e-9 * std::max(1.0, s.length));
  theta_a_ = degenerate_ ? 0.0 : std::atan((0.0 - delta_) / d_);
  theta_b_ = degenerate_ ? 0.0 : std::atan((s.length - delta_) / d_);
  if (theta_b_ - theta_a_ <= 0.0) degenerate_ = true;
}

double EquiangularDistance::sample(double u) const {
  if (degenerate_) return u * segment_.length;
  double t = delta_ + d_ * std::tan(theta_a_ + u * (theta_b_ - theta_a_));
  return std::clamp(t, 0.0, segment_.length);
}

double EquiangularDistance::pdf(double t) const {
  if (t < 0.0 || t > segment_.length) return 0.0;
  if (degenerate_) return 1.0 / segment_.length;
  const double x = t - delta_;
  return d_ / ((theta_b_ - theta_a_) * (d_ * d_ + x * x));
}

std::vector<double> stratified(int count, std::span<const double> jitter) {
  std::vector<double> u(static_cast<std::size_t>(count));
  for (int j = 0; j < count; ++j) u[j] = (j + jitter[j]) / count;
  return u;
}

int stochastic_round(double m, double u) {
  const double f = std::floor(m);
  return static_cast<int>(f) + (u < m - f ? 1 : 0);
}

}  // namespace gcsim::media
