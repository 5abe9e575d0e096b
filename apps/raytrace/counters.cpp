#include "apps/raytrace/counters.hpp"

namespace gcsim::raytrace {

TraceCounters& TraceCounters::operator+=(const TraceCounters& o) {
  primary_rays += o.primary_rays;
  primary_box_tests += o.primary_box_tests;
  primary_prim_tests += o.primary_prim_tests;
  secondary_rays += o.secondary_rays;
  secondary_in_pencil += o.secondary_in_pencil;
  first_bounce_rays += o.first_bounce_rays;
  first_bounce_in_pencil_tiles += o.first_bounce_in_pencil_tiles;
  first_bounce_box_tests += o.first_bounce_box_tests;
  first_bounce_prim_tests += o.first_bounce_prim_tests;
  shadow_rays += o.shadow_rays;
  secondary_box_tests += o.secondary_box_tests;
  secondary_prim_tests += o.secondary_prim_tests;
  sphere_tests += o.sphere_tests;
  triangle_tests += o.triangle_tests;
  plane_tests += o.plane_tests;
  subtree_nodes += o.subtree_nodes;
  pencils += o.pencils;
  child_sorts += o.child_sorts;
  uniformity_tests += o.uniformity_tests;
  uniform_regions += o.uniform_regions;
  uniform_pixels += o.uniform_pixels;
  uniformity_box_checks += o.uniformity_box_checks;
  candidate_sort_entries += o.candidate_sort_entries;
  beams += o.beams;
  shades += o.shades;
  media_segments += o.media_segments;
  media_samples += o.media_samples;
  media_knn_photons += o.media_knn_photons;
  media_sh_evals += o.media_sh_evals;
  return *this;
}

std::vector<std::pair<std::string_view, std::int64_t>> TraceCounters::ops() const {
  return {
      {"rt_camera_ray", primary_rays},
      {"rt_secondary_ray", secondary_rays + shadow_rays},
      {"ray_box", box_tests()},
      {"ray_sphere", sphere_tests},
      {"ray_triangle", triangle_tests},
      {"rt_plane_box", plane_tests},
      {"rt_subtree_node", subtree_nodes},
      {"rt_child_sort", child_sorts},
      {"rt_uniform_check", uniformity_box_checks},
      {"rt_candidate_sort", candidate_sort_entries},
      {"rt_pencil", pencils},
      {"rt_shade", shades},
      {"media_camera_ray", media_segments},
      {"media_march_sample", media_samples},
      {"media_knn_lookup", media_samples},
      {"media_knn_photon", media_knn_photons},
      {"media_sh_eval", media_sh_evals},
  };
}

}  // namespace gcsim::raytrace
