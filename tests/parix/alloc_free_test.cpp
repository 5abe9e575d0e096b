// Steady-state messages allocate nothing: this binary replaces the
// global operator new with one that counts calls, runs the ring benchmark's program for N and for
// 2N iterations and compares the counts. Both runs pay the same set-up (fibers, links, the pools
// growing to their peak), so any difference is the per-message cost. Its own binary, because the
// replacement applies to the whole program. The ring's receives mostly wait for their message; a
// second program has every message arrive first and wait in its link end's queue.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <new>

#include "apps/programs/ring_program.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace {
std::atomic<std::int64_t> g_allocations{0};
}  // namespace

// GCC sees malloc inside operator new and free inside operator delete and warns of a mismatch.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return ::operator new(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
// The aligned forms (the runtime's request blocks use them) are counted too.
void* operator new(std::size_t n, std::align_val_t a) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  const auto align = static_cast<std::size_t>(a);
  if (void* p = std::aligned_alloc(align, (n + align - 1) / align * align)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n, std::align_val_t a) { return ::operator new(n, a); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }

namespace gcsim::parix {
namespace {

// Heap allocations of one run of the ring program.
std::int64_t allocations_of_ring(int nodes, int iterations, std::int64_t bytes, const std::string& model) {
  SimulationOptions o;
  o.config = machine::with_nodes(machine::published_machine_config(), nodes);
  o.config.network_model = model;
  const std::int64_t before = g_allocations.load();
  run_simulated(o, [&](Processor& p) { programs::ring_exchange(p, iterations, bytes); });
  return g_allocations.load() - before;
}

TEST(AllocFree, TheCounterSeesAllocations) {
  static void* volatile sink;  // keeps the compiler from eliding the pair
  const std::int64_t before = g_allocations.load();
  sink = ::operator new(16);
  ::operator delete(sink);
  EXPECT_EQ(g_allocations.load() - before, 1);
}

class RingAllocations : public ::testing::TestWithParam<std::string> {};

TEST_P(RingAllocations, NonePerMessageInSteadyState) {
  const std::string model = GetParam();
  constexpr int kNodes = 16, kIterations = 500;
  allocations_of_ring(kNodes, 1, 64, model);  // first run: one-time initialisations (statics)
  for (std::int64_t bytes : {0, 64, 4096}) {
    const std::int64_t n = allocations_of_ring(kNodes, kIterations, bytes, model);
    const std::int64_t twice = allocations_of_ring(kNodes, 2 * kIterations, bytes, model);
    EXPECT_EQ(twice - n, 0) << model << " network, " << bytes << "-byte messages: " << n << " allocations for "
                            << kNodes * kIterations << " messages, " << twice << " for twice as many";
  }
}

INSTANTIATE_TEST_SUITE_P(Networks, RingAllocations, ::testing::Values("analytic", "packet", "flow"));

// Heap allocations of `rounds` rounds in which every message arrives before its receive: processor
// 0 sends kBurst messages on link `data` and waits until all are delivered (queued at processor 1's
// end), then says so on link `control`; processor 1 receives them only then, and acknowledges, so
// the next round starts with the queue empty. The queue reaches its peak in the first round.
std::int64_t allocations_arriving_first(int rounds, std::int64_t bytes, const std::string& model) {
  constexpr int kBurst = 48;
  SimulationOptions o;
  o.config = machine::with_nodes(machine::published_machine_config(), 2);
  o.config.network_model = model;
  const std::int64_t before = g_allocations.load();
  run_simulated(o, [&](Processor& p) {
    const int peer = 1 - p.id();
    Link data = p.connect(peer, 0);
    Link control = p.connect(peer, 1);
    const Bytes payload(static_cast<std::size_t>(bytes), std::byte{2});
    const Bytes note(8, std::byte{3});
    Bytes in;
    Request sent[kBurst];
    for (int r = 0; r < rounds; ++r) {
      if (p.id() == 0) {
        for (Request& s : sent) s = p.isend(data, payload);
        for (Request& s : sent) p.wait(s);
        p.send(control, note);
        p.recv(control, in);
      } else {
        p.recv(control, in);
        for (int i = 0; i < kBurst; ++i) {
          p.recv(data, in);
          if (static_cast<std::int64_t>(in.size()) != bytes) ADD_FAILURE() << "a message of " << in.size() << " bytes";
        }
        p.send(control, note);
      }
    }
  });
  return g_allocations.load() - before;
}

class ArrivedFirstAllocations : public ::testing::TestWithParam<std::string> {};

TEST_P(ArrivedFirstAllocations, NonePerMessageInSteadyState) {
  const std::string model = GetParam();
  constexpr int kRounds = 40;
  allocations_arriving_first(1, 64, model);
  for (std::int64_t bytes : {0, 64, 4096}) {
    const std::int64_t n = allocations_arriving_first(kRounds, bytes, model);
    const std::int64_t twice = allocations_arriving_first(2 * kRounds, bytes, model);
    EXPECT_EQ(twice - n, 0) << model << " network, " << bytes << "-byte messages: " << n << " allocations for "
                            << kRounds << " rounds, " << twice << " for twice as many";
  }
}

INSTANTIATE_TEST_SUITE_P(Networks, ArrivedFirstAllocations, ::testing::Values("analytic", "packet", "flow"));

}  // namespace
}  // namespace gcsim::parix
