#include "apps/common/media/photon_map.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <nanoflann.hpp>

namespace gcsim::media {

// nanoflann's dataset adaptor over the photon positions.
struct PhotonCloud {
  const std::vector<Photon>* photons;
  std::size_t kdtree_get_point_count() const { return photons->size(); }
  float kdtree_get_pt(std::size_t i, std::size_t dim) const { return (*photons)[i].position[static_cast<int>(dim)]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const { return false; }
};

using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, PhotonCloud>, PhotonCloud, 3,
                                                   std::uint32_t>;

struct PhotonMap::Index {
  PhotonCloud cloud;
  KdTree tree;
  explicit Index(const std::vector<Photon>* p)
      : cloud{p}, tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16)) {
    tree.buildIndex();
  }
};

PhotonMap::PhotonMap(std::vector<Photon> photons) : photons_(std::move(photons)) {
  if (photons_.empty()) throw std::invalid_argument("PhotonMap: no photons were stored");
  index_ = std::make_unique<Index>(&photons_);
}
PhotonMap::~PhotonMap() = default;
// The index reads the photons through a pointer to photons_: re-aim it after a move.
PhotonMap::PhotonMap(PhotonMap&& other) noexcept
    : photons_(std::move(other.photons_)), index_(std::move(other.index_)) {
  index_->cloud.photons = &photons_;
}
PhotonMap& PhotonMap::operator=(PhotonMap&& other) noexcept {
  photons_ = std::move(other.photons_);
  index_ = std::move(other.index_);
  index_->cloud.photons = &photons_;
  return *this;
}

NearestPhotons PhotonMap::nearest(const glm::dvec3& x, std::size_t k) const {
  k = std::min(k, photons_.size());
  NearestPhotons result;
  result.indices.resize(k);
  std::vector<float> d2(k);
  const float q[3] = {static_cast<float>(x.x), static_cast<float>(x.y), static_cast<float>(x.z)};
  const std::size_t found = index_->tree.knnSearch(q, k, result.indices.data(), d2.data());
  result.indices.resize(found);
  result.radius_squared = found ? d2[found - 1] : 0.0;
  return result;
}

NearestPhotons PhotonMap::nearest_within(const glm::dvec3& x, std::size_t k, double bound,
                                         std::size_t& candidates) const {
  k = std::min(k, photons_.size());
  const float q[3] = {static_cast<float>(x.x), static_cast<float>(x.y), static_cast<float>(x.z)};
  // A relative margin so float rounding of the squared distances cannot drop a photon on the bound.
  const float bound2 = static_cast<float>(bound * bound * (1.0 + 1e-4));
  std::vector<std::pair<std::uint32_t, float>> found;
  found.reserve(4 * k);
  candidates = index_->tree.radiusSearch(q, bound2, found, nanoflann::SearchParams(32, 0.0f, false));
  if (found.size() < k || k == 0) return nearest(x, k);  // the bound was not one: fall back
  auto kth = found.begin() + static_cast<std::ptrdiff_t>(k - 1);
  std::nth_element(found.begin(), kth, found.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  NearestPhotons result;
  result.radius_squared = kth->second;
  result.indices.reserve(k);
  for (auto it = found.begin(); it <= kth; ++it) result.indices.push_back(it->first);
  return result;
}

namespace {
double sphere_volume(double r2) { return 4.0 / 3.0 * kPi * r2 * std::sqrt(r2); }
}  // namespace

double PhotonMap::in_scattered(const glm::dvec3& x, const glm::dvec3& w_out, const HomogeneousMedium& medium,
                               std::size_t k) const {
  const NearestPhotons n = nearest(x, k);
  if (n.radius_squared <= 0.0) return 0.0;
  double sum = 0.0;
  for (std::uint32_t i : n.indices)
    sum += medium.phase.eval(glm::dot(glm::dvec3(photons_[i].direction), w_out)) * photons_[i].power;
  return sum / (medium.sigma_t * sphere_volume(n.radius_squared));
}

double PhotonMap::fluence(const glm::dvec3& x, double sigma_t, std::size_t k) const {
  const NearestPhotons n = nearest(x, k);
  if (n.radius_squared <= 0.0) return 0.0;
  double sum = 0.0;
  for (std::uint32_t i : n.indices) sum += photons_[i].power;
  return sum / (sigma_t * sphere_volume(n.radius_squared));
}

}  // namespace gcsim::media
