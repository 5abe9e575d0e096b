// Fuzz target: the run JSON that `gcsim report` reads (written by --json), turned into the HTML
// page as the command does. A malformed file must raise std::runtime_error naming the file
// (gcsim maps it to exit status 3); a JSON of the wrong shape (a string where a number was
// written, a huge number, an array for an object) must too, or be shown as it is. Any other
// exception escapes and is a finding. The plotting script is replaced by /bin/true: the page's
// trace section is the report's, not the plots'.
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "apps/cli/trace_run_report.hpp"
#include "tests/fuzz/fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool quiet_plots = ::setenv("GCSIM_PYTHON", "/bin/true", 1) == 0;
  (void)quiet_plots;
  const std::string json = gcsim::fuzz::scratch_file(gcsim::fuzz::as_text(data, size), ".json");
  const std::string out = json + ".report";
  try {
    gcsim::cli::write_run_report({json, out, ""});
  } catch (const std::runtime_error&) {
  }
  std::error_code ec;
  std::filesystem::remove_all(out, ec);
  return 0;
}
