#pragma once
// Exact operation counts of a render. They are the paper's measure (BV and primitive tests per
// ray, table 1(b)) and, multiplied by cycles per operation from the machine file, the simulated
// CPU time of the GC's nodes.
#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

namespace gcsim::raytrace {

struct TraceCounters {
  // Primary rays (one per pixel) and the tests they needed.
  std::int64_t primary_rays = 0;
  std::int64_t primary_box_tests = 0;
  std::int64_t primary_prim_tests = 0;
  // Secondary (reflection, refraction) and shadow rays, and their tests.
  std::int64_t secondary_rays = 0;
  std::int64_t secondary_in_pencil = 0;   // secondary rays traced through a pencil subtree (2.3)
  // First-generation reflected/refracted rays (the ones pencils are for), those of subregions that
  // had a pencil, and the tests the first generation needed.
  std::int64_t first_bounce_rays = 0;
  std::int64_t first_bounce_in_pencil_tiles = 0;
  std::int64_t first_bounce_box_tests = 0;
  std::int64_t first_bounce_prim_tests = 0;
  std::int64_t shadow_rays = 0;
  std::int64_t secondary_box_tests = 0;
  std::int64_t secondary_prim_tests = 0;
  // Split of all primitive tests by kind (for the cost model).
  std::int64_t sphere_tests = 0;
  std::int64_t triangle_tests = 0;
  // Building subtrees (2.2.1) and pencils (2.3): box-against-plane classifications, nodes made.
  std::int64_t plane_tests = 0;
  std::int64_t subtree_nodes = 0;
  std::int64_t pencils = 0;
  // Front-to-back child ordering (2.2.2): one comparison per expanded node with two box children.
  std::int64_t child_sorts = 0;
  // Uniformity test (2.2.3): regions tested, regions found uniform, pixels filled from them.
  std::int64_t uniformity_tests = 0;
  std::int64_t uniform_regions = 0;
  std::int64_t uniform_pixels = 0;
  // Boxes and triangles looked at by the test (a distance or a plane side, not a ray test:
  // the paper's test reads the subtree's flags; these are reported apart from BV tests).
  std::int64_t uniformity_box_checks = 0;
  // Ray classification (B1): candidate-list entries sorted by distance.
  std::int64_t candidate_sort_entries = 0;
  std::int64_t beams = 0;
  // Shading evaluations (one per hit point shaded).
  std::int64_t shades = 0;
  // Participating media (RayMedia): ray segments inside a medium, distance samples along them (each
  // a k-nearest-photon query of k_nearest photons), SH histogram bins reconstructed.
  std::int64_t media_segments = 0;
  std::int64_t media_samples = 0;
  std::int64_t media_knn_photons = 0;
  std::int64_t media_sh_evals = 0;

  std::int64_t box_tests() const { return primary_box_tests + secondary_box_tests; }
  std::int64_t prim_tests() const { return primary_prim_tests + secondary_prim_tests; }

  TraceCounters& operator+=(const TraceCounters& o);

  // The operations charged to a simulated processor, by the names of the [ops] table of
  // configs/*.toml.
  std::vector<std::pair<std::string_view, std::int64_t>> ops() const;
};

}  // namespace gcsim::raytrace
