#pragma once
// Work computed ahead on host threads (--host-threads): items 0..n-1 whose results are a function
// of the item alone (a ray-traced tile, a tile of media pixels), which simulated processors take
// one by one. Worker threads compute the items in the order they are expected to be taken; a taker
// gets item i once: computed ahead, or computed now on its own thread if no worker has started it;
// while a worker finishes it, the taker computes the next pending items instead of sleeping. The
// results do not depend on who computed them, so a simulation that charges what each result
// counted stays the same whatever the number of threads; only the host's wall time changes.
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

namespace gcsim::apps {

template <class Result>
class WorkAhead {
 public:
  using Compute = std::function<Result(int item)>;

  // workers: one compute function per worker thread (each with its own scratch); order: the
  // items in the order they will probably be taken (each at most once).
  WorkAhead(int items, std::vector<int> order, std::vector<Compute> workers)
      : order_(std::move(order)), slots_(std::size_t(items)), computes_(std::move(workers)) {
    if (computes_.empty()) throw std::invalid_argument("WorkAhead: at least one worker");
    for (int item : order_)
      if (item < 0 || item >= items) throw std::invalid_argument("WorkAhead: an item out of range in the order");
    for (std::size_t i = 0; i < computes_.size(); ++i) threads_.emplace_back([this, i] { work(computes_[i]); });
  }
  ~WorkAhead() {
    {
      std::lock_guard<std::mutex> held(lock_);
      stopping_ = true;
    }
    threads_.clear();  // joins: each worker finishes the item in hand
  }
  WorkAhead(const WorkAhead&) = delete;
  WorkAhead& operator=(const WorkAhead&) = delete;

  // Item `item`, computed ahead or now with `here` (the taker's own compute function).
  Result take(int item, const Compute& here) {
    std::unique_lock<std::mutex> held(lock_);
    Slot& s = slots_.at(std::size_t(item));
    if (s.state == State::pending) {
      s.state = State::running;
      held.unlock();
      Result r = here(item);
      held.lock();
      s.state = State::taken;
      return r;
    }
    if (s.state == State::taken) throw std::logic_error("WorkAhead: an item taken twice");
    while (s.state != State::done) {
      const int other = claim();
      if (other < 0) {
        item_done_.wait(held, [&] { return s.state == State::done; });
        break;
      }
      held.unlock();
      finish(other, here);  // another taker's item: a failure goes to that taker
      held.lock();
    }
    s.state = State::taken;
    if (s.failure) std::rethrow_exception(s.failure);
    return std::move(s.result);
  }

  std::int64_t by_workers() const {  // items the workers took on so far
    std::lock_guard<std::mutex> held(lock_);
    return by_workers_;
  }
  int workers() const { return int(computes_.size()); }

 private:
  enum class State { pending, running, done, taken };
  struct Slot {
    State state = State::pending;
    Result result{};
    std::exception_ptr failure;
  };

  int claim() {  // the next pending item in order, marked running, or -1
    while (next_ < order_.size()) {
      const int item = order_[next_++];
      if (slots_[std::size_t(item)].state != State::pending) continue;  // a taker was first
      slots_[std::size_t(item)].state = State::running;
      return item;
    }
    return -1;
  }

  // Computes a claimed item (lock not held) and stores its result, or its failure for its taker.
  void finish(int item, const Compute& compute) {
    Result r{};
    std::exception_ptr failure;
    try {
      r = compute(item);
    } catch (...) {
      failure = std::current_exception();
    }
    std::lock_guard<std::mutex> held(lock_);
    Slot& s = slots_[std::size_t(item)];
    s.result = std::move(r);
    s.failure = failure;
    s.state = State::done;
    item_done_.notify_all();
  }

  void work(const Compute& compute) {
    std::unique_lock<std::mutex> held(lock_);
    for (;;) {
      if (stopping_) return;
      const int item = claim();
      if (item < 0) return;  // every item is handed out
      ++by_workers_;
      held.unlock();
      finish(item, compute);
      held.lock();
    }
  }

  std::vector<int> order_;
  std::size_t next_ = 0;
  std::vector<Slot> slots_;
  std::vector<Compute> computes_;
  mutable std::mutex lock_;
  std::condition_variable item_done_;
  bool stopping_ = false;
  std::int64_t by_workers_ = 0;
  std::vector<std::jthread> threads_;  // last: joined before the rest is destroyed
};

}  // namespace gcsim::apps
