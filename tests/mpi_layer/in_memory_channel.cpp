#include "tests/mpi_layer/in_memory_channel.hpp"

#include <algorithm>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string>
#include <thread>

namespace gcsim::mpi_layer::testing {

// One rank's end: its handles, and its step clock (see the header).
class InMemoryChannel final : public CollectiveChannel {
 public:
  InMemoryChannel(InMemoryNetwork& network, int rank) : network_(network), rank_(rank) {}
  int rank() const override { return rank_; }
  int size() const override { return network_.ranks_; }

  Handle start_send(int peer, int tag, std::span<const std::byte> data) override {
    check_peer(peer);
    network_.post({rank_, peer, tag}, {{data.begin(), data.end()}, ++clock_});
    pending_.push_back(std::nullopt);
    return static_cast<Handle>(pending_.size() - 1);
  }
  Handle start_recv(int peer, int tag, std::span<std::byte> into) override {
    check_peer(peer);
    pending_.push_back(Receive{peer, tag, into});
    return static_cast<Handle>(pending_.size() - 1);
  }
  void wait_all(std::span<const Handle> handles) override {
    for (Handle h : handles) {
      if (h < 0 || static_cast<std::size_t>(h) >= pending_.size() || spent_.count(h) != 0)
        throw std::logic_error("wait_all on a handle that is not pending");
      spent_.insert({h, true});
      if (!pending_[static_cast<std::size_t>(h)]) continue;  // a send: finished when started
      const Receive& r = *pending_[static_cast<std::size_t>(h)];
      InMemoryNetwork::Message m = network_.take({r.peer, rank_, r.tag});
      if (m.data.size() != r.into.size())
        throw std::logic_error("rank " + std::to_string(rank_) + " expected " + std::to_string(r.into.size()) +
                               " bytes from rank " + std::to_string(r.peer) + " under tag " + std::to_string(r.tag) +
                               ", the message has " + std::to_string(m.data.size()));
      if (!m.data.empty()) std::memcpy(r.into.data(), m.data.data(), m.data.size());
      received_ = std::max(m.step, received_ + 1);  // one receive per step: it may have waited
      clock_ = std::max(clock_, received_);
      network_.note_arrival(received_);
    }
  }
  void charge_reduction(std::size_t bytes) override {
    const std::lock_guard lock(network_.mutex_);
    network_.stats_.reduction_bytes += bytes;
  }

 private:
  struct Receive {
    int peer, tag;
    std::span<std::byte> into;
  };
  void check_peer(int peer) const {
    if (peer < 0 || peer >= network_.ranks_) throw std::logic_error("peer " + std::to_string(peer) + " out of range");
  }
  InMemoryNetwork& network_;
  int rank_;
  int clock_ = 0;     // the step of this rank's latest send or receive
  int received_ = 0;  // the step of its latest receive
  std::vector<std::optional<Receive>> pending_;
  std::map<Handle, bool> spent_;
};

void InMemoryNetwork::post(const Key& key, Message message) {
  const std::lock_guard lock(mutex_);
  ++stats_.messages;
  stats_.bytes += message.data.size();
  queues_[key].push_back(std::move(message));
  changed_.notify_all();
}

void InMemoryNetwork::note_arrival(int step) {
  const std::lock_guard lock(mutex_);
  stats_.rounds = std::max(stats_.rounds, step);
}

bool InMemoryNetwork::deadlocked() const {
  if (static_cast<int>(waiting_.size()) < running_ || running_ == 0) return false;
  return std::all_of(waiting_.begin(), waiting_.end(), [&](const auto& w) {
    const auto q = queues_.find(w.second);
    return q == queues_.end() || q->second.empty();
  });
}

InMemoryNetwork::Message InMemoryNetwork::take(const Key& key) {
  std::unique_lock lock(mutex_);
  waiting_[std::get<1>(key)] = key;
  if (deadlocked()) deadlock_ = true;
  changed_.notify_all();
  changed_.wait(lock, [&] { return deadlock_ || !queues_[key].empty(); });
  waiting_.erase(std::get<1>(key));
  if (queues_[key].empty()) throw std::runtime_error("deadlock: every rank waits for a message nobody sends");
  Message m = std::move(queues_[key].front());
  queues_[key].pop_front();
  return m;
}

void InMemoryNetwork::finished() {
  const std::lock_guard lock(mutex_);
  --running_;
  if (deadlocked()) deadlock_ = true;
  changed_.notify_all();
}

ScheduleStats InMemoryNetwork::run(const std::function<void(CollectiveChannel&)>& body) {
  stats_ = {};
  queues_.clear();
  deadlock_ = false;
  running_ = ranks_;
  std::vector<std::exception_ptr> failures(static_cast<std::size_t>(ranks_));
  std::vector<std::thread> threads;
  for (int r = 0; r < ranks_; ++r)
    threads.emplace_back([&, r] {
      try {
        InMemoryChannel channel(*this, r);
        body(channel);
      } catch (...) {
        failures[static_cast<std::size_t>(r)] = std::current_exception();
      }
      finished();
    });
  for (std::thread& t : threads) t.join();
  for (const std::exception_ptr& f : failures)
    if (f) std::rethrow_exception(f);
  for (const auto& [key, queue] : queues_) stats_.left_unreceived += queue.size();
  return stats_;
}

}  // namespace gcsim::mpi_layer::testing
