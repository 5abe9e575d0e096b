#pragma once
// What a run reports: simulated time next to the host's wall-clock time, and the counters behind them.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "machine/sim_time.hpp"

namespace gcsim::parix {

struct ProcessorStats {
  machine::SimTime finish = 0;    // when the processor's program returned
  machine::SimTime compute = 0;   // time its CPU work took
  machine::SimTime comm = 0;      // time blocked in connect/send/recv/wait
  machine::SimTime waiting = 0;   // of which before the peer acted (docs/run-records.md, "waiting")
  machine::SimTime connect = 0;   // of which opening connections
  std::int64_t messages_sent = 0;
  std::int64_t bytes_sent = 0;
  std::int64_t connections = 0;
  std::map<std::string, std::int64_t, std::less<>> ops;  // counted operations
};

// Whose clock a run's times are: the simulated machine's, or the host's (a backend of real
// processes, which measured its run instead of simulating it).
enum class Clock { simulated, wall };

struct RunResult {
  Clock clock = Clock::simulated;
  std::string model;              // network model name
  std::string config_name;
  int nodes = 0;
  machine::SimTime makespan = 0;  // simulated time of the whole run
  double wall_seconds = 0;        // host time the simulation took
  std::uint64_t events = 0;       // discrete events processed by the kernel
  std::int64_t link_end_slots = 0;  // host: link ends stored at most (simulated backend; not in the JSON)
  std::vector<ProcessorStats> processors;
  // Node memory (simulated backend): the highest any node held, on which processor's node, and
  // the node's memory. memory_warning: set when a node went over it (only a run that warns).
  std::int64_t memory_peak = 0;
  int memory_peak_processor = -1;
  std::int64_t memory_capacity = 0;
  std::string memory_warning;

  double simulated_seconds() const { return machine::to_seconds(makespan); }
  double mean_compute_seconds() const;
  double mean_comm_seconds() const;
  double mean_waiting_seconds() const;
  // Blocked while bytes moved or a link was set up: comm less waiting (mean per processor).
  double mean_communicating_seconds() const { return mean_comm_seconds() - mean_waiting_seconds(); }
  double max_comm_seconds() const;
  std::int64_t total_messages() const;
  std::map<std::string, std::int64_t, std::less<>> total_ops() const;
  // {"simulated": {"total_s", "compute_s", "comm_s"}, "wall": {"total_s"}, "events", "nodes", "model", ...}
  nlohmann::json to_json() const;
};

}  // namespace gcsim::parix
