#pragma once
// One way to fail: every error is printed as `gcsim: error: ...` on stderr and ends the process
// with one of these codes (README "Exit codes", `gcsim --help`). Commands throw the error type
// that says what went wrong; apps/cli/errors.cpp maps every exception to its code.
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace gcsim::pipeline {

enum ExitCode : int {
  kExitOk = 0,
  kExitRunFailed = 1,     // the run went wrong or did not reach its goal (e.g. a threshold not reached)
  kExitUsage = 2,         // the command line: unknown option, bad value, inconsistent options
  kExitFile = 3,          // a file that cannot be read, parsed or written (scene, machine file, output path)
  kExitResource = 4,      // host or node memory exhausted
  kExitDeadlock = 5,      // every simulated processor blocked with nothing pending
  kExitInterrupted = 130, // SIGINT or SIGTERM: what was finished is written, marked "interrupted"
  // 70: a simulated processor overflowed its fiber stack (parix/sim/fiber_stack.hpp; raise fiber_stack_kib)
};

// The exit codes as the help footer and README list them.
std::string exit_code_table();

// A file cannot be read, parsed or written.
class FileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The run finished but did not do what was asked (e.g. the energy threshold was not reached).
class RunFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Prints `gcsim: error: MESSAGE` on stderr (one line, a trailing newline added if missing).
void print_error(std::string_view message);

// Checks before any work that each non-empty path can be written: its directory exists and a
// file can be created there (created files are removed again; existing files are not touched).
// `option` names the option in the error, e.g. "--json". Throws FileError.
void check_writable(const std::string& path, std::string_view option);

}  // namespace gcsim::pipeline
