// Fuzz target: the test-only triangle format (tests/scene_formats/triangles), read through the scene
// catalogue's one entry from a scratch .tri file (so the extension dispatch runs too), then lowered
// to the thesis's WORLD and to the ray tracer's primitives. The only error allowed is SceneError.
#include <variant>

#include "apps/common/scene/description_to_world.hpp"
#include "apps/common/scene/scene_catalogue.hpp"
#include "apps/common/scene/scene_error.hpp"
#include "apps/raytrace/lower_scene.hpp"
#include "tests/fuzz/fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gcsim;
  if (size > 64 * 1024) return 0;
  try {
    const scene::SceneDescription d = scene::load_scene(fuzz::scratch_file(fuzz::as_text(data, size), ".tri"));
    if (d.shapes.empty()) __builtin_trap();  // the format refuses an empty file
    for (const scene::Shape& s : d.shapes)
      if (!std::holds_alternative<scene::Polygon>(s.geometry) || std::get<scene::Polygon>(s.geometry).count != 3) __builtin_trap();
    const scene::World w = scene::to_world(d);
    std::size_t patches = 0;
    for (const scene::Entity& e : w.entities) patches += e.patches.size();
    if (patches != d.shapes.size()) __builtin_trap();  // a triangle is one patch
    const raytrace::Scene lowered = raytrace::lower_scene(d);
    if (lowered.triangles.size() != d.shapes.size() || lowered.lights.size() != 1) __builtin_trap();
  } catch (const scene::SceneError&) {
  }
  return 0;
}
