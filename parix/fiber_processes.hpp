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
  // From the process itself: sleep until resume(). Checks the stack first (see fiber_stack.hpp):
  // no other fiber may run after this one smashed a neighbour's stack.
  void suspend() {
    check_stack();
    ctx_->suspend();
  }
  // From any fiber of the same host thread: make the process runnable again. Straight to its
  // scheduler: context::active()->schedule() would first look up the running fiber in
  // thread-local storage, which costs more than the rest of a wake-up.
  void resume() { ctx_->get_scheduler()->schedule(ctx_); }
  void check_stack() const {
    if (canary_ && !canary_->intact()) report_stack_overflow(stack_bytes_);
  }

 private:
  friend class FiberPool;
  boost::fibers::context* ctx_ = nullptr;
  const StackCanary* canary_ = nullptr;  // null: the stack has a guard page
  std::size_t stack_bytes_ = 0;
};

class FiberPool {
 public:
  explicit FiberPool(std::size_t stack_bytes) : stacks_(std::make_shared<FiberStackPool>(stack_bytes)) {}
  FiberPool(const FiberPool&) = delete;
  FiberPool& operator=(const FiberPool&) = delete;
  ~FiberPool() {
    fibers_.clear();  // joined by join_all (or never started: std::terminate, as for any fiber)
    yield();          // lets Boost release the terminated fibers now, returning their stacks
  }
  // Starts body in a new fiber whose stack `context` watches; it first runs at the next yield().
  // Throws (std::runtime_error) and starts nothing if no stack can be mapped.
  void launch(FiberContext& context, std::function<void()> body) {
    fibers_.emplace_back(boost::fibers::launch::post, std::allocator_arg, FiberStack(stacks_),
                         [&context, body = std::move(body)] {
                           body();
                           context.check_stack();
                         });
    context.canary_ = stacks_->last_canary();
    context.stack_bytes_ = stacks_->stack_bytes();
  }
  // From the simulation's main fiber: lets the ready fibers run.
  static void yield() { boost::this_fiber::yield(); }
  // Waits until every fiber has returned.
  void join_all() {
    for (auto& f : fibers_) f.join();
  }
  FiberStackPool& stacks() { return *stacks_; }

 private:
  std::shared_ptr<FiberStackPool> stacks_;  // shared with the fibers, which return their stacks to it
  std::vector<boost::fibers::fiber> fibers_;
};

}  // namespace gcsim::parix::detail
