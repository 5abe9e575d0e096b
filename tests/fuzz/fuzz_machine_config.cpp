// Fuzz target: machine files (TOML). A malformed file must raise ConfigError, nothing else.
#include "machine/machine_config.hpp"
#include "tests/fuzz/fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const gcsim::machine::MachineConfig c = gcsim::machine::parse_machine_config(gcsim::fuzz::as_text(data, size), "fuzz.toml");
    // An accepted machine must be usable: the mesh shape and op times of every node count.
    for (int n = 1; n <= c.nodes && n <= 64; n *= 2) (void)gcsim::machine::with_nodes(c, n);
  } catch (const gcsim::machine::ConfigError&) {
  }
  return 0;
}
