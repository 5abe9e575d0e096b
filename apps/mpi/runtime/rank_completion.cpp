// The rank's waiting: until requests complete, probes, and the checks at MPI_Finalize.
#include <cstdio>

#include "apps/mpi/runtime/rank.hpp"

namespace gcsim::mpi_layer {

bool Rank::test(MPI_Request handle) {
  Operation& op = operation(handle);
  if (op.persistent) return op.persistent->started == MPI_REQUEST_NULL || test(op.persistent->started);
  // op stays where it is: operations live apart from the table's index, and progress drops only
  // freed ones, which no handle names.
  progress();
  if (!op.done) return false;
  call_span.involve(op.peer_world, !op.is_send);
  if (!op.is_send && !op.charged) {
    op.charged = true;
    call_span.note_received(op.status.gcsim_bytes);
    charge(op.status.gcsim_bytes);
  }
  return true;
}

int Rank::finish(MPI_Request& handle, MPI_Status* status) {
  Operation* op = operations_.find(handle);
  if (!op) fail(MPI_ERR_REQUEST, "invalid request");
  if (op->persistent) return finish_persistent(*op, status);
  const int error = op->status.MPI_ERROR;
  if (status) *status = op->status;
  operations_.erase(handle);
  handle = MPI_REQUEST_NULL;
  return error;
}

void Rank::wait_loop(Predicate done, std::string_view name, const parix::WaitDescription& call) {
  std::vector<parix::Request> wires;
  call_span.name(name);
  for (;;) {
    progress();
    if (done.test(done.object)) return;
    wires.clear();
    if (sends_on_wire_ > 0) {
      for (const OperationTable::Entry& e : operations_) {
        const Operation& op = *e.op;
        if (op.is_send && !op.done && op.wire.valid()) wires.push_back(op.wire);
      }
    }
    leave_cpu();
    const machine::SimTime blocked_from = processor_.now();
    mailbox_.await(wires, call, -1);
    mailbox_.trace_blocked(call_span.label("mpi_wait"), blocked_from, call_span.peer(), call_span.bytes());
    install();
  }
}

bool Rank::probe(const Communicator& c, int source, int tag, MPI_Status* status) {
  progress();
  Operation probe;
  probe.context = c.context;
  probe.tag = tag;
  probe.peer_world = source == MPI_ANY_SOURCE ? -1 : c.world_rank_of(source);
  for (const Arrived& m : unexpected_) {
    if (!matches(probe, m)) continue;
    if (status) {
      status->MPI_SOURCE = c.rank_of_world(m.source);
      status->MPI_TAG = m.tag;
      status->MPI_ERROR = MPI_SUCCESS;
      status->gcsim_bytes = m.size;
      status->gcsim_cancelled = 0;
    }
    return true;
  }
  return false;
}

void Rank::finalize_checks() {
  progress();
  program_ran_ = true;  // its warnings are this rank's output
  for (const OperationTable::Entry& e : operations_) {
    if (!e.op->done) {
      std::fprintf(stderr, "gcsim: warning: rank %d: MPI_Finalize with a request never completed: %s\n", world_rank(),
                   e.op->call.str().c_str());
    }
  }
  for (const Arrived& m : unexpected_) {
    if (m.context % 2 != 0) {  // a collective's: every rank's calls consume all of them unless they disagree
      std::fprintf(stderr, "gcsim: warning: rank %d: MPI_Finalize with a collective's message never received: from rank %d, "
                   "%lld bytes (the ranks' collectives did not match: a different root, count, or call)\n",
                   world_rank(), m.source, static_cast<long long>(m.size));
      continue;
    }
    std::string comm = "a freed communicator";
    for (const auto& [handle, c] : comms_) {
      if (c.context == m.context) comm = comm_name(handle);
    }
    std::fprintf(stderr, "gcsim: warning: rank %d: MPI_Finalize with a message never received: from rank %d, tag %d, %lld bytes, on %s\n",
                 world_rank(), m.source, m.tag, static_cast<long long>(m.size), comm.c_str());
  }
}

}  // namespace gcsim::mpi_layer
