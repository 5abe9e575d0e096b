#include "tests/mpi_layer/in_memory_channel.hpp"

#include <algorithm>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string>
#include <thread>

namespace gcsim::mpi_layer::testing {

// One rank's end: its handles, and its step clock (see the header). Everything it shares with
// the other ranks is under the network's mutex.
class InMemoryChannel final : public CollectiveChannel {
 public:
  InMemoryChannel(InMemoryNetwork& network, int rank) : network_(network), rank_(rank) {}
  int rank() const override { return rank_; }
  int size() const override { return network_.ranks_; }

  Handle start_send(int peer, int tag, std::span<const std::byte> data) override {
    check_peer(peer);
    const std::lock_guard lock(network_.mutex_);
    const std::uint64_t id = network_.next_id_++;
    network_.queues_[{rank_, peer, tag}].push_back({{data.begin(), data.end()}, ++clock_, id});
    ++network_.stats_.messages;
    network_.stats_.bytes += data.size();
    network_.wake(peer);
    pending_.push_back({true, peer, tag, {}, id});
    return static_cast<Handle>(pending_.size() - 1);
  }
  Handle start_recv(int peer, int tag, std::span<std::byte> into) override {
    check_peer(peer);
    pending_.push_back({false, peer, tag, into, 0});
    return static_cast<Handle>(pending_.size() - 1);
  }
  void wait_all(std::span<const Handle> handles) override;
  void charge_reduction(std::size_t bytes) override {
    const std::lock_guard lock(network_.mutex_);
    network_.stats_.reduction_bytes += bytes;
  }
  bool can_progress() const;  // under the network's mutex

 private:
  struct Pending {
    bool is_send;
    int peer, tag;
    std::span<std::byte> into;
    std::uint64_t id;
    bool done = false, spent = false;
    int arrived_step = 0;
  };
  void check_peer(int peer) const {
    if (peer < 0 || peer >= network_.ranks_) throw std::logic_error("peer " + std::to_string(peer) + " out of range");
  }
  bool send_finished(const Pending& p) const {
    return network_.mode_ == SendMode::Buffered || network_.taken_.count(p.id) != 0;
  }
  void take(Pending& p);
  bool progress();  // under the mutex: finishes what it can, true if all of waiting_on_ is done
  void count_steps();

  InMemoryNetwork& network_;
  int rank_;
  int clock_ = 0;     // the step of this rank's latest send or receive
  int received_ = 0;  // the step of its latest receive
  std::vector<Pending> pending_;
  std::vector<Handle> waiting_on_;
};

void InMemoryChannel::take(Pending& p) {
  auto& queue = network_.queues_[{p.peer, rank_, p.tag}];
  InMemoryNetwork::Message m = std::move(queue.front());
  queue.pop_front();
  if (m.data.size() != p.into.size())
    throw std::logic_error("rank " + std::to_string(rank_) + " expected " + std::to_string(p.into.size()) +
                           " bytes from rank " + std::to_string(p.peer) + " under tag " + std::to_string(p.tag) +
                           ", the message has " + std::to_string(m.data.size()));
  if (!m.data.empty()) std::memcpy(p.into.data(), m.data.data(), m.data.size());
  network_.taken_.insert(m.id);
  network_.wake(p.peer);  // a synchronous send there may now finish
  p.arrived_step = m.step;
  p.done = true;
}

bool InMemoryChannel::progress() {
  std::set<InMemoryNetwork::Key> blocked;  // a later receive on one of them must wait its turn
  bool all = true;
  for (Handle h : waiting_on_) {
    Pending& p = pending_[static_cast<std::size_t>(h)];
    if (p.done) continue;
    if (p.is_send) {
      p.done = send_finished(p);
    } else {
      const InMemoryNetwork::Key key{p.peer, rank_, p.tag};
      const auto q = network_.queues_.find(key);
      if (blocked.count(key) == 0 && q != network_.queues_.end() && !q->second.empty()) take(p);
      else blocked.insert(key);
    }
    all = all && p.done;
  }
  return all;
}

bool InMemoryChannel::can_progress() const {
  for (Handle h : waiting_on_) {
    const Pending& p = pending_[static_cast<std::size_t>(h)];
    if (p.done) continue;
    if (p.is_send && send_finished(p)) return true;
    if (p.is_send) continue;
    const auto q = network_.queues_.find({p.peer, rank_, p.tag});
    if (q != network_.queues_.end() && !q->second.empty()) return true;
  }
  return false;
}

// Receives take their steps in the order they were started, whatever order they finished in.
void InMemoryChannel::count_steps() {
  for (Handle h : waiting_on_) {
    Pending& p = pending_[static_cast<std::size_t>(h)];
    p.spent = true;
    if (p.is_send) continue;
    received_ = std::max(p.arrived_step, received_ + 1);
    clock_ = std::max(clock_, received_);
    network_.stats_.rounds = std::max(network_.stats_.rounds, received_);
  }
}

void InMemoryChannel::wait_all(std::span<const Handle> handles) {
  std::unique_lock lock(network_.mutex_);
  waiting_on_.assign(handles.begin(), handles.end());
  for (Handle h : waiting_on_)
    if (h < 0 || static_cast<std::size_t>(h) >= pending_.size() || pending_[static_cast<std::size_t>(h)].spent ||
        std::count(waiting_on_.begin(), waiting_on_.end(), h) != 1)
      throw std::logic_error("wait_all on a handle that is not pending");
  while (!progress()) {
    network_.waiting_[rank_] = this;
    if (network_.deadlocked()) {
      network_.deadlock_ = true;
      network_.wake_all();
    }
    network_.wakeup_[static_cast<std::size_t>(rank_)].wait(lock, [&] { return network_.deadlock_ || can_progress(); });
    network_.waiting_.erase(rank_);
    if (!can_progress()) throw std::runtime_error("deadlock: every rank waits for something no rank will do");
  }
  count_steps();
}

bool InMemoryNetwork::deadlocked() const {
  if (static_cast<int>(waiting_.size()) < running_ || running_ == 0) return false;
  return std::none_of(waiting_.begin(), waiting_.end(), [](const auto& w) { return w.second->can_progress(); });
}

void InMemoryNetwork::finished() {
  const std::lock_guard lock(mutex_);
  --running_;
  if (deadlocked()) {
    deadlock_ = true;
    wake_all();
  }
}

ScheduleStats InMemoryNetwork::run(const std::function<void(CollectiveChannel&)>& body) {
  stats_ = {};
  queues_.clear();
  taken_.clear();
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
