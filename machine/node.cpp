#include "machine/node.hpp"

namespace gcsim::machine {

void Node::compute(SimTime duration, Kernel::Action on_done) {
  Job job{duration, std::move(on_done)};
  if (free_cpus_ > 0) start(std::move(job));
  else waiting_.push_back(std::move(job));
}

void Node::start(Job job) {
  --free_cpus_;
  kernel_->after(job.duration, [this, done = std::move(job.on_done)] {
    ++free_cpus_;
    if (!waiting_.empty()) {
      Job next = std::move(waiting_.front());
      waiting_.pop_front();
      start(std::move(next));
    }
    done();
  });
}

}  // namespace gcsim::machine
