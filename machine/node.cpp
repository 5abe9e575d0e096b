#include "machine/node.hpp"

namespace gcsim::machine {

void Node::compute(SimTime duration, Kernel::Action&& on_done) {
  if (free_cpus_ > 0) start(duration, std::move(on_done));  // moved once, into its running slot
  else waiting_.push_back({duration, std::move(on_done)});
}

void Node::start(SimTime duration, Kernel::Action&& on_done) {
  --free_cpus_;
  std::uint32_t slot = 0;
  if (free_slots_.empty()) {
    slot = static_cast<std::uint32_t>(running_.size());
    running_.push_back(std::move(on_done));
  } else {
    slot = free_slots_.back();
    free_slots_.pop_back();
    running_[slot].fill(std::move(on_done));  // emptied by finish()
  }
  kernel_->after(duration, [this, slot] { finish(slot); });
}

void Node::compute(SimTime duration, void (*done)(void*), void* context) {
  if (free_cpus_ == 0) return compute(duration, [done, context] { done(context); });
  --free_cpus_;
  kernel_->after(duration, [this, done, context] {
    release_cpu();
    done(context);
  });
}

void Node::finish(std::uint32_t slot) {
  Kernel::Action done = std::move(running_[slot]);
  free_slots_.push_back(slot);
  release_cpu();
  done();
}

void Node::release_cpu() {
  ++free_cpus_;
  if (!waiting_.empty()) {
    Job next = std::move(waiting_.front());
    waiting_.pop_front();
    start(next.duration, std::move(next.on_done));
  }
}

}  // namespace gcsim::machine
