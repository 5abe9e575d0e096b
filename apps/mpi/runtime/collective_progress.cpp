#include "apps/mpi/runtime/collective_progress.hpp"

#include <boost/context/protected_fixedsize_stack.hpp>

#include "apps/mpi/runtime/rank.hpp"

namespace gcsim::mpi_layer {

namespace {
// The blocking forms' frames are small (their buffers live on the heap); a user op runs on it too.
// Reserved with a guard page, committed only as touched.
constexpr std::size_t kScheduleStackBytes = 1 << 20;
}  // namespace

CollectiveProgress::CollectiveProgress(Rank& rank, MPI_Request request, std::function<int()> run)
    : rank_(rank), request_(request), run_(std::move(run)) {
  fiber_ = boost::context::fiber(std::allocator_arg, boost::context::protected_fixedsize_stack(kScheduleStackBytes),
                                 [this](boost::context::fiber&& caller) {
                                   caller_ = std::move(caller);
                                   try {
                                     code_ = run_();
                                   } catch (const boost::context::detail::forced_unwind&) {
                                     throw;  // destroyed unfinished: Boost.Context unwinds the stack
                                   } catch (...) {
                                     thrown_ = std::current_exception();
                                   }
                                   finished_ = true;
                                   return std::move(caller_);
                                 });
}

CollectiveProgress::~CollectiveProgress() {
  if (!fiber_) return;
  // Unwinding the unfinished schedule runs its frames' destructors: one level more than any
  // caller's, so none of them closes the rank's call (no trace record, no compute mark).
  switch_in(1);
  fiber_ = boost::context::fiber();
  set_depths(outer_);
}

bool CollectiveProgress::ready() const {
  if (finished_) return false;
  for (MPI_Request h : waiting_) {
    if (!rank_.operation(h).done) return false;
  }
  return true;
}

void CollectiveProgress::resume() {
  switch_in(0);
  fiber_ = std::move(fiber_).resume();
  switch_out();
  if (thrown_) std::rethrow_exception(std::exchange(thrown_, nullptr));
}

void CollectiveProgress::yield(const std::vector<MPI_Request>& waiting) {
  waiting_ = waiting;
  caller_ = std::move(caller_).resume();
  waiting_.clear();
}

CollectiveProgress::Depths CollectiveProgress::depths() const {
  return {rank_.registry().call.depth, rank_.computing.meter.depth, rank_.call_span.depth()};
}

void CollectiveProgress::set_depths(const Depths& d) {
  rank_.registry().call.depth = d.call;
  rank_.computing.meter.depth = d.meter;
  rank_.call_span.set_depth(d.span);
}

void CollectiveProgress::switch_in(int extra) {
  outer_ = depths();
  set_depths({outer_.call + own_.call + extra, outer_.meter + own_.meter + extra, outer_.span + own_.span + extra});
}

void CollectiveProgress::switch_out() {
  const Depths now = depths();
  own_ = {now.call - outer_.call, now.meter - outer_.meter, now.span - outer_.span};
  set_depths(outer_);
}

}  // namespace gcsim::mpi_layer
