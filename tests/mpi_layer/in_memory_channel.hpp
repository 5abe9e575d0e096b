#pragma once
// A CollectiveChannel test double: N ranks, each on its own std::thread, exchanging messages
// through per-(sender, receiver, tag) queues in memory. Sends are buffered (they finish at once);
// a receive waits for its queue. If every running rank waits on an empty queue the run is
// deadlocked: every waiting rank throws instead of hanging.
//
// It also measures the schedule. Messages and bytes are counted; rounds are communication steps
// under the full-duplex one-port model (each rank sends at most one message and receives at most
// one per step): a send takes the step after this rank's latest send or receive; a receive
// completes at the later of its message's step and the step after this rank's previous receive;
// the run's rounds are the latest step a receive completed at. Both depend only on each rank's
// program order, so they are exact and deterministic whatever the threads do.
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
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
};

class InMemoryNetwork {
 public:
  explicit InMemoryNetwork(int ranks) : ranks_(ranks) {}
  // Runs body on every rank, each on its own thread, and waits for all; rethrows the first
  // failure (lowest rank) after every thread has ended.
  ScheduleStats run(const std::function<void(CollectiveChannel&)>& body);

 private:
  friend class InMemoryChannel;
  using Key = std::tuple<int, int, int>;  // sender, receiver, tag
  struct Message {
    std::vector<std::byte> data;
    int step;
  };
  void post(const Key& key, Message message);
  Message take(const Key& key);  // blocks; throws on deadlock
  void finished();
  void note_arrival(int step);
  bool deadlocked() const;  // under mutex_

  int ranks_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::map<Key, std::deque<Message>> queues_;
  std::map<int, Key> waiting_;  // receiver -> the queue it waits on
  int running_ = 0;
  bool deadlock_ = false;
  ScheduleStats stats_;
};

}  // namespace gcsim::mpi_layer::testing
