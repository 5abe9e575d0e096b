#pragma once
// Host-process control, not part of the PARIX API: stopping a run from outside (SIGINT, SIGTERM).
// A signal handler may only set a lock-free atomic, so the request is a flag that the simulated
// backend's loop polls (parix/sim/process_lifetime.cpp) and host-side loops check. The run then
// unwinds every processor, closes its trace and throws Interrupted with what it had reached.
#include <atomic>
#include <stdexcept>
#include <string>

#include "parix/run_result.hpp"

namespace gcsim::parix::host {

namespace detail {
// Inline, so that the simulation's loop reads it without a call once per event.
inline std::atomic<bool> interruption_flag{false};
static_assert(std::atomic<bool>::is_always_lock_free, "a signal handler may only touch lock-free atomics");
}  // namespace detail

// Async-signal-safe: sets the flag only.
void request_interruption() noexcept;
inline bool interruption_requested() noexcept { return detail::interruption_flag.load(std::memory_order_relaxed); }
// For tests and for a process that runs again after reporting an interruption.
void clear_interruption() noexcept;

// Thrown by a run that stopped because interruption_requested(); `partial` holds the simulated
// time reached (makespan = the kernel's clock), the events and the per-processor counters so far.
class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(RunResult partial)
      : std::runtime_error("interrupted at simulated time " + std::to_string(partial.simulated_seconds()) + " s"),
        partial_(std::move(partial)) {}
  const RunResult& partial() const { return partial_; }

 private:
  RunResult partial_;
};

// For loops that run outside a simulation (accuracy tables, host-side solves): throws Interrupted
// with nothing simulated reached once an interruption was requested.
void throw_if_interrupted();

}  // namespace gcsim::parix::host
