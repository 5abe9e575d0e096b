#include "apps/render/wall_deposits.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <span>
#include <stdexcept>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "apps/common/geometry/hit.hpp"
#include "apps/common/geometry/ray.hpp"
#include "apps/common/geometry/traversal.hpp"
#include "apps/render/view_scene.hpp"
#include "parix/collectives.hpp"

namespace gcsim::render {

namespace {

// Does the triangle's winding normal look the way `normal` does?
bool along(const geometry::Triangle& tri, const glm::dvec3& normal) {
  return glm::dot(glm::dvec3(glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0)), normal) >= 0;
}

}  // namespace

ElementLookup::ElementLookup(const radiosity::Scene& mesh, const scene::SceneDescription& d)
    : elements_(mesh.elements.size()) {
  // Triangles of the element first added on each set of corners, by those corners sorted.
  std::map<std::array<int, 4>, std::pair<std::size_t, std::size_t>> by_corners;
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    const int m = mesh.surface_of_element(int(e)).material;
    if (m >= 0 && is_specular(d.materials.at(std::size_t(m)))) continue;
    const radiosity::SceneElement& el = mesh.elements[e];
    std::array<int, 4> key{-1, -1, -1, -1};
    std::copy_n(el.vertex.begin(), el.count, key.begin());
    std::sort(key.begin(), key.end());  // the -1 of a triangle first: still one key per set of corners
    if (const auto it = by_corners.find(key); it != by_corners.end()) {
      for (std::size_t t = it->second.first; t < it->second.second; ++t) {  // usually the other side of those triangles
        const geometry::Triangle& tri = triangles_.triangles[t];
        std::vector<int>& side = along(tri, el.normal) ? front_ : back_;
        if (side[t] < 0) side[t] = int(e);
      }
      continue;
    }
    const std::size_t first = triangles_.triangles.size();
    auto at = [&](int k) { return glm::vec3(mesh.vertices[std::size_t(el.vertex[std::size_t(k)])]); };
    for (int k = 1; k + 1 < el.count; ++k) {
      const geometry::Triangle tri{at(0), at(k), at(k + 1)};
      triangles_.triangles.push_back(tri);
      front_.push_back(along(tri, el.normal) ? int(e) : -1);
      back_.push_back(along(tri, el.normal) ? -1 : int(e));
    }
    by_corners.emplace(key, std::make_pair(first, triangles_.triangles.size()));
  }
  if (!triangles_.triangles.empty()) bvh_ = geometry::build_bvh_by_clustering(triangles_);
}

int ElementLookup::find(const glm::dvec3& origin, const glm::dvec3& direction, geometry::TestTally& tally) const {
  if (triangles_.triangles.empty()) return -1;
  // As the photon's own ray: the first hit beyond a small distance from where the flight began.
  const geometry::Ray ray(glm::vec3(origin), glm::vec3(direction), 1e-5f * (1.0f + glm::length(glm::vec3(origin))));
  geometry::Hit hit;
  geometry::traverse_ordered(triangles_, bvh_.packed, ray, hit, tally);
  if (!hit.valid()) return -1;
  const geometry::Triangle& tri = triangles_.triangles[std::size_t(hit.prim)];
  const bool onto_front = glm::dot(glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0), glm::vec3(direction)) < 0;
  return onto_front ? front_[std::size_t(hit.prim)] : back_[std::size_t(hit.prim)];
}

// 2^-24 of a photon's power: a deposit is exact to 6e-8 of it, and 2^63 units hold 5e11 photons'
// worth at a tint of 1.
DepositSums::DepositSums(std::size_t elements, double photon_power)
    : quantum(std::ldexp(photon_power, -24)), units(3 * elements, 0) {}

void DepositSums::add(int element, const glm::dvec3& power) {
  for (int k = 0; k < 3; ++k) {
    const double u = std::round(power[k] / quantum);
    if (!(u >= 0.0 && u < 0x1p62))
      throw std::overflow_error(fmt::format("wall deposits: a photon's power {} (channel {}) is outside the fixed-point "
                                            "range of {} units of {}", power[k], k, 0x1p62, quantum));
    units[3 * std::size_t(element) + std::size_t(k)] += std::int64_t(u);
  }
  ++deposits;
}

std::vector<radiosity::Rgb> DepositSums::power() const {
  std::vector<radiosity::Rgb> out(units.size() / 3);
  for (std::size_t e = 0; e < out.size(); ++e)
    out[e] = radiosity::Rgb(double(units[3 * e]), double(units[3 * e + 1]), double(units[3 * e + 2])) * quantum;
  return out;
}

DepositSums all_reduce(parix::Processor& p, DepositSums mine) {
  // The counts travel after the sums: [units..., deposits, missed].
  parix::Bytes b((mine.units.size() + 2) * sizeof(std::int64_t));
  std::memcpy(b.data(), mine.units.data(), mine.units.size() * sizeof(std::int64_t));
  const std::int64_t counts[2] = {std::int64_t(mine.deposits), std::int64_t(mine.missed)};
  std::memcpy(b.data() + mine.units.size() * sizeof(std::int64_t), counts, sizeof(counts));
  const std::int64_t elements = std::int64_t(mine.units.size() / 3);
  const parix::Bytes all = parix::allreduce(p, std::move(b), [&p, elements](parix::Bytes& acc, std::span<const std::byte> in) {
    const std::size_t n = acc.size() / sizeof(std::int64_t);
    for (std::size_t i = 0; i < n; ++i) {  // integers: the sum is the same in any order
      std::int64_t a, x;
      std::memcpy(&a, acc.data() + i * sizeof(a), sizeof(a));
      std::memcpy(&x, in.data() + i * sizeof(x), sizeof(x));
      a += x;
      std::memcpy(acc.data() + i * sizeof(a), &a, sizeof(a));
    }
    p.compute("deposit_merge", elements);
  });
  std::memcpy(mine.units.data(), all.data(), mine.units.size() * sizeof(std::int64_t));
  std::int64_t total[2];
  std::memcpy(total, all.data() + mine.units.size() * sizeof(std::int64_t), sizeof(total));
  mine.deposits = std::uint64_t(total[0]), mine.missed = std::uint64_t(total[1]);
  return mine;
}

}  // namespace gcsim::render
