#pragma once
// One virtual processor on an MPI rank (or a node-local thread of it). See mpi_runtime.hpp.
#include <atomic>
#include <chrono>
#include <exception>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "machine/node_memory.hpp"
#include "machine/trace.hpp"
#include "parix/processor.hpp"
#include "parix/run_result.hpp"

namespace gcsim::parix::mpi {

class MpiProcessor;

// A link open on the rank: its peer processor and the MPI tag its messages carry.
struct MpiLink {
  int peer;
  int mpi_tag;
};

// What the processor and its threads share on one rank.
struct RankState {
  int rank = 0;
  int size = 1;
  int processor = 0;         // the virtual processor this rank runs (SimulationOptions::placement)
  std::vector<int> rank_of;  // processor -> the rank that runs it; identity when empty
  machine::NodeMemory memory{0, machine::MemoryLimit::enforce};  // the node's, set by run_mpi
  std::chrono::steady_clock::time_point epoch;
  bool tracing = false;
  std::mutex lock;  // guards everything below and the counters of every processor on the rank
  std::map<std::pair<int, int>, std::int64_t> links_opened;  // (peer, tag) -> connects so far
  // Links belong to the node, not to the thread that opened them (as in the simulated backend):
  // a thread may open a link that the node's main processor then uses, after the thread ended.
  std::map<std::int64_t, MpiLink> links;
  std::int64_t next_link = 0;
  MpiProcessor* main = nullptr;  // thread 0's processor, which lives for the whole run: every Link's owner
  ProcessorStats stats;
  std::vector<machine::TraceRecord> records;
  std::vector<std::unique_ptr<std::string>> labels;  // storage the records' labels point into
  std::atomic<int> next_thread{1};
  std::exception_ptr failure;  // the first exception a spawned thread threw

  SimTime now() const;
  int rank_of_processor(int p) const { return rank_of.empty() ? p : rank_of[static_cast<std::size_t>(p)]; }
  void record(machine::TraceRecord r, std::string_view label);
};

class MpiProcessor final : public Processor {
 public:
  MpiProcessor(RankState& rank, int thread) : rank_(rank), thread_(thread) {
    if (thread == 0) rank.main = this;
  }
  ~MpiProcessor() override;

  int id() const override { return rank_.processor; }
  int count() const override { return rank_.size; }
  SimTime now() const override { return rank_.now(); }
  void compute(std::span<const OpCount> ops) override;
  void compute_in_comm(std::span<const OpCount> ops) override { compute(ops); }
  void use_memory(std::int64_t bytes, std::string_view kind) override;
  Link connect(int peer, int tag) override;
  void send(Link& link, std::span<const std::byte> data) override;
  Bytes recv(Link& link) override;
  void recv(Link& link, Bytes& into) override;
  Request isend(Link& link, std::span<const std::byte> data) override;
  Request irecv(Link& link) override;
  void wait(Request& r) override;
  std::size_t wait_any(std::span<Request* const> rs) override;
  bool cancel(Request& r) override;
  Thread spawn(std::function<void(Processor&)> body) override;

 protected:
  void close_link(std::int64_t handle) override;

 private:
  MpiLink link_info(const Link& link, const char* call) const;
  bool poll(RequestState& r);  // advances r; true once it is done or cancelled
  void block_on(RequestState& r, const char* call, machine::TraceKind kind);
  void count_comm(SimTime start, SimTime end, int peer, std::int64_t bytes, const char* call, machine::TraceKind kind);

  RankState& rank_;
  int thread_;
};

}  // namespace gcsim::parix::mpi
