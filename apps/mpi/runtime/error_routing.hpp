#pragma once
// The runtime's side of MPI 3.1 section 8.3: an error goes through the error handler of the
// communicator the call names (error_handling.hpp says which), as the standard defines them:
// MPI_ERRORS_ARE_FATAL (the default on MPI_COMM_WORLD and MPI_COMM_SELF, inherited by every
// communicator made from them) ends the run; MPI_ERRORS_RETURN returns the code; a user handler
// (MPI_Comm_create_errhandler) is called with the communicator and the code, then the code is
// returned.
#include <string>
#include <string_view>

#include "apps/mpi/error_handling.hpp"

namespace gcsim::mpi_layer {

class Rank;

// MPI_ERRORS_ARE_FATAL acted on: unwinds every rank; gcsim mpirun prints `gcsim: MESSAGE` and
// exits with its code for MPI errors. message: "rank 3: MPI_Send: invalid rank 9 ... [MPI_ERR_RANK]".
struct FatalMpiError {
  int rank;
  std::string message;
};

// gcsim mpirun's exit status after a fatal MPI error (README "Exit codes", `gcsim --help`).
inline constexpr int kMpiErrorExitCode = 6;

// The router the ranks' registries use (it works on the rank whose fiber runs).
ErrorRouter& runtime_error_router();

// Runs comm's handler (MPI_COMM_WORLD's if comm is gone) on code, raised by call with the reason
// what; returns code, or throws FatalMpiError.
int run_error_handler(Rank& rank, const std::string& call, MPI_Comm comm, int code, std::string_view what);

// "MPI_ERR_RANK" for an error class, "error code 77" for another code.
std::string error_class_name(int code);

}  // namespace gcsim::mpi_layer
