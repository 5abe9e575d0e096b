// The fiber stack pool: thousands of stacks within the system's map limit, recycled stacks, and an
// overflow that ends the run with the message naming [runtime] fiber_stack_kib -- for a stack
// with a guard page and for one with a painted canary (in a child process: the run must end).
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "parix/sim/fiber_processes.hpp"
#include "parix/sim/fiber_stack.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::parix {
namespace {

long maps_now() {
  std::ifstream maps("/proc/self/maps");
  long n = 0;
  for (std::string line; std::getline(maps, line);) ++n;
  return n;
}

long map_limit() {
  long limit = 65530;
  std::ifstream("/proc/sys/vm/max_map_count") >> limit;
  return limit;
}

TEST(FiberStackPool, MoreStacksThanTheMapLimitAllowsGuardedStaysUnderIt) {
  FiberStackPool pool(16 << 10);
  const long wanted = map_limit() / 2 + 1000;  // two maps each would not fit
  std::vector<boost::context::stack_context> stacks;
  for (long i = 0; i < wanted; ++i) stacks.push_back(pool.allocate());
  EXPECT_GT(pool.guarded_stacks(), 0u);
  EXPECT_GT(pool.painted_stacks(), 0u);
  EXPECT_GE(pool.guarded_stacks() + pool.painted_stacks(), static_cast<std::size_t>(wanted));
  EXPECT_LT(maps_now(), map_limit());
  // Stacks are distinct and each has its full size.
  for (std::size_t i = 1; i < stacks.size(); ++i) {
    const char* a = static_cast<const char*>(stacks[i - 1].sp);
    const char* b = static_cast<const char*>(stacks[i].sp);
    EXPECT_GE(a > b ? a - b : b - a, static_cast<std::ptrdiff_t>(pool.stack_bytes())) << i;
    if (::testing::Test::HasFailure()) break;
  }
  for (auto& s : stacks) pool.deallocate(s);
}

TEST(FiberStackPool, RecyclesReturnedStacksWithoutMappingMore) {
  FiberStackPool pool(64 << 10);
  auto a = pool.allocate();
  const std::size_t carved = pool.guarded_stacks() + pool.painted_stacks();
  void* top = a.sp;
  pool.deallocate(a);
  auto b = pool.allocate();
  EXPECT_EQ(b.sp, top);
  EXPECT_EQ(b.size, pool.stack_bytes());
  EXPECT_EQ(pool.guarded_stacks() + pool.painted_stacks(), carved);
  pool.deallocate(b);
}

TEST(FiberStackPool, RoundsStacksUpToWholePages) {
  FiberStackPool pool(20000);
  EXPECT_GE(pool.stack_bytes(), 20000u);
  EXPECT_EQ(pool.stack_bytes() % 4096, 0u);
}

// Writes every byte of its frames, depth frames of about 1 KiB deep.
void dig(int depth) {
  volatile char pad[1000];
  std::memset(const_cast<char*>(pad), depth & 0xff, sizeof pad);
  if (depth > 0) dig(depth - 1);
  pad[0] = pad[999];
}

// Three fibers on 16 KiB stacks; the third goes about 2-3 KiB past the bottom of its stack.
void overflow_third_fiber(bool guarded) {
  detail::FiberPool fibers(16 << 10);
  if (!guarded) {
    // The canary sits in the page below the stack: the overflow must not reach the fiber below.
    fibers.stacks().stop_guarding();
  }
  detail::FiberContext contexts[3];
  for (int i = 0; i < 3; ++i) {
    fibers.launch(contexts[i], [i] {
      if (i == 2) dig(18);
    });
  }
  while (true) fibers.run_ready();  // the third fiber's end of run must stop the process
}

TEST(FiberStackPoolDeathTest, OverflowIntoAGuardPageNamesTheSetting) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(overflow_third_fiber(true), ::testing::ExitedWithCode(kStackOverflowExitCode),
              "overflowed its fiber stack of 16 KiB; raise fiber_stack_kib");
}

TEST(FiberStackPoolDeathTest, OverflowOverACanaryNamesTheSetting) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(overflow_third_fiber(false), ::testing::ExitedWithCode(kStackOverflowExitCode),
              "overflowed its fiber stack of 16 KiB; raise fiber_stack_kib");
}

// End to end: a simulated program that needs more stack than the machine file gives it.
void run_deep_program() {
  SimulationOptions o;
  o.config = machine::published_machine_config();
  o.config.fiber_stack_bytes = 16 << 10;
  o.config = machine::with_nodes(o.config, 4);
  run_simulated(o, [](Processor& p) {
    if (p.id() == 3) dig(40);
  });
}

TEST(FiberStackPoolDeathTest, ASimulatedProgramThatOverflowsGetsTheMessage) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(run_deep_program(), ::testing::ExitedWithCode(kStackOverflowExitCode),
              "overflowed its fiber stack of 16 KiB; raise fiber_stack_kib in the \\[runtime\\] table");
}

// The same program with room enough runs.
TEST(FiberStackPool, TheSameProgramRunsWithALargerStack) {
  SimulationOptions o;
  o.config = machine::published_machine_config();
  o.config.fiber_stack_bytes = 256 << 10;
  o.config = machine::with_nodes(o.config, 4);
  const RunResult r = run_simulated(o, [](Processor& p) {
    if (p.id() == 3) dig(40);
  });
  EXPECT_EQ(r.nodes, 4);
}

// The canary check itself: painted is intact, any of its checked depths written is not.
TEST(StackCanary, DetectsAWriteAtTheTopOrTheBottom) {
  alignas(8) static unsigned char raw[StackCanary::kBytes];
  auto* canary = reinterpret_cast<StackCanary*>(raw);
  canary->paint();
  EXPECT_TRUE(canary->intact());
  raw[StackCanary::kBytes - 1] ^= 1;  // the first byte an overflow from above reaches
  EXPECT_FALSE(canary->intact());
  canary->paint();
  raw[0] ^= 1;
  EXPECT_FALSE(canary->intact());
}

}  // namespace
}  // namespace gcsim::parix
