// The run loop: fibers run until all block, then the kernel advances to the next event; a run in
// which every processor is blocked and no event is pending is a deadlock.
#include "parix/sim/process_lifetime.hpp"

#include <algorithm>
#include <string>

#include "parix/host/interruption.hpp"
#include "parix/sim/deadlock_report.hpp"
#include "parix/sim/sim_process.hpp"

namespace gcsim::parix::detail {

ProcessLifetime::ProcessLifetime(machine::Kernel& kernel, std::vector<ProcessorStats>& stats, std::size_t stack_bytes)
    : kernel_(kernel), stats_(stats), fibers_(stack_bytes) {}

ProcessLifetime::~ProcessLifetime() = default;

SimProcess& ProcessLifetime::add(std::unique_ptr<SimProcess> p) { return *all_.emplace_back(std::move(p)); }

int ProcessLifetime::threads_of(int id) const {
  return static_cast<int>(std::count_if(all_.begin(), all_.end(), [id](const auto& p) { return p->id() == id; }));
}

void ProcessLifetime::launch(SimProcess* p, std::function<void(Processor&)> body) {
  fibers_.launch(p->fiber, [this, p, body = std::move(body)] {
    try {
      if (!cancelling_) body(*p);  // a run abandoned before this fiber first ran skips it
    } catch (const Cancelled&) {
    } catch (...) {
      if (!failure_) failure_ = std::current_exception();
    }
    p->drop_persistent_links();
    finish(p);
  });
  ++live_;
}

void ProcessLifetime::finish(SimProcess* p) {
  p->finished = true;
  auto& s = stats_[p->id()];
  s.finish = std::max(s.finish, kernel_.now());
  if (p->joiner) p->joiner->wake();
  --live_;
}

ProcessLifetime::End ProcessLifetime::run(const std::function<void(Processor&)>& program) {
  try {
    for (auto& p : all_) launch(p.get(), program);
  } catch (...) {
    failure_ = std::current_exception();  // out of host memory: unwind what was launched
    cancelling_ = true;
  }
  End end = End::finished;
  for (;;) {
    fibers_.run_ready();  // every woken fiber runs until it blocks or returns
    if (failure_ || live_ == 0) break;
    if (host::interruption_requested()) {  // SIGINT/SIGTERM (parix/host/interruption.hpp): one relaxed load per event
      end = End::interrupted;
      break;
    }
    if (!kernel_.step()) {
      end = End::deadlock;
      break;
    }
  }
  if (end == End::deadlock) deadlock_report_ = report_blocked();
  if (end != End::finished || failure_) {
    // Unwind every blocked fiber so that their stacks are released cleanly.
    cancelling_ = true;
    for (auto& p : all_) p->wake();
    fibers_.run_ready();
  } else {
    kernel_.run();  // messages still in flight after the last processor returned
  }
  fibers_.join_all();
  return failure_ ? End::failed : end;
}

std::string ProcessLifetime::report_blocked() const {
  std::vector<BlockedProcess> blocked;
  std::vector<std::string> described;  // the texts of lazily described waits, kept for the report
  described.reserve(all_.size());      // no reallocation: the report points into them
  for (const auto& p : all_) {
    if (p->finished) continue;
    const char* call = p->blocked_call;
    if (p->blocked_description && call) call = described.emplace_back(p->blocked_description->text()).c_str();
    blocked.push_back({p->id(), p->thread(), call, p->blocked_peer, p->blocked_since});
  }
  return parix::deadlock_report(kernel_.now(), blocked);
}

}  // namespace gcsim::parix::detail
