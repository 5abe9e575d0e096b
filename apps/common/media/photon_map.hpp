#pragma once
// The volume photon map (Jensen & Christensen 1998; paper section 2): photons stored at medium
// interactions, a k-d tree over their positions (Debian's nanoflann), and the k-nearest-photon
// radiance estimate of eq. (4).
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "apps/common/media/medium.hpp"

namespace gcsim::media {

struct Photon {
  glm::vec3 position;
  glm::vec3 direction;  // travel direction ω_p [A3]
  float power;          // ΔΦ_p (luminance [A8])
};

struct NearestPhotons {
  std::vector<std::uint32_t> indices;
  double radius_squared = 0.0;  // r_k²: the k-th neighbour's squared distance
};

class PhotonMap {
 public:
  explicit PhotonMap(std::vector<Photon> photons);
  ~PhotonMap();
  PhotonMap(PhotonMap&&) noexcept;
  PhotonMap& operator=(PhotonMap&&) noexcept;

  const std::vector<Photon>& photons() const { return photons_; }
  NearestPhotons nearest(const glm::dvec3& x, std::size_t k) const;
  // The k nearest photons of x when all of them are known to lie within `bound` of x — e.g. the k
  // nearest of a point y at distance δ lie within r_k(y) + δ of x (triangle inequality). One radius
  // search and a linear selection instead of a k-NN descent that keeps a sorted heap: the same set as
  // nearest() up to ties at r_k. `candidates` is told how many photons the search returned.
  NearestPhotons nearest_within(const glm::dvec3& x, std::size_t k, double bound, std::size_t& candidates) const;

  // Li(x, ω_o) ≈ (1/σt) Σ_{p≤k} p(ω_p·ω_o) ΔΦ_p / dV, dV = 4/3 π r_k³ (eq. 4); ω_o points toward the eye.
  double in_scattered(const glm::dvec3& x, const glm::dvec3& w_out, const HomogeneousMedium& medium,
                      std::size_t k) const;
  // Fluence φ(x) ≈ (1/σt) Σ ΔΦ_p / dV: photons are stored at every interaction, whose density is σt φ [A4].
  double fluence(const glm::dvec3& x, double sigma_t, std::size_t k) const;

 private:
  struct Index;
  std::vector<Photon> photons_;
  std::unique_ptr<Index> index_;
};

}  // namespace gcsim::media
