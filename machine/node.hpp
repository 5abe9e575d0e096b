#pragma once
// A node's CPUs and memory. Compute requests take a free CPU or queue for one in arrival order,
// so threads sharing a node share its CPUs deterministically. Its memory: machine/node_memory.hpp.
#include <cstdint>
#include <deque>
#include <functional>
#include <vector>

#include "machine/kernel.hpp"
#include "machine/node_memory.hpp"

namespace gcsim::machine {

class Node {
 public:
  Node(Kernel& kernel, int cpus, std::int64_t memory_bytes, MemoryLimit limit = MemoryLimit::enforce)
      : kernel_(&kernel), free_cpus_(cpus), memory_(memory_bytes, limit) {}

  // Runs `duration` of work on one of the node's CPUs; on_done runs when it is finished.
  void compute(SimTime duration, Kernel::Action&& on_done);
  // The same with a completion that is a function and its argument (a process waiting for its
  // CPU time): on a free CPU the kernel's event holds it, with no running slot to keep.
  void compute(SimTime duration, void (*done)(void*), void* context);

  NodeMemory& memory() { return memory_; }
  const NodeMemory& memory() const { return memory_; }

 private:
  struct Job {
    SimTime duration;
    Kernel::Action on_done;
  };
  void start(SimTime duration, Kernel::Action&& on_done);  // on a free CPU
  void finish(std::uint32_t slot);
  void release_cpu();  // a job ended: the next waiting one starts
  Kernel* kernel_;
  int free_cpus_;
  std::deque<Job> waiting_;
  // The running jobs' on_done, in reused slots: the kernel's event then holds a slot number, small
  // enough for its inline storage (an action inside an action would take a heap allocation).
  std::vector<Kernel::Action> running_;
  std::vector<std::uint32_t> free_slots_;
  NodeMemory memory_;
};

}  // namespace gcsim::machine
