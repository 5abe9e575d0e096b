#include "machine/node.hpp"

namespace gcsim::machine {

void Node::compute(SimTime duration, Kernel::Action on_done) {
  Job job{duration, std::move(on_done)};
  if (free_cpus_ > 0) start(std::move(job));
  else waiting_.push_back(std::move(job));
}

void Node::start(Job job) {
  --free_cpus_;
  std::uint32_t slot = 0;
  if (free_slots_.empty()) {
    slot = static_cast<std::uint32_t>(running_.size());
    running_.push_back(std::move(job.on_done));
  } else {
    slot = free_slots_.back();
    free_slots_.pop_back();
    running_[slot] = std::move(job.on_done);
  }
  kernel_->after(job.duration, [this, slot] { finish(slot); });
}

void Node::finish(std::uint32_t slot) {
  Kernel::Action done = std::move(running_[slot]);
  free_slots_.push_back(slot);
  ++free_cpus_;
  if (!waiting_.empty()) {
    Job next = std::move(waiting_.front());
    waiting_.pop_front();
    start(std::move(next));
  }
  done();
}

}  // namespace gcsim::machine
