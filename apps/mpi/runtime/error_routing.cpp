#include "apps/mpi/runtime/error_routing.hpp"

#include <cstdio>

#include "apps/mpi/runtime/rank.hpp"

namespace gcsim::mpi_layer {
namespace {

class RuntimeErrorRouter final : public ErrorRouter {
 public:
  int raise(const char* call, MPI_Comm target, const Error& e) override {
    return run_error_handler(Rank::current(), entry_point_name(call), target, e.code(), e.what());
  }
};

// The handler in force: the communicator's, or MPI_COMM_WORLD's for one freed since (a request's).
MPI_Errhandler handler_of(Rank& rank, MPI_Comm& comm) {
  try {
    return rank.comm(comm).errhandler;
  } catch (const Error&) {
    comm = MPI_COMM_WORLD;
    return rank.comm(comm).errhandler;
  }
}

std::string fatal_message(const Rank& rank, const std::string& call, int code, std::string_view what) {
  if (what.starts_with(call + ": ")) what.remove_prefix(call.size() + 2);  // collectives name themselves
  const bool describes_call = what.starts_with(call + "(");                 // a mismatch names both calls
  return "rank " + std::to_string(rank.world_rank()) + ": " + (describes_call ? "" : call + ": ") + std::string(what) +
         " [" + error_class_name(code) + "]";
}

}  // namespace

ErrorRouter& runtime_error_router() {
  static RuntimeErrorRouter router;  // stateless: it works on Rank::current()
  return router;
}

std::string error_class_name(int code) {
  const std::string_view text = error_text(code);
  if (text.empty()) return "error code " + std::to_string(code);
  return std::string(text.substr(0, text.find(':')));
}

int run_error_handler(Rank& rank, const std::string& call, MPI_Comm comm, int code, std::string_view what) {
  const MPI_Errhandler handler = handler_of(rank, comm);
  if (handler == MPI_ERRORS_RETURN) return code;
  if (handler != MPI_ERRORS_ARE_FATAL) {
    if (const UserErrhandler* user = rank.registry().errhandlers.find(handler)) {
      MPI_Comm handler_comm = comm;
      int handler_code = code;
      user->function(&handler_comm, &handler_code);
      return code;
    }
  }
  std::fflush(stdout);  // what the rank printed before the error is its output
  throw FatalMpiError{rank.world_rank(), fatal_message(rank, call, code, what)};
}

}  // namespace gcsim::mpi_layer
