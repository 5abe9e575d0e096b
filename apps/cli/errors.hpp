#pragma once
// Maps whatever a command threw to `gcsim: error: ...` on stderr and its exit code
// (apps/pipeline/failure.hpp lists the codes).
#include <exception>

namespace gcsim::cli {

// Prints the error of e and returns the process's exit code.
int report_failure(std::exception_ptr e);

}  // namespace gcsim::cli
