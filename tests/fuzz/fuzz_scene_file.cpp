// Fuzz target: the TOML scene file (apps/common/scene/scene_file.hpp), read with the scenes/ folder
// as its base (so seeds that name meshes find them) and lowered to the thesis's WORLD when its
// radiosity mesh is small. The only error allowed is SceneFileError.
#include <string>
#include <variant>

#include "apps/common/scene/description_to_world.hpp"
#include "apps/common/scene/scene_file.hpp"
#include "tests/fuzz/fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gcsim::scene;
  if (size > 64 * 1024) return 0;
  try {
    const SceneDescription d =
        parse_scene_file(gcsim::fuzz::as_text(data, size), "fuzz.toml", std::string(GCSIM_SOURCE_DIR) + "/scenes");
    long elements = 0;
    for (const Shape& s : d.shapes) {
      if (s.material < 0 || s.material >= int(d.materials.size())) __builtin_trap();
      if (const auto* p = std::get_if<Polygon>(&s.geometry))
        elements += long(p->patch_columns) * p->patch_rows * p->element_columns * p->element_rows;
    }
    if (elements <= 100000) {
      const World w = to_world(d);
      if (w.instances.size() != w.entities.size()) __builtin_trap();
    }
  } catch (const SceneFileError&) {
  }
  return 0;
}
