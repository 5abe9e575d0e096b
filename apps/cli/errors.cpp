#include "apps/cli/errors.hpp"

#include <new>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "apps/common/scene/scene_error.hpp"
#include "apps/pipeline/command_groups.hpp"
#include "apps/pipeline/failure.hpp"
#include "apps/pipeline/resource_check.hpp"
#include "machine/input_file.hpp"
#include "machine/output_file.hpp"
#include "machine/machine_config.hpp"
#include "parix/host/interruption.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::cli {

using namespace pipeline;

namespace {

// What() may end in a newline (deadlock reports are several lines); print_error adds one if not.
int fail(const std::exception& e, int code) {
  print_error(e.what());
  return code;
}

}  // namespace

int report_failure(std::exception_ptr e) {
  try {
    std::rethrow_exception(e);
  } catch (const ExitStatus& s) {  // the command printed its own message (e.g. the plot script's)
    return s.code;
  } catch (const CLI::ParseError& x) {  // a check in a command's callback (CLI::ValidationError)
    return fail(x, kExitUsage);
  } catch (const parix::host::Interrupted& x) {
    // Host-side loops (accuracy tables, renders on the host) have no simulated clock to report.
    print_error(x.partial().makespan > 0 ? fmt::format("interrupted at simulated time {:.6f} s; finished results were written",
                                                       x.partial().simulated_seconds())
                                         : std::string("interrupted; finished results were written"));
    return kExitInterrupted;
  } catch (const parix::DeadlockError& x) {
    return fail(x, kExitDeadlock);
  } catch (const parix::OutOfMemoryError& x) {  // a node's memory (--memory-limit warn continues)
    return fail(x, kExitResource);
  } catch (const HostMemoryError& x) {
    return fail(x, kExitResource);
  } catch (const std::bad_alloc&) {
    print_error("out of host memory");
    return kExitResource;
  } catch (const FileError& x) {
    return fail(x, kExitFile);
  } catch (const machine::OutputFileError& x) {  // a write or close failed (a full disk, /dev/full)
    return fail(x, kExitFile);
  } catch (const machine::InputFileError& x) {  // a trace's CSV, a run JSON
    return fail(x, kExitFile);
  } catch (const machine::ConfigError& x) {
    return fail(x, kExitFile);
  } catch (const scene::SceneError& x) {  // every scene loader's errors (TOML, OBJ, WORLD, ...)
    return fail(x, kExitFile);
  } catch (const RunFailure& x) {
    return fail(x, kExitRunFailed);
  } catch (const std::invalid_argument& x) {  // option values the commands check themselves
    return fail(x, kExitUsage);
  } catch (const std::out_of_range& x) {
    return fail(x, kExitUsage);
  } catch (const std::exception& x) {
    return fail(x, kExitRunFailed);
  } catch (...) {
    print_error("unknown failure");
    return kExitRunFailed;
  }
}

}  // namespace gcsim::cli
