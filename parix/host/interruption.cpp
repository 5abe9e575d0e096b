#include "parix/host/interruption.hpp"

#include <atomic>

namespace gcsim::parix::host {

void request_interruption() noexcept { detail::interruption_flag.store(true, std::memory_order_relaxed); }
void clear_interruption() noexcept { detail::interruption_flag.store(false, std::memory_order_relaxed); }

void throw_if_interrupted() {
  if (interruption_requested()) throw Interrupted(RunResult{});
}

}  // namespace gcsim::parix::host
