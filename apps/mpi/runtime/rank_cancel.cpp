// MPI_Request_free and MPI_Cancel (MPI 3.1 sections 3.7.3, 3.8.4). A freed active request runs on
// and is dropped once complete. Cancel either succeeds or the communication completes, never both:
//  - a receive not matched yet is withdrawn and completes at once, cancelled;
//  - a rendezvous send (above the eager limit, or synchronous) whose request-to-send the receiver
//    has not matched yet is withdrawn there: the sender asks, the receiver drops it if still
//    unmatched and answers; the send completes cancelled on a yes, or as usual (its clear-to-send
//    comes first on the pair's ordered channel) on a no;
//  - an eager send is complete when started (its data is handed over whole), so it cannot be
//    cancelled, which the standard allows; nor can a matched receive or send, nor a collective.
#include <algorithm>

#include "apps/mpi/runtime/rank.hpp"
#include "apps/mpi/runtime/rank_letters.hpp"

namespace gcsim::mpi_layer {

void Rank::free_request(MPI_Request handle) {
  Operation& op = operation(handle);
  if (op.persistent) {
    if (op.persistent->started != MPI_REQUEST_NULL) free_request(op.persistent->started);
    operations_.erase(handle);
    return;
  }
  progress();
  Operation& op_now = operation(handle);
  if (!op_now.freed) ++freed_live_;
  op_now.freed = true;
  drop_freed();
}

void Rank::drop_freed() {
  if (freed_live_ == 0) return;  // the usual case, on every progress
  freed_live_ -= operations_.erase_if([](const Operation& op) { return op.freed && op.done; });
}

void Rank::cancel(MPI_Request handle) {
  progress_due_ = true;  // a request done now: a schedule waiting for it may go on
  Operation& op = operation(handle);
  if (op.persistent) {
    if (op.persistent->started != MPI_REQUEST_NULL) cancel(op.persistent->started);
    return;
  }
  if (op.done || op.collective) return;
  if (!op.is_send) {
    const auto posted = std::find(posted_.begin(), posted_.end(), handle);
    if (posted == posted_.end()) return;  // matched: it completes as it would have
    posted_.erase(posted);
    op.done = true;
    op.charged = true;
    op.status = MPI_Status{};
    op.status.MPI_SOURCE = MPI_ANY_SOURCE;
    op.status.MPI_TAG = MPI_ANY_TAG;
    op.status.gcsim_cancelled = 1;
    return;
  }
  if (op.wire.valid() || op.cancel_asked) return;  // its data is on the way, or asked already
  op.cancel_asked = true;
  mailbox_.send(op.peer_world, envelope(kCancelAsk, 0, op.context, 0, handle), {});
}

void Rank::on_cancel_asked(const parix::Letter& l) {
  const auto& w = l.envelope.words;
  const auto it = std::find_if(unexpected_.begin(), unexpected_.end(), [&](const Arrived& m) {
    return m.rendezvous && m.source == l.source && m.sender_op == w[3];
  });
  const bool withdrawn = it != unexpected_.end();
  if (withdrawn) unexpected_.erase(it);
  mailbox_.send(l.source, envelope(kCancelAnswer, 0, w[1], withdrawn ? 1 : 0, w[3]), {});
}

void Rank::on_cancel_answered(const parix::Letter& l) {
  const auto& w = l.envelope.words;
  Operation* op = operations_.find(w[3]);
  if (w[2] == 0 || !op) return;  // matched first: the send completes as usual
  Operation& s = *op;
  s.done = true;
  s.payload = {};
  s.status.gcsim_cancelled = 1;
}

}  // namespace gcsim::mpi_layer
