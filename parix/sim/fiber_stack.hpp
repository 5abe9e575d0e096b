#pragma once
// Stacks for the simulated processors' fibers, carved from a few large memory maps.
//
// A guard-paged stack per fiber costs two kernel memory maps (the guard and the stack), and the
// system allows about 65,530 per process: one mapping per fiber stops near 32,700 fibers. So the
// pool carves stacks from slabs of kStacksPerSlab stacks each, and protects them in one of two ways:
//   - guarded slabs, while the map budget allows (the first ~25,000 stacks with the default limit):
//     a PROT_NONE page below every stack, so an overflow faults at once, before it writes anything;
//     the fault handler (fiber_stack_pool.cpp) names the cause instead of a bare segmentation fault;
//   - painted slabs beyond that (one map per slab): a canary at the bottom of every stack, checked
//     each time the fiber switches out or returns. The overflowing fiber is the only one running
//     until its next switch-out (one host thread), so no other fiber ever runs on a smashed stack.
//     A frame that skips the whole canary without writing it would escape; the canary is 1 KiB
//     and checked at several depths, and the guarded stacks cover the machine's first nodes.
// Either way an overflow ends the run with a message naming [runtime] fiber_stack_kib, never with
// silent corruption. Stacks are recycled on the pool's free list and unmapped with the pool.
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <unordered_map>
#include <vector>

#include <boost/context/stack_context.hpp>

namespace gcsim::parix {

// Exit status of a run that overflowed a fiber stack.
inline constexpr int kStackOverflowExitCode = 70;

// The bottom of a painted stack; intact() is false once something has written over it.
class StackCanary {
 public:
  static constexpr std::size_t kBytes = 1024;
  static constexpr std::uint64_t kPattern = 0x9e3779b97f4a7c15ull;
  void paint();
  bool intact() const {
    // Deepest-reached first: an overflow writes downwards from the top of the canary.
    return words_[kWords - 1] == kPattern && words_[kWords / 2] == kPattern && words_[kWords / 4] == kPattern &&
           words_[0] == kPattern;
  }

 private:
  static constexpr std::size_t kWords = kBytes / sizeof(std::uint64_t);
  std::uint64_t words_[kWords];
};

// Names, in the overflow message, what runs on this thread's fiber from now on ("rank 3") and how
// to give it more stack; both must outlive the run (null: the default message, naming
// [runtime] fiber_stack_kib). A layer that runs programs on fibers sets it as each one resumes.
void describe_running_stack(const char* who, const char* remedy);
// Where the overflow message goes (default: standard error); for a caller that has redirected
// descriptor 2 meanwhile.
void report_stack_overflows_to(int fd);

// Ends the process with the overflow message (the stack can no longer be trusted: no unwinding).
[[noreturn]] void report_stack_overflow(std::size_t stack_bytes);

class FiberStackPool {
 public:
  static constexpr std::size_t kStacksPerSlab = 64;
  // stack_bytes: usable bytes per stack, rounded up to whole pages.
  explicit FiberStackPool(std::size_t stack_bytes);
  ~FiberStackPool();
  FiberStackPool(const FiberStackPool&) = delete;
  FiberStackPool& operator=(const FiberStackPool&) = delete;

  // Throws std::runtime_error naming the sizes if the host cannot map more memory.
  boost::context::stack_context allocate();
  void deallocate(boost::context::stack_context& s) noexcept;

  // The canary of the stack last returned by allocate(); null if that stack has a guard page.
  StackCanary* last_canary() const { return last_canary_; }
  std::size_t stack_bytes() const { return stack_bytes_; }
  std::size_t guarded_stacks() const { return guarded_; }
  std::size_t painted_stacks() const { return painted_; }

  // For tests: carve no more guarded slabs, as if the map budget were spent.
  void stop_guarding() { guarding_ = false; }

 private:
  struct Stack {
    char* bottom;  // lowest usable byte
    bool guarded;
  };
  void add_slab();
  bool guard_budget_allows() const;

  std::size_t stack_bytes_;
  std::size_t page_;
  bool guarding_ = true;
  struct Slab {
    std::size_t bytes;
    bool guarded;
  };
  std::map<char*, Slab> slabs_;  // by base address
  std::vector<Stack> free_;
  std::size_t guarded_ = 0;
  std::size_t painted_ = 0;
  StackCanary* last_canary_ = nullptr;
  std::unordered_map<void*, unsigned> valgrind_ids_;  // stack top -> id, only under valgrind
};

// The stack allocator handed to Boost.Context: a view of the pool. Boost keeps a copy in each
// fiber's record and gives the stack back as the fiber returns, so the pool (FiberPool's first
// member) outlives every stack.
class FiberStack {
 public:
  explicit FiberStack(FiberStackPool* pool) : pool_(pool) {}
  boost::context::stack_context allocate() { return pool_->allocate(); }
  void deallocate(boost::context::stack_context& s) noexcept { pool_->deallocate(s); }

 private:
  FiberStackPool* pool_;
};

}  // namespace gcsim::parix
