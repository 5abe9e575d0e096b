// Fuzz target: the trace CSV that `gcsim paje` reads, converted to Paje as the command does.
// A malformed file must raise std::runtime_error naming the file and line.
#include <stdexcept>

#include "machine/paje_writer.hpp"
#include "machine/trace_csv.hpp"
#include "tests/fuzz/fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string csv = gcsim::fuzz::scratch_file(gcsim::fuzz::as_text(data, size), ".csv");
  try {
    const gcsim::machine::TraceCsv trace = gcsim::machine::read_trace_csv(csv);
    gcsim::machine::write_paje(trace, "/dev/null");
  } catch (const std::runtime_error&) {
  }
  return 0;
}
