// Fuzz target: ENTITY files of the radiosity scenes (thesis figures 4.4 to 4.6). A malformed file
// must raise ParseError; an accepted one must flatten into a scene or be refused with
// std::invalid_argument naming the record.
#include <stdexcept>

#include "apps/common/scene/world_loader.hpp"
#include "apps/radiosity/scene.hpp"
#include "tests/fuzz/fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gcsim::radiosity;
  try {
    World w;
    w.name = "fuzz";
    w.entities.push_back(parse_entity(gcsim::fuzz::as_text(data, size), "fuzz.ent"));
    w.instances.push_back({0, {}});
    const Scene s = flatten(w);
    (void)s.extent();
    // What the parser accepts, the writer must write and the parser read back.
    (void)parse_entity(format_entity(w.entities[0]), "formatted.ent");
  } catch (const ParseError&) {
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
