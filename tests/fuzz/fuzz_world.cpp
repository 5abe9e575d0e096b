// Fuzz target: WORLD files. Entity files they name are looked up in tests/radiosity/fixtures
// (square.ent, square_lit.ent), so instances of real entities get placed and flattened; errors
// must be ParseError (or invalid_argument from flattening), never a crash.
#include <stdexcept>

#include "apps/common/scene/world_loader.hpp"
#include "apps/radiosity/scene.hpp"
#include "tests/fuzz/fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gcsim::radiosity;
  try {
    const World w = parse_world(gcsim::fuzz::as_text(data, size), "fuzz.wld", GCSIM_SOURCE_DIR "/tests/radiosity/fixtures");
    (void)flatten(w);
  } catch (const ParseError&) {
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
