#pragma once
// Activities, as SimGrid calls them: what a simulated process starts and later waits for -- a
// computation on its node, the set-up of a connection, a communication. The machine model
// finishes an activity by an event (complete()), which wakes the process waiting on it. A process
// can test an activity without blocking, wait for it (SimProcess::wait_for_activity), or cancel it
// when the run is abandoned; a cancelled activity ignores its completion.
// Communications are RequestState objects (parix/processor.hpp), the activity behind a Request.
#include <functional>

namespace gcsim::parix::detail {

class Activity {
 public:
  enum class State { running, done, cancelled };

  // The process (or whoever) to wake when the activity completes; empty: nobody waits.
  std::function<void()> on_complete;

  State state() const { return state_; }
  bool test() const { return state_ == State::done; }
  void complete() {
    if (state_ != State::running) return;
    state_ = State::done;
    if (on_complete) on_complete();
  }
  void cancel() {
    if (state_ == State::running) state_ = State::cancelled;
  }

 private:
  State state_ = State::running;
};

}  // namespace gcsim::parix::detail
