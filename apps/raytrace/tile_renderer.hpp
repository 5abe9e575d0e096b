#pragma once
// Renders subregions (tiles): nearest hits of the primary rays with the chosen algorithm, then
// shading. With Whitted shading, the first reflected and refracted rays of a tile go through the
// pencil subtrees of section 2.3; deeper rays and shadow rays use the whole tree (sorted, A2).
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "apps/common/geometry/bvh.hpp"
#include "apps/common/rng.hpp"
#include "apps/raytrace/geometry_names.hpp"
#include "apps/raytrace/camera.hpp"
#include "apps/raytrace/counters.hpp"
#include "apps/raytrace/pencil.hpp"
#include "apps/raytrace/primary_tracer.hpp"
#include "apps/raytrace/render_settings.hpp"

namespace gcsim::raytrace {

class TileRenderer {
 public:
  // shared_pairs: see PrimaryTracer.
  TileRenderer(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
               const PreparedChildPairs* shared_pairs = nullptr);

  // Colours (linear RGB) and primary hit ids (-1: background) of [x0, x1) x [y0, y1), row-major.
  // row_counters: see PrimaryTracer::trace_tile.
  void render_tile(int x0, int y0, int x1, int y1, std::span<glm::vec3> colors, std::span<std::int32_t> prims,
                   TraceCounters& counters, TraceCounters* row_counters = nullptr);
  const Camera& camera() const { return camera_; }

 private:
  enum class Bounce { reflection, refraction };
  struct SecondaryRay { Ray ray; float weight; bool valid = false; };
  glm::vec3 shade(const Ray& ray, const Hit& hit, int depth, const Pencil* reflection_pencil,
                  const Pencil* refraction_pencil, TraceCounters& counters);
  glm::vec3 shade_surface(const Ray& ray, const Hit& hit, int depth, const Pencil* reflection_pencil,
                          const Pencil* refraction_pencil, TraceCounters& counters);
  glm::vec3 local_light(const Ray& ray, const Hit& hit, const SurfacePoint& sp, bool shadows, TraceCounters& counters);
  Hit trace_secondary(const Ray& ray, const Pencil* pencil, TraceCounters& counters);
  SecondaryRay secondary_ray(const Ray& ray, const Hit& hit, Bounce kind) const;
  std::optional<Pencil> tile_pencil(const Ray corner_primary[4], const Hit corner_hits[4], Bounce kind,
                                    TraceCounters& counters) const;

  const Scene& scene_;
  const Bvh& bvh_;
  RenderSettings settings_;
  Camera camera_;
  PrimaryTracer primary_;
  std::vector<Hit> hits_;
  apps::Rng pixel_rng_;  // the current pixel's stream for the media's samples (settings_.media)
};

}  // namespace gcsim::raytrace
