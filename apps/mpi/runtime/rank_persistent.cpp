// Persistent requests (MPI 3.1 section 3.9): a request that outlives its operations. MPI_Start runs
// the call it was made with (`restart`: an MPI_Isend ... MPI_Irecv of the same arguments, the
// buffer read at the start, as a started send reads it); wait and test finish that operation and
// leave the request inactive, not null. An inactive one completes at once with an empty status.
#include "apps/mpi/runtime/rank.hpp"

namespace gcsim::mpi_layer {

MPI_Request Rank::add_persistent(std::string call, std::function<MPI_Request(Rank&)> restart) {
  Operation op;
  op.call = CallText::of(std::move(call));
  op.persistent = std::make_unique<Operation::Persistent>(Operation::Persistent{std::move(restart)});
  op.done = true;  // inactive
  op.charged = true;
  return add_operation(std::move(op));
}

void Rank::start_persistent(MPI_Request handle) {
  Operation& op = operation(handle);
  if (!op.persistent) fail(MPI_ERR_REQUEST, "MPI_Start: not a persistent request");
  if (op.persistent->started != MPI_REQUEST_NULL) fail(MPI_ERR_REQUEST, "MPI_Start: the request is active already");
  const MPI_Request started = op.persistent->restart(*this);
  operation(handle).persistent->started = started;
}

bool Rank::inactive(MPI_Request handle) {
  const Operation& op = operation(handle);
  return op.persistent && op.persistent->started == MPI_REQUEST_NULL;
}

// The started operation's status and error; an inactive request's status is empty. The request
// stays, inactive.
int Rank::finish_persistent(Operation& p, MPI_Status* status) {
  if (p.persistent->started != MPI_REQUEST_NULL) return finish(p.persistent->started, status);
  if (status) {
    *status = MPI_Status{};
    status->MPI_SOURCE = MPI_ANY_SOURCE;
    status->MPI_TAG = MPI_ANY_TAG;
  }
  return MPI_SUCCESS;
}

}  // namespace gcsim::mpi_layer
