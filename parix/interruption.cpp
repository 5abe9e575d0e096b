#include "parix/interruption.hpp"

#include <atomic>

namespace gcsim::parix {

namespace {
std::atomic<bool> requested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "a signal handler may only touch lock-free atomics");
}  // namespace

void request_interruption() noexcept { requested.store(true, std::memory_order_relaxed); }
bool interruption_requested() noexcept { return requested.load(std::memory_order_relaxed); }
void clear_interruption() noexcept { requested.store(false, std::memory_order_relaxed); }

void throw_if_interrupted() {
  if (interruption_requested()) throw Interrupted(RunResult{});
}

}  // namespace gcsim::parix
