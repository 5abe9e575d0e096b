// Non-blocking collectives as deferred blocking ones: the call checks its communicator, takes its
// sequence number and records the blocking algorithm; the first test or wait of the request runs
// it, after every earlier one still pending on the same communicator (so each rank runs a
// communicator's collectives in the order it started them, as the standard requires of callers).
// Overlap of a collective with the caller's own work is thereby lost, not its results: point-to-
// point between the start and the wait proceeds, but a rank blocked in the wait does not let a
// later-started collective of another rank finish first (apps/mpi/README.md says so).
#include <vector>

#include "apps/mpi/runtime/rank.hpp"

namespace gcsim::mpi_layer {

MPI_Request Rank::start_collective(std::string call, std::int64_t context, std::function<int()> run) {
  Operation op;
  op.call = std::move(call);
  op.context = context;
  op.charged = true;  // the collective's messages pay their own overheads
  op.status.MPI_SOURCE = MPI_ANY_SOURCE;  // an empty status, as a collective's is
  op.status.MPI_TAG = MPI_ANY_TAG;
  op.collective = std::move(run);
  return add_operation(std::move(op));
}

void Rank::run_collectives_until(MPI_Request handle) {
  const std::int64_t context = operation(handle).context;
  std::vector<MPI_Request> due;  // handles grow with each start: the map's order is start order
  for (auto& [h, op] : operations_) {
    if (h > handle) break;
    if (op.collective && op.context == context) due.push_back(h);
  }
  for (MPI_Request h : due) {
    std::function<int()> run = std::move(operation(h).collective);
    operation(h).collective = nullptr;
    const int code = run();
    Operation& op = operation(h);
    op.status.MPI_ERROR = code;
    op.done = true;
  }
}

}  // namespace gcsim::mpi_layer
