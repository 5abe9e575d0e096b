// The fiber stack pool (parix/sim/fiber_stack.hpp): slabs, the map budget and the guard-page fault
// handler that turns a fault in a guard page into the overflow message.
#include "parix/sim/fiber_stack.hpp"

#include <signal.h>
#include <sys/mman.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

#if __has_include(<valgrind/valgrind.h>)
#include <valgrind/valgrind.h>
#define GCSIM_VALGRIND_STACKS 1
#endif

namespace gcsim::parix {
namespace {

// Maps the process may hold (vm.max_map_count), and those it held before the first pool.
long system_map_limit() {
  long limit = 65530;
  std::ifstream("/proc/sys/vm/max_map_count") >> limit;
  return limit;
}
long maps_at_start() {
  std::ifstream maps("/proc/self/maps");
  long n = 0;
  for (std::string line; std::getline(maps, line);) ++n;
  return n;
}
// Maps left for malloc, libraries and whatever else the process does after the pools took theirs.
constexpr long kMapReserve = 16384;
std::atomic<long> g_maps_in_pools{0};

// Guarded slabs, readable from the fault handler (async-signal-safe: fixed array, atomics).
struct GuardedSlab {
  std::atomic<char*> base{nullptr};
  std::size_t bytes = 0;
  std::size_t stride = 0;
  std::size_t page = 0;
  std::size_t stack_bytes = 0;
};
constexpr std::size_t kMaxGuardedSlabs = 8192;
std::array<GuardedSlab, kMaxGuardedSlabs> g_guarded;
std::mutex g_guarded_mutex;
struct sigaction g_previous_segv;

// Who runs on this thread's current fiber and how to give it more stack (describe_running_stack).
thread_local const char* g_running_who = nullptr;
thread_local const char* g_running_remedy = nullptr;
std::atomic<int> g_report_fd{STDERR_FILENO};

void write_overflow_message(std::size_t stack_bytes) {
  char text[512];
  const int n = g_running_who
                    ? std::snprintf(text, sizeof text, "gcsim: %s overflowed its stack of %zu KiB; %s\n", g_running_who,
                                    stack_bytes / 1024, g_running_remedy ? g_running_remedy : "give it a larger stack")
                    : std::snprintf(text, sizeof text,
                                    "gcsim: a simulated processor overflowed its fiber stack of %zu KiB; "
                                    "raise fiber_stack_kib in the [runtime] table of the machine file\n",
                                    stack_bytes / 1024);
  if (n > 0) [[maybe_unused]] auto w = ::write(g_report_fd.load(), text, static_cast<std::size_t>(n));
}

void on_segv(int sig, siginfo_t* info, void* context) {
  char* addr = static_cast<char*>(info->si_addr);
  for (const GuardedSlab& s : g_guarded) {
    char* base = s.base.load(std::memory_order_acquire);
    if (base && addr >= base && addr < base + s.bytes && std::size_t(addr - base) % s.stride < s.page) {
      write_overflow_message(s.stack_bytes);
      ::_exit(kStackOverflowExitCode);
    }
  }
  // Not a guard page: let the previous handler (or the default action) deal with it.
  if (g_previous_segv.sa_flags & SA_SIGINFO) {
    if (g_previous_segv.sa_sigaction) return g_previous_segv.sa_sigaction(sig, info, context);
  } else if (g_previous_segv.sa_handler != SIG_DFL && g_previous_segv.sa_handler != SIG_IGN) {
    return g_previous_segv.sa_handler(sig);
  }
  ::signal(SIGSEGV, SIG_DFL);  // returning re-executes the access, which now kills as usual
}

// The handler runs on an alternate stack: the faulting one has no room left.
void install_fault_handler() {
  static std::once_flag once;
  std::call_once(once, [] {
    struct sigaction sa {};
    sa.sa_sigaction = on_segv;
    sa.sa_flags = SA_SIGINFO | SA_ONSTACK;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGSEGV, &sa, &g_previous_segv);
  });
  thread_local bool has_alt_stack = false;
  if (has_alt_stack) return;
  stack_t current{};
  if (sigaltstack(nullptr, &current) == 0 && !(current.ss_flags & SS_DISABLE)) {
    has_alt_stack = true;  // someone (a sanitizer) already gave this thread one
    return;
  }
  // Allocated on demand (a thread_local array would grow every thread's TLS block); kept for the
  // thread's life, as the kernel may switch to it at any fault.
  constexpr std::size_t kAltStackBytes = 64 * 1024;
  static thread_local std::unique_ptr<char[]> alt;
  alt = std::make_unique<char[]>(kAltStackBytes);
  stack_t st{};
  st.ss_sp = alt.get();
  st.ss_size = kAltStackBytes;
  has_alt_stack = sigaltstack(&st, nullptr) == 0;
}

void register_guarded(char* base, std::size_t bytes, std::size_t stride, std::size_t page, std::size_t stack_bytes) {
  std::lock_guard lock(g_guarded_mutex);
  for (GuardedSlab& s : g_guarded) {
    if (s.base.load(std::memory_order_relaxed)) continue;
    s.bytes = bytes, s.stride = stride, s.page = page, s.stack_bytes = stack_bytes;
    s.base.store(base, std::memory_order_release);
    return;
  }
}

void unregister_guarded(char* base) {
  std::lock_guard lock(g_guarded_mutex);
  for (GuardedSlab& s : g_guarded) {
    if (s.base.load(std::memory_order_relaxed) == base) s.base.store(nullptr, std::memory_order_release);
  }
}

}  // namespace

void StackCanary::paint() {
  for (std::uint64_t& w : words_) w = kPattern;
}

void describe_running_stack(const char* who, const char* remedy) {
  g_running_who = who;
  g_running_remedy = remedy;
}

void report_stack_overflows_to(int fd) { g_report_fd.store(fd); }

void report_stack_overflow(std::size_t stack_bytes) {
  write_overflow_message(stack_bytes);
  ::_exit(kStackOverflowExitCode);
}

FiberStackPool::FiberStackPool(std::size_t stack_bytes) : page_(static_cast<std::size_t>(::sysconf(_SC_PAGESIZE))) {
  stack_bytes_ = (std::max<std::size_t>(stack_bytes, 2 * page_) + page_ - 1) / page_ * page_;
  install_fault_handler();
}

FiberStackPool::~FiberStackPool() {
  for (const auto& [base, slab] : slabs_) {
    if (slab.guarded) unregister_guarded(base);
    ::munmap(base, slab.bytes);
    g_maps_in_pools -= slab.guarded ? long(2 * kStacksPerSlab) : 1;
  }
}

bool FiberStackPool::guard_budget_allows() const {
  static const long limit = system_map_limit();
  static const long baseline = maps_at_start();
  return guarding_ && baseline + g_maps_in_pools.load() + long(2 * kStacksPerSlab) + kMapReserve <= limit;
}

// Every stack gets stride = page + stack_bytes: the page below it is the guard (PROT_NONE) in a
// guarded slab and holds the canary in a painted one, so the usable size is the same either way.
void FiberStackPool::add_slab() {
  const std::size_t stride = page_ + stack_bytes_;
  const std::size_t bytes = stride * kStacksPerSlab;
  void* mem = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_STACK, -1, 0);
  if (mem == MAP_FAILED) {
    throw std::runtime_error("cannot map " + std::to_string(bytes >> 20) + " MiB more for fiber stacks (" +
                             std::to_string(guarded_ + painted_) + " stacks of " + std::to_string(stack_bytes_ / 1024) +
                             " KiB mapped so far): " + std::strerror(errno) +
                             "; the host is out of memory: simulate fewer nodes or lower fiber_stack_kib in [runtime]");
  }
  char* base = static_cast<char*>(mem);
  bool guarded = guard_budget_allows();
  if (guarded) {
    for (std::size_t i = 0; i < kStacksPerSlab && guarded; ++i) {
      guarded = ::mprotect(base + i * stride, page_, PROT_NONE) == 0;
    }
    if (!guarded) {  // out of maps after all: fall back to canaries for this slab
      ::mprotect(base, bytes, PROT_READ | PROT_WRITE);
    }
  }
  slabs_.emplace(base, Slab{bytes, guarded});
  if (guarded) {
    register_guarded(base, bytes, stride, page_, stack_bytes_);
    guarded_ += kStacksPerSlab;
    g_maps_in_pools += long(2 * kStacksPerSlab);
  } else {
    painted_ += kStacksPerSlab;
    g_maps_in_pools += 1;
  }
  // Highest first, so that allocate() hands out the lowest stack first.
  for (std::size_t i = kStacksPerSlab; i-- > 0;) free_.push_back({base + i * stride + page_, guarded});
}

boost::context::stack_context FiberStackPool::allocate() {
  if (free_.empty()) add_slab();
  const Stack s = free_.back();
  free_.pop_back();
  last_canary_ = nullptr;
  if (!s.guarded) {
    last_canary_ = reinterpret_cast<StackCanary*>(s.bottom - StackCanary::kBytes);
    last_canary_->paint();
  }
  boost::context::stack_context ctx;
  ctx.size = stack_bytes_;
  ctx.sp = s.bottom + stack_bytes_;
#ifdef GCSIM_VALGRIND_STACKS
  if (RUNNING_ON_VALGRIND) valgrind_ids_[ctx.sp] = VALGRIND_STACK_REGISTER(s.bottom, ctx.sp);
#endif
  return ctx;
}

void FiberStackPool::deallocate(boost::context::stack_context& ctx) noexcept {
  char* bottom = static_cast<char*>(ctx.sp) - ctx.size;
#ifdef GCSIM_VALGRIND_STACKS
  if (auto it = valgrind_ids_.find(ctx.sp); it != valgrind_ids_.end()) {
    VALGRIND_STACK_DEREGISTER(it->second);
    valgrind_ids_.erase(it);
  }
#endif
  // The slab it came from: the last one starting at or below it.
  const auto slab = std::prev(slabs_.upper_bound(bottom));
  const bool guarded = slab->second.guarded;
  free_.push_back({bottom, guarded});
}

}  // namespace gcsim::parix
