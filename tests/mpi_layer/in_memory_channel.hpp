#pragma once
// A CollectiveChannel test double: N ranks, each on its own std::thread, exchanging messages
// through per-(sender, receiver, tag) queues in memory. A message is queued when its send starts;
// with SendMode::Buffered the send is then finished, with SendMode::Synchronous it finishes only
// once the receiver has taken the message (as a rendezvous protocol or a PARIX-style synchronous
// send would), so a schedule that relies on buffering deadlocks. wait_all finishes its handles in
// whatever order they become ready, as MPI_Waitall does. If every running rank waits on something
// that cannot happen the run is deadlocked: every waiting rank throws instead of hanging.
//
// It also measures the schedule. Messages and bytes are counted; rounds are communication steps
// under the full-duplex one-port model (each rank sends at most one message and receives at most
// one per step): a send takes the step after this rank's latest send or receive; a receive
// completes at the later of its message's step and the step after this rank's previous receive
// (receives counted in the order they were started); the run's rounds are the latest step a
// receive completed at. Both depend only on each rank's program order, so they are exact and
// deterministic whatever the threads do.
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <mutex>
#include <set>
#include <tuple>
#include <vector>

#include "apps/mpi/collective_channel.hpp"

namespace gcsim::mpi_layer::testing {

struct ScheduleStats {
  std::size_t messages = 0;
  std::size_t bytes = 0;
  int rounds = 0;
  std::size_t reduction_bytes = 0;  // charged by charge_reduction, all ranks
  std::size_t left_unreceived = 0;  // messages still queued when every rank returned
  friend bool operator==(const ScheduleStats&, const ScheduleStats&) = default;
};

enum class SendMode { Buffered, Synchronous };

class InMemoryChannel;

class InMemoryNetwork {
 public:
  explicit InMemoryNetwork(int ranks, SendMode mode = SendMode::Buffered)
      : ranks_(ranks), mode_(mode), wakeup_(static_cast<std::size_t>(ranks)) {}
  // Runs body on every rank, each on its own thread, and waits for all; rethrows the first
  // failure (lowest rank) after every thread has ended.
  ScheduleStats run(const std::function<void(CollectiveChannel&)>& body);

 private:
  friend class InMemoryChannel;
  using Key = std::tuple<int, int, int>;  // sender, receiver, tag
  struct Message {
    std::vector<std::byte> data;
    int step;
    std::uint64_t id;
  };
  bool deadlocked() const;  // under mutex_
  void finished();
  void wake(int rank) { wakeup_[static_cast<std::size_t>(rank)].notify_one(); }
  void wake_all() {
    for (std::condition_variable& c : wakeup_) c.notify_one();
  }

  int ranks_;
  SendMode mode_;
  std::mutex mutex_;
  std::vector<std::condition_variable> wakeup_;  // one per rank: only it waits on it
  std::map<Key, std::deque<Message>> queues_;
  std::set<std::uint64_t> taken_;                   // ids of messages a receiver has taken
  std::map<int, const InMemoryChannel*> waiting_;  // ranks blocked in wait_all
  std::uint64_t next_id_ = 0;
  int running_ = 0;
  bool deadlock_ = false;
  ScheduleStats stats_;
};

}  // namespace gcsim::mpi_layer::testing
