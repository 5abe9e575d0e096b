// The C entry points of error handlers (MPI 3.1 section 8.3): made, attached to communicators,
// read back, freed and called. What a handler does is error_routing.cpp's.
#include "apps/mpi/c_call.hpp"
#include "apps/mpi/runtime/error_routing.hpp"
#include "apps/mpi/runtime/rank.hpp"

using namespace gcsim::mpi_layer;

namespace {

bool is_valid_errhandler(Rank& rank, MPI_Errhandler h) {
  if (h == MPI_ERRORS_ARE_FATAL || h == MPI_ERRORS_RETURN) return true;
  const UserErrhandler* user = rank.registry().errhandlers.find(h);
  return user && !user->freed;
}

}  // namespace

extern "C" {

int MPI_Comm_create_errhandler(MPI_Comm_errhandler_function* function, MPI_Errhandler* errhandler) {
  return runtime_call([&](Rank& rank) {
    MPI_Errhandler& out = out_arg(errhandler);
    if (!function) fail(MPI_ERR_ARG, "null error handler function");
    out = rank.registry().errhandlers.insert(UserErrhandler{function, false});
  });
}

int MPI_Errhandler_create(MPI_Handler_function* function, MPI_Errhandler* errhandler) {
  return MPI_Comm_create_errhandler(function, errhandler);
}

int MPI_Errhandler_free(MPI_Errhandler* errhandler) {
  return runtime_call([&](Rank& rank) {
    MPI_Errhandler& h = out_arg(errhandler);
    UserErrhandler* user = rank.registry().errhandlers.find(h);
    if (h == MPI_ERRORS_ARE_FATAL || h == MPI_ERRORS_RETURN) fail(MPI_ERR_ARG, "a predefined error handler cannot be freed");
    if (!user || user->freed) fail(MPI_ERR_ARG, "invalid or freed error handler");
    user->freed = true;  // communicators that keep it still call it (section 8.3.4)
    h = MPI_ERRHANDLER_NULL;
  });
}

int MPI_Comm_set_errhandler(MPI_Comm comm, MPI_Errhandler errhandler) {
  return runtime_call([&](Rank& rank) {
    Communicator& c = rank.comm(comm);
    if (!is_valid_errhandler(rank, errhandler)) fail(MPI_ERR_ARG, "invalid or freed error handler");
    c.errhandler = errhandler;
  });
}

int MPI_Comm_get_errhandler(MPI_Comm comm, MPI_Errhandler* errhandler) {
  return runtime_call([&](Rank& rank) { out_arg(errhandler) = rank.comm(comm).errhandler; });
}

int MPI_Errhandler_set(MPI_Comm comm, MPI_Errhandler errhandler) { return MPI_Comm_set_errhandler(comm, errhandler); }
int MPI_Errhandler_get(MPI_Comm comm, MPI_Errhandler* errhandler) { return MPI_Comm_get_errhandler(comm, errhandler); }

int MPI_Comm_call_errhandler(MPI_Comm comm, int errorcode) {
  return runtime_call([&](Rank& rank) {
    rank.comm(comm);
    run_error_handler(rank, "MPI_Comm_call_errhandler", comm, errorcode, "raised by the program");
  });
}

}  // extern "C"
