// Non-blocking collectives that progress: the call checks its communicator, takes its sequence
// number and starts the blocking form's schedule on a coroutine of its own (collective_progress.hpp),
// which runs at once until it first waits (so its first messages leave at the call, as a real
// library posts them). Every later progress of the rank (each test, wait, probe, send or receive,
// and each wake-up by a letter while it waits for anything) resumes the schedules whose awaited
// requests are complete, in start order; a schedule that ends completes its request with its
// error code. Collectives of one communicator match by their sequence numbers (collective_tags.hpp),
// so several may be in flight at once, and point-to-point between them proceeds.
#include <algorithm>
#include <vector>

#include "apps/mpi/runtime/rank.hpp"

namespace gcsim::mpi_layer {

MPI_Request Rank::start_collective(std::string call, std::int64_t context, std::function<int()> run) {
  call_span.describe(call);  // the start's own overheads are the MPI_I... call's, in the trace
  Operation op;
  op.call = CallText::of(std::move(call));
  op.context = context;
  op.charged = true;  // the collective's messages pay their own overheads
  op.status.MPI_SOURCE = MPI_ANY_SOURCE;  // an empty status, as a collective's is
  op.status.MPI_TAG = MPI_ANY_TAG;
  op.collective = true;
  const MPI_Request handle = add_operation(std::move(op));
  schedules_.push_back(std::make_unique<CollectiveProgress>(*this, handle, std::move(run)));
  if (!running_schedule_) run_schedule(*schedules_.back());
  drop_finished_schedules();
  return handle;
}

void Rank::advance_collectives() {
  if (running_schedule_ || schedules_.empty()) return;  // a schedule's own waits do not nest
  for (std::size_t i = 0; i < schedules_.size(); ++i) {
    if (schedules_[i]->ready()) run_schedule(*schedules_[i]);
  }
  drop_finished_schedules();
}

void Rank::run_schedule(CollectiveProgress& schedule) {
  struct Running {  // cleared also when the schedule rethrows (an abandoned run, MPI_Abort)
    CollectiveProgress*& running;
    ~Running() { running = nullptr; }
  } running{running_schedule_};
  running_schedule_ = &schedule;
  schedule.resume();
  if (!schedule.finished()) return;
  Operation& op = operation(schedule.request());  // a freed request is dropped only once done
  op.status.MPI_ERROR = schedule.code();
  op.done = true;
}

void Rank::drop_finished_schedules() {
  std::erase_if(schedules_, [](const std::unique_ptr<CollectiveProgress>& s) { return s->finished(); });
  drop_freed();
}

}  // namespace gcsim::mpi_layer
