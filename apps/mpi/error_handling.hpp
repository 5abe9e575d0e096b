#pragma once
// Where an error of a C entry point goes (MPI 3.1 section 8.3): through the error handler of the
// communicator the call names (its request's for a request call, MPI_COMM_WORLD's for a call with
// neither). The core only knows which call runs and which communicator it named; the runtime,
// which owns the communicators and their handlers, installs the ErrorRouter that acts on them.
// Without one (a single process, the core's tests) every error is returned.
#include <source_location>
#include <string>

#include "apps/mpi/error.hpp"
#include "apps/mpi/include/mpi.h"

namespace gcsim::mpi_layer {

struct Registry;

// A handler made by MPI_Comm_create_errhandler; freed ones still run for the communicators that
// keep them, as the standard says, but their handle is no longer valid.
struct UserErrhandler {
  MPI_Comm_errhandler_function* function = nullptr;
  bool freed = false;
};

// The entry point a rank is in. A nested one (MPI_Finalize's barrier) returns its error to the
// outer one, so each error meets one handler, named after the call the program made.
struct CallInProgress {
  int depth = 0;
  const char* signature = "";  // "int MPI_Send(const void*, ...)" or just "MPI_Send"
  MPI_Comm target = MPI_COMM_WORLD;
  bool target_named = false;
  // The first communicator (or request's communicator) the call looks up successfully.
  void name_target(MPI_Comm comm) {
    if (depth == 1 && !target_named) target = comm, target_named = true;
  }
};

class ErrorRouter {
 public:
  // Runs the target's handler on e; returns what the call returns (or throws to end the run).
  virtual int raise(const char* call, MPI_Comm target, const Error& e) = 0;

 protected:
  ~ErrorRouter() = default;
};

// "MPI_Send" from a function signature as std::source_location spells it ("int gcsim_MPI_Send(const
// void*, ...)": the link name), or a bare name.
std::string entry_point_name(const char* signature);

// Marks one entry point running on r's rank; raise() routes its error.
class CallScope {
 public:
  CallScope(Registry& r, const char* signature);
  ~CallScope();
  CallScope(const CallScope&) = delete;
  CallScope& operator=(const CallScope&) = delete;
  int raise(const Error& e);

 private:
  Registry& registry_;
};

}  // namespace gcsim::mpi_layer
