#pragma once
// Processes as Boost.Fiber fibers: the one place the simulated runtime touches Boost.Fiber.
// The simulation launches a fiber per process, lets ready fibers run from its own main fiber,
// and a process suspends itself until the simulation resumes it. Another implementation
// (threads, ucontext) would replace this file only.
#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

#include <boost/fiber/all.hpp>

#include "parix/fiber_stack.hpp"

namespace gcsim::parix::detail {

// The handle by which a process suspends itself and the simulation resumes it.
class FiberContext {
 public:
  // Called first thing in the process's fiber.
  void bind_to_current() { ctx_ = boost::fibers::context::active(); }
  // From the process itself: sleep until resume().
  void suspend() { ctx_->suspend(); }
  // From any fiber: make the process runnable again.
  void resume() { boost::fibers::context::active()->schedule(ctx_); }

 private:
  boost::fibers::context* ctx_ = nullptr;
};

class FiberPool {
 public:
  static constexpr std::size_t kStackBytes = 1 << 20;
  // Starts body in a new fiber; it first runs at the next yield().
  void launch(std::function<void()> body) {
    fibers_.emplace_back(boost::fibers::launch::post, std::allocator_arg, FiberStack(kStackBytes), std::move(body));
  }
  // From the simulation's main fiber: lets the ready fibers run.
  static void yield() { boost::this_fiber::yield(); }
  // Waits until every fiber has returned.
  void join_all() {
    for (auto& f : fibers_) f.join();
  }

 private:
  std::vector<boost::fibers::fiber> fibers_;
};

}  // namespace gcsim::parix::detail
