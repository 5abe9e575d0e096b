#include "machine/kernel.hpp"

#include <stdexcept>
#include <string>

namespace gcsim::machine {

void Kernel::at(SimTime t, Action action) {
  if (t < now_) {
    throw std::logic_error("Kernel::at: event scheduled in the past (" + std::to_string(t) + " ps < now " +
                           std::to_string(now_) + " ps)");
  }
  queue_.push(Event{t, seq_++, std::move(action)});
}

bool Kernel::step() {
  if (queue_.empty()) return false;
  // priority_queue::top is const; the action is moved out through a const_cast before pop, which
  // is safe because the element is removed immediately and the ordering keys are untouched.
  Event& top = const_cast<Event&>(queue_.top());
  now_ = top.time;
  Action action = std::move(top.action);
  queue_.pop();
  ++processed_;
  action();
  return true;
}

}  // namespace gcsim::machine
