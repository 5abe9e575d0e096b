#pragma once
// Distance samplers along one homogeneous segment [0, Δx] of a ray (paper section 3.3–3.4):
// each draws t from a uniform u and returns its density P(t). The in-scattering integral they serve is
//   I = ∫_0^{Δx} e^{−σt t} Li(t) dt,   estimated by (1/M) Σ e^{−σt t_j} Li(t_j) / P(t_j)   (eq. 6),
// and weight(t) = e^{−σt t} / P(t) is given in a form that does not underflow for τ ≫ 1.
#include <memory>
#include <span>
#include <vector>

namespace gcsim::media {

struct Segment {
  double length = 0.0;   // Δx
  double sigma_t = 0.0;  // σt, constant on the segment
};

class DistanceSampler {
 public:
  explicit DistanceSampler(Segment s) : segment_(s) {}
  virtual ~DistanceSampler() = default;
  virtual double sample(double u) const = 0;
  virtual double pdf(double t) const = 0;
  // e^{−σt t} / P(t); 0 where P is 0.
  virtual double weight(double t) const;
  const Segment& segment() const { return segment_; }

 protected:
  Segment segment_;
};

// P(t) = 1/Δx: the uniform baseline (jittered when fed stratified u [A6]).
class UniformDistance final : public DistanceSampler {
 public:
  using DistanceSampler::DistanceSampler;
  double sample(double u) const override;
  double pdf(double t) const override;
};

// P(t) = e^{−σt t} / S (eq. 8), sampled by inverting its CDF (eq. 10) in the form
// t = −log1p(u · expm1(−σt Δx)) / σt, exact for tiny and huge optical depths.
class TransmittanceDistance final : public DistanceSampler {
 public:
  explicit TransmittanceDistance(Segment s);
  double sample(double u) const override;
  double pdf(double t) const override;
  double weight(double t) const override { return s_; }  // = S for every t (eq. 9)
  double segment_integral() const { return s_; }

 private:
  double s_;
};

// Radiance importance sampling from the piecewise-constant histogram h of the SH grid along the ray
// (eqs. 19–20). Negative or zero h [A11] are handled by a defensive mixture
//   P = α e^{−σt t}/S + (1 − α) h⁺(t) e^{−σt t}/S_h⁺,   h⁺ = max(h, 0),
// which is positive wherever the transmittance is, so the estimate stays unbiased; α = 0 gives the
// paper's pure density (zero variance when Li = h > 0). If S_h⁺ = 0 the sampler is pure transmittance.
class HistogramDistance final : public DistanceSampler {
 public:
  // edges: t_1 = 0 < ... < t_{n+1} = Δx; values: h_i on [t_i, t_{i+1}).
  HistogramDistance(Segment s, std::vector<double> edges, std::vector<double> values, double alpha);
  double sample(double u) const override;
  double pdf(double t) const override;
  double weight(double t) const override;
  // S_h = Σ_i h_i e^{−t_i σt} (1 − e^{−(t_{i+1} − t_i) σt}) / σt: eq. (18) with the transmittance factor
  // the paper drops restored; computed from the raw h (negative values included).
  double s_h() const { return s_h_; }
  double alpha() const { return alpha_; }
  std::size_t bin_of(double t) const;

 private:
  double sample_in_bin(std::size_t i, double v) const;
  std::vector<double> edges_, values_;
  std::vector<double> cdf_;   // cumulative h⁺_i e^{−(t_i − t_ref) σt}(1 − e^{−Δ_i σt})/σt, normalized
  double total_rel_ = 0.0;    // Σ of the un-normalized weights, relative to e^{−t_ref σt}
  double t_ref_ = 0.0;        // start of the first bin with h > 0 (keeps weights from underflowing)
  double s_ = 0.0, s_h_ = 0.0, alpha_ = 1.0;
};

// Equiangular sampling for a point light (Kulla & Fajardo 2012): P(t) ∝ 1/(D² + (t − Δ)²), with Δ the
// light's projection on the ray and D its distance from it. Degenerate D falls back to uniform.
class EquiangularDistance final : public DistanceSampler {
 public:
  EquiangularDistance(Segment s, double light_along, double light_distance);
  double sample(double u) const override;
  double pdf(double t) const override;

 private:
  double delta_, d_, theta_a_, theta_b_;
  bool degenerate_;
};

// Stratified uniform numbers (j + ξ_j)/M, sorted [A10].
std::vector<double> stratified(int count, std::span<const double> jitter);

// M from a real-valued count (eqs. 21–22) by stochastic rounding [A12]: floor(M) or floor(M)+1.
int stochastic_round(double m, double u);

}  // namespace gcsim::media
