#pragma once
// The lifetime of a simulated run's processes: each processor and thread is a SimProcess in its own
// fiber, launched here, run by the loop (fibers until all block, then one kernel event), and
// unwound when the run is abandoned. Every process blocked with no event pending is a deadlock.
#include <cstddef>
#include <exception>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "machine/kernel.hpp"
#include "parix/processor.hpp"
#include "parix/run_result.hpp"
#include "parix/sim/fiber_processes.hpp"

namespace gcsim::parix::detail {

class SimProcess;

// Thrown into a blocked fiber to unwind it when the run is abandoned (deadlock or an error
// elsewhere). Deliberately not a std::exception, so application handlers do not catch it.
struct Cancelled {};

class ProcessLifetime {
 public:
  enum class End { finished, deadlock, failed, interrupted };

  // stats: per processor, sized before any process exists; a process's finish time goes there.
  ProcessLifetime(machine::Kernel& kernel, std::vector<ProcessorStats>& stats, std::size_t stack_bytes);
  ProcessLifetime(const ProcessLifetime&) = delete;
  ProcessLifetime& operator=(const ProcessLifetime&) = delete;
  ~ProcessLifetime();

  // Adds a process (a processor's main thread or a spawned one), not started yet.
  SimProcess& add(std::unique_ptr<SimProcess> p);
  // Starts p's fiber; throws, with nothing started, if no fiber stack can be mapped.
  void launch(SimProcess* p, std::function<void(Processor&)> body);
  // Runs the processes added so far, each running program, until all returned or the run is
  // deadlocked, failed or interrupted; an abandoned run's fibers are unwound. A deadlock's report
  // is in deadlock_report, made before the unwinding.
  End run(const std::function<void(Processor&)>& program);
  const std::string& deadlock_report() const { return deadlock_report_; }

  // The processes (and threads) of processor `id` so far.
  int threads_of(int id) const;
  // Whether the run is being abandoned: blocking calls then throw Cancelled.
  bool cancelling() const { return cancelling_; }
  // The first exception a process (or an event) raised; rethrown when the run ends.
  const std::exception_ptr& failure() const { return failure_; }
  void fail(std::exception_ptr e) {
    if (!failure_) failure_ = std::move(e);
  }

 private:
  void finish(SimProcess* p);
  std::string report_blocked() const;

  machine::Kernel& kernel_;
  std::vector<ProcessorStats>& stats_;
  std::vector<std::unique_ptr<SimProcess>> all_;
  FiberPool fibers_;
  int live_ = 0;
  bool cancelling_ = false;
  std::exception_ptr failure_;
  std::string deadlock_report_;
};

}  // namespace gcsim::parix::detail
