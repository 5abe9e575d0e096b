#pragma once
// The ray tracer's command-line options (run, sweep, bench) and the reports its commands share.
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "apps/common/geometry/bvh.hpp"
#include "apps/raytrace/counters.hpp"
#include "apps/raytrace/render_settings.hpp"
#include "apps/raytrace/scene.hpp"

namespace gcsim::raytrace::app {

struct RenderOptions {
  std::string scene = "teapots";
  std::string algo = "A4";
  int tile = 8;
  int size = 512;
  std::string shading = "auto";
  bool no_pencils = false;
  int max_depth = 5;
};

// --scene, --algo, --tile, --size and, with shading_options, --shading, --no-pencils, --max-depth.
void add_render_options(CLI::App* cmd, RenderOptions& o, bool shading_options = true);
RenderSettings settings_of(const RenderOptions& o, const Scene& scene);
// A built-in scene or an OBJ file; a bad one fails as a --scene validation error.
Scene load_scene_or_fail(const std::string& name);
void print_scene(const Scene& s, const Bvh& bvh);
nlohmann::json counters_json(const TraceCounters& c);
void print_counters(const TraceCounters& c);

}  // namespace gcsim::raytrace::app
