#pragma once
// Errors of the MPI layer: the core throws Error carrying an MPI error class; the C entry points
// turn it into the function's return value.
#include <stdexcept>
#include <string_view>

#include "apps/mpi/include/mpi.h"

namespace gcsim::mpi_layer {

class Error : public std::runtime_error {
 public:
  Error(int code, const char* what) : std::runtime_error(what), code_(code) {}
  int code() const { return code_; }

 private:
  int code_;
};

[[noreturn]] inline void fail(int code, const char* what) { throw Error(code, what); }

// The standard's text for an error class; empty for a code that is not one.
std::string_view error_text(int code);
bool is_error_code(int code);

}  // namespace gcsim::mpi_layer
