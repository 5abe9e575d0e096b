#pragma once
// A node's CPUs and memory. Compute requests take a free CPU or queue for one in arrival order,
// so threads sharing a node share its CPUs deterministically.
#include <cstdint>
#include <deque>
#include <functional>

#include "machine/kernel.hpp"

namespace gcsim::machine {

class Node {
 public:
  Node(Kernel& kernel, int cpus, std::int64_t memory_bytes) : kernel_(&kernel), free_cpus_(cpus), memory_bytes_(memory_bytes) {}

  // Runs `duration` of work on one of the node's CPUs; on_done runs when it is finished.
  void compute(SimTime duration, Kernel::Action on_done);

  // Adds bytes (negative: releases) to the memory in use; false if it would exceed the node's memory.
  bool use_memory(std::int64_t bytes);
  std::int64_t memory_used() const { return memory_used_; }
  std::int64_t memory_bytes() const { return memory_bytes_; }

 private:
  struct Job {
    SimTime duration;
    Kernel::Action on_done;
  };
  void start(Job job);
  Kernel* kernel_;
  int free_cpus_;
  std::deque<Job> waiting_;
  std::int64_t memory_bytes_;
  std::int64_t memory_used_ = 0;
};

}  // namespace gcsim::machine
