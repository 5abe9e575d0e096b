#pragma once
// Processes as fibers, switched directly with Boost.Context: the one place the simulated runtime
// touches a fiber library. The simulation's main context keeps a FIFO ready queue: launch() and
// resume() append a process, run_ready() switches into each ready process in turn until it
// suspends or returns, and a process's suspend() switches straight back to the main context.
// FIFO is the order Boost.Fiber's round_robin scheduler gave (used here before), so simulated
// results and traces did not change; dropping it saved its ready queue, its thread-local look-ups
// of the active fiber and its dispatcher. Nothing is thread-local: each simulation
// (one per host thread) has its own queue. Another implementation would replace this file only.
#include <cstddef>
#include <exception>
#include <functional>
#include <memory>
#include <utility>

#include <boost/context/fiber.hpp>

#include "parix/sim/fiber_stack.hpp"

namespace gcsim::parix::detail {

class FiberPool;

// The handle by which a process suspends itself and the simulation resumes it.
class FiberContext {
 public:
  // From the process itself: sleep until resume(). Checks the stack first (see fiber_stack.hpp):
  // no other fiber may run after this one smashed a neighbour's stack.
  void suspend() {
    check_stack();
    main_ = std::move(main_).resume();
  }
  // From the main context or any process of the same simulation: make the process runnable
  // again. Only a suspended process that is not already queued may be resumed.
  inline void resume();
  void check_stack() const {
    if (canary_ && !canary_->intact()) report_stack_overflow(stack_bytes_);
  }

 private:
  friend class FiberPool;
  boost::context::fiber self_;    // the process, while it is not running; empty once it returned
  boost::context::fiber main_;    // the main context, while the process runs
  FiberContext* next_ = nullptr;  // behind this one in the ready queue
  FiberPool* pool_ = nullptr;
  const StackCanary* canary_ = nullptr;  // null: the stack has a guard page
  std::size_t stack_bytes_ = 0;
};

class FiberPool {
 public:
  explicit FiberPool(std::size_t stack_bytes) : stacks_(stack_bytes) {}
  FiberPool(const FiberPool&) = delete;
  FiberPool& operator=(const FiberPool&) = delete;
  // A fiber destroyed unfinished would be unwound by Boost.Context with an exception the process
  // bodies' catch-all would swallow; the simulation always lets every fiber return first.
  ~FiberPool() {
    if (unfinished_ != 0) std::terminate();
  }
  // Starts body in a new fiber whose stack `context` watches; it first runs at the next
  // run_ready(), after those already ready. body must not throw. Throws (std::runtime_error) and
  // starts nothing if no stack can be mapped.
  void launch(FiberContext& context, std::function<void()> body) {
    context.self_ = boost::context::fiber(std::allocator_arg, FiberStack(&stacks_),
                                          [&context, body = std::move(body)](boost::context::fiber&& main) {
                                            context.main_ = std::move(main);
                                            body();
                                            context.check_stack();
                                            return std::move(context.main_);
                                          });
    context.pool_ = this;
    context.canary_ = stacks_.last_canary();
    context.stack_bytes_ = stacks_.stack_bytes();
    ++unfinished_;
    enqueue(context);
  }
  // From the main context: runs the ready processes in FIFO order, each until it suspends or
  // returns, including those made ready meanwhile, until none is ready.
  void run_ready() {
    while (FiberContext* c = head_) {
      head_ = c->next_;
      if (!head_) tail_ = nullptr;
      c->self_ = std::move(c->self_).resume();
      if (!c->self_) --unfinished_;  // it returned; Boost.Context gave its stack back already
    }
  }
  // From the main context: runs the ready processes; every fiber must have returned after that.
  void join_all() {
    run_ready();
    if (unfinished_ != 0) std::terminate();  // a process suspended with nobody left to wake it
  }
  FiberStackPool& stacks() { return stacks_; }

 private:
  friend class FiberContext;
  void enqueue(FiberContext& c) {
    c.next_ = nullptr;
    if (tail_) tail_->next_ = &c;
    else head_ = &c;
    tail_ = &c;
  }
  FiberStackPool stacks_;  // first member: outlives the fibers' records, which live on its stacks
  FiberContext* head_ = nullptr;
  FiberContext* tail_ = nullptr;
  std::size_t unfinished_ = 0;  // launched and not yet returned
};

void FiberContext::resume() { pool_->enqueue(*this); }

}  // namespace gcsim::parix::detail
