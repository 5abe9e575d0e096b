// The SH radiance grid: sizes of eqs. (12–13), voxels equal to the SH projection of the k-NN estimate,
// histograms along rays.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <utility>

#include <glm/geometric.hpp>

#include "apps/media/photon_tracer_infinite.hpp"
#include "apps/common/media/radiance_grid.hpp"
#include "apps/common/rng.hpp"
#include "tests/media/quadrature.hpp"

namespace gcsim::media {
namespace {

TEST(RadianceGrid, DimensionsFollowEquationsTwelveAndThirteen) {
  // A cube: n = a N / k split evenly; a 1×2×4 box keeps the aspect ratio.
  EXPECT_EQ(radiance_grid_dims({0, 0, 0}, {1, 1, 1}, 100000, 100), glm::ivec3(50));  // 125000 = 50³
  glm::ivec3 d = radiance_grid_dims({0, 0, 0}, {1, 2, 4}, 100000, 125);             // n = 100000
  EXPECT_EQ(d, glm::ivec3(23, 46, 93));
  EXPECT_NEAR(double(d.x) * d.y * d.z, 100000.0, 0.03 * 100000.0);
  EXPECT_EQ(radiance_grid_dims({0, 0, 0}, {1, 1, 1}, 10, 100), glm::ivec3(2));  // cbrt(12.5) → 2
  EXPECT_THROW(radiance_grid_dims({0, 0, 0}, {1, 0, 1}, 10, 10), std::invalid_argument);
}

TEST(RadianceGrid, VoxelsAreTheShProjectionOfTheKnnEstimate) {
  HomogeneousMedium m{1.0, 0.8, 0.0, Phase::henyey_greenstein(0.4)};
  auto traced = trace_point_light_infinite(m, glm::dvec3(0), 5.0, 20000, 8, 3);
  PhotonMap map(std::move(traced.photons));
  UniformGrid g{{-1, -1, -1}, {1, 1, 1}, {3, 3, 3}};
  const std::size_t k = 50;
  RadianceGrid grid(g, map, m, k);
  // Each of the 9 rows along x starts with a k-NN descent; the other 18 voxels take bounded searches.
  const GridBuildCounts& n = grid.build_counts();
  EXPECT_EQ(n.photon_adds, 27u * k);
  EXPECT_EQ(n.knn_queries, 9u);
  EXPECT_EQ(n.range_queries, 18u);
  EXPECT_GE(n.range_candidates, 18u * k);
  EXPECT_GT(n.projections, 0u);
  EXPECT_LE(n.projections, n.photon_adds);
  for (glm::ivec3 c : {glm::ivec3(0, 0, 0), glm::ivec3(1, 1, 1), glm::ivec3(2, 0, 1)}) {
    const glm::dvec3 x = g.cell_center(c);
    // Project Li(x, ω) of eq. (4) on the SH basis by quadrature over the sphere.
    std::vector<double> z, w;
    testing::gauss_legendre(96, z, w);
    ShBasis ref{};
    for (int i = 0; i < 96; ++i) {
      double r = std::sqrt(1 - z[i] * z[i]);
      for (int j = 0; j < 192; ++j) {
        double phi = 2 * kPi * (j + 0.5) / 192;
        glm::dvec3 dir(r * std::cos(phi), r * std::sin(phi), z[i]);
        double li = map.in_scattered(x, dir, m, k);
        ShBasis y = sh_basis(dir);
        for (int l = 0; l < kShCoefficients; ++l) ref[l] += w[i] * (2 * kPi / 192) * li * y[l];
      }
    }
    const ShCoefficients& f = grid.voxel(g.linear_index(c));
    for (int l = 0; l < kShCoefficients; ++l) EXPECT_NEAR(f[l], ref[l], 1e-5 * std::abs(ref[0])) << l;
  }
}

// The bounded radius search finds exactly the k nearest: the same r_k and the same set as the k-NN
// descent, for bounds from the triangle inequality (a neighbour's r_k plus the distance) and for a
// bound too small to hold k photons (then it falls back to the descent).
TEST(PhotonMap, BoundedSearchFindsTheSameNearestPhotons) {
  HomogeneousMedium m{1.0, 0.8, 0.0, Phase::isotropic()};
  auto traced = trace_point_light_infinite(m, glm::dvec3(0), 5.0, 20000, 8, 5);
  PhotonMap map(std::move(traced.photons));
  apps::Rng rng(7, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const glm::dvec3 y(2 * rng.uniform_double() - 1, 2 * rng.uniform_double() - 1, 2 * rng.uniform_double() - 1);
    const glm::dvec3 x = y + 0.1 * glm::dvec3(rng.uniform_double(), rng.uniform_double() - 0.5, 0.0);
    const std::size_t k = 1 + trial % 80;
    const double bound = trial % 10 == 9 ? 1e-6 : std::sqrt(map.nearest(y, k).radius_squared) + glm::length(x - y);
    std::size_t candidates = 0;
    NearestPhotons a = map.nearest(x, k), b = map.nearest_within(x, k, bound, candidates);
    EXPECT_EQ(a.radius_squared, b.radius_squared) << trial;
    std::sort(a.indices.begin(), a.indices.end()), std::sort(b.indices.begin(), b.indices.end());
    EXPECT_EQ(a.indices, b.indices) << trial;
  }
}

// Every voxel of a grid built with bounded searches and projected photons equals the paper's recipe
// done voxel by voxel: a k-NN descent, then each photon added with its Funk–Hecke weights (eq. 30).
TEST(RadianceGrid, CoherentBuildEqualsOneKnnQueryPerVoxel) {
  HomogeneousMedium m{1.0, 0.8, 0.0, Phase::schlick(0.5)};
  auto traced = trace_point_light_infinite(m, glm::dvec3(0), 5.0, 20000, 8, 9);
  PhotonMap map(std::move(traced.photons));
  UniformGrid g{{-1.2, -1, -0.8}, {1, 1.1, 1}, {10, 9, 8}};
  const std::size_t k = 40;
  const RadianceGrid grid(g, map, m, k);
  EXPECT_EQ(grid.build_counts().knn_queries, 9u * 8u);
  for (std::size_t i = 0; i < g.voxel_count(); ++i) {
    const glm::ivec3 c(int(i % 10), int(i / 10 % 9), int(i / 90));
    const NearestPhotons n = map.nearest(g.cell_center(c), k);
    const double volume = 4.0 / 3.0 * kPi * n.radius_squared * std::sqrt(n.radius_squared);
    ShCoefficients ref{};
    for (std::uint32_t p : n.indices)
      sh_add_photon(ref, m.phase, m.sigma_t, map.photons()[p].power / volume, glm::dvec3(map.photons()[p].direction));
    for (int l = 0; l < kShCoefficients; ++l)
      ASSERT_NEAR(grid.voxel(i)[l], ref[l], 1e-5 * std::abs(ref[0]) + 1e-12) << "voxel " << i << " coefficient " << l;
  }
}

// Host threads cut a slice at row starts and join the pieces in order: the same voxels bit for bit
// and the same counted work (each photon projected once per slice) as one thread, for any slice.
TEST(RadianceGrid, HostThreadsBuildTheSameVoxelsAndCounts) {
  HomogeneousMedium m{1.0, 0.8, 0.0, Phase::schlick(0.5)};
  auto traced = trace_point_light_infinite(m, glm::dvec3(0), 5.0, 20000, 8, 9);
  PhotonMap map(std::move(traced.photons));
  UniformGrid g{{-1.2, -1, -0.8}, {1, 1.1, 1}, {10, 9, 8}};
  for (auto [first, last] : {std::pair<std::size_t, std::size_t>{0, 720}, {37, 500}, {95, 104}}) {
    GridBuildCounts c1;
    const std::vector<ShCoefficients> one = build_voxel_range(g, map, m, 40, first, last, c1);
    for (int jobs : {2, 3, 7}) {
      GridBuildCounts cn;
      const std::vector<ShCoefficients> many = build_voxel_range(g, map, m, 40, first, last, cn, jobs);
      ASSERT_EQ(one.size(), many.size());
      EXPECT_EQ(0, std::memcmp(one.data(), many.data(), one.size() * sizeof(ShCoefficients))) << first << " " << jobs;
      EXPECT_EQ(c1.knn_queries, cn.knn_queries);
      EXPECT_EQ(c1.knn_photons, cn.knn_photons);
      EXPECT_EQ(c1.range_queries, cn.range_queries);
      EXPECT_EQ(c1.range_candidates, cn.range_candidates);
      EXPECT_EQ(c1.projections, cn.projections);
      EXPECT_EQ(c1.photon_adds, cn.photon_adds);
    }
  }
}

TEST(RadianceGrid, HistogramFollowsTheVoxelsAlongTheRay) {
  HomogeneousMedium m{1.0, 0.8, 0.0, Phase::isotropic()};
  auto traced = trace_point_light_infinite(m, glm::dvec3(0), 5.0, 5000, 4, 3);
  PhotonMap map(std::move(traced.photons));
  UniformGrid g{{-1, -1, -1}, {1, 1, 1}, {4, 4, 4}};
  RadianceGrid grid(g, map, m, 30);
  const glm::dvec3 o(-2, 0.1, 0.2), d = glm::normalize(glm::dvec3(1, 0.1, 0.05));
  RayHistogram h = grid.histogram(o, d, 0, 10);
  ASSERT_EQ(h.edges.size(), h.values.size() + 1);
  ASSERT_GE(h.values.size(), 4u);
  const ShBasis y = sh_basis(-d);
  for (std::size_t i = 0; i < h.values.size(); ++i) {
    const glm::dvec3 mid = o + 0.5 * (h.edges[i] + h.edges[i + 1]) * d;
    EXPECT_DOUBLE_EQ(h.values[i], grid.eval(mid, y));
    // Isotropic phase: only band 0 is non-zero, and h is the k-NN estimate at the voxel centre.
    const glm::dvec3 centre = g.cell_center(g.cell_of(mid));
    EXPECT_NEAR(h.values[i], map.in_scattered(centre, -d, m, 30), 1e-5 * h.values[i]);
  }
}

}  // namespace
}  // namespace gcsim::media
