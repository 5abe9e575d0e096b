#pragma once
// Activities, as SimGrid calls them: what a process starts and later tests, waits for or cancels
// -- a computation on its node, the set-up of a connection, a communication. Each is running until
// it ends done (complete(), by the machine model's event, which wakes whoever waits on it) or
// cancelled (cancel()); the first of the two wins and the state never changes again, so an event
// arriving for a cancelled activity is ignored. Part of the API (a Request's state is one, and an
// application tests it), so it lives beside processor.hpp; the backends end activities.
//  - Computations and connection set-ups are cancelled only when a run is abandoned (deadlock,
//    error, interruption): SimProcess::wait_for_activity cancels what it was waiting for.
//  - Communications are RequestState objects (parix/processor.hpp), the activity behind a Request.
//    The application cancels them with Processor::cancel(Request&); the backend decides whether a
//    communication can still be withdrawn (see processor.hpp) and only then calls cancel().
namespace gcsim::parix::detail {

// Whoever waits for an activity (a simulated process). A plain interface rather than a
// std::function: a process sets and clears it around every blocking call, twice per message.
class Waiter {
 public:
  virtual void wake() = 0;

 protected:
  ~Waiter() = default;
};

class Activity {
 public:
  enum class State { running, done, cancelled };

  // Whom to wake when the activity ends, done or cancelled; null: nobody waits.
  Waiter* waiter = nullptr;

  State state() const { return state_; }
  bool running() const { return state_ == State::running; }
  bool test() const { return state_ == State::done; }
  bool cancelled() const { return state_ == State::cancelled; }
  void complete() {
    if (state_ != State::running) return;
    state_ = State::done;
    if (waiter) waiter->wake();
  }
  void cancel() {
    if (state_ != State::running) return;
    state_ = State::cancelled;
    if (waiter) waiter->wake();  // a waiter (another thread of the process) stops waiting
  }
  // Running again: only for an activity that is over and that nothing else refers to any more, so
  // no event can still end it (a process's blocking receive, reused for the next one).
  void rearm() { state_ = State::running; }

 private:
  State state_ = State::running;
};

}  // namespace gcsim::parix::detail
