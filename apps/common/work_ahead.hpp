#pragma once
// Work computed ahead on host threads (--host-threads): items whose results are a function of the
// item alone (a ray-traced tile, a tile of media pixels, a hemicube cell of one shooter's
// projection), which simulated processors take one by one. Worker threads compute the items in the
// order they are expected to be taken; a taker gets item i once: computed ahead, or computed now on
// its own thread if no worker has started it; while a worker finishes it, the taker computes the
// next pending items instead of sleeping. The results do not depend on who computed them, so a
// simulation that charges what each result counted stays the same whatever the number of threads;
// only the host's wall time changes.
//
// The items are known at the start (items 0..n-1 and their order), or become known as the run goes
// (expect(): a radiosity loop's cells once its shooter is projected); the workers wait for more
// until the WorkAhead is destroyed. A taken item's slot is freed, so a long run holds only the
// items not yet taken.
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <unordered_map>
#include <utility>
#include <vector>

namespace gcsim::apps {

template <class Result, class Item = int>
class WorkAhead {
 public:
  using Compute = std::function<Result(Item item)>;

  // workers: one compute function per worker thread (each with its own scratch); no items yet.
  explicit WorkAhead(std::vector<Compute> workers) : computes_(std::move(workers)) {
    if (computes_.empty()) throw std::invalid_argument("WorkAhead: at least one worker");
    for (std::size_t i = 0; i < computes_.size(); ++i) threads_.emplace_back([this, i] { work(computes_[i]); });
  }
  // Items 0..items-1, in `order`: the order they will probably be taken (each at most once).
  WorkAhead(int items, const std::vector<int>& order, std::vector<Compute> workers) : WorkAhead(std::move(workers)) {
    for (int item : order)
      if (item < 0 || item >= items) throw std::invalid_argument("WorkAhead: an item out of range in the order");
    std::vector<Item> ordered;
    for (int item : order) ordered.push_back(Item(item));
    expect(ordered);
    std::lock_guard<std::mutex> held(lock_);
    for (int item = 0; item < items; ++item) slots_.try_emplace(Item(item));  // left out of the order: taken, not computed ahead
  }
  ~WorkAhead() {
    {
      std::lock_guard<std::mutex> held(lock_);
      stopping_ = true;
    }
    work_ready_.notify_all();
    threads_.clear();  // joins: each worker finishes the item in hand
  }
  WorkAhead(const WorkAhead&) = delete;
  WorkAhead& operator=(const WorkAhead&) = delete;

  // More items, in the order they will probably be taken; an item already expected keeps its place.
  void expect(const std::vector<Item>& items) {
    {
      std::lock_guard<std::mutex> held(lock_);
      for (Item item : items)
        if (slots_.try_emplace(item).second) order_.push_back(item);
    }
    work_ready_.notify_all();
  }

  // Item `item`, computed ahead or now with `here` (the taker's own compute function).
  Result take(Item item, const Compute& here) {
    std::unique_lock<std::mutex> held(lock_);
    const auto at = slots_.find(item);
    if (at == slots_.end()) throw std::logic_error("WorkAhead: an item never expected, or taken twice");
    Slot& s = at->second;  // stays put: other slots come and go, but this one only when taken
    if (s.state == State::pending) {
      s.state = State::running;
      held.unlock();
      Result r = here(item);
      held.lock();
      slots_.erase(item);
      return r;
    }
    while (s.state != State::done) {
      Item other{};
      if (!claim(other)) {
        item_done_.wait(held, [&] { return s.state == State::done; });
        break;
      }
      held.unlock();
      finish(other, here);  // another taker's item: a failure goes to that taker
      held.lock();
    }
    Result r = std::move(s.result);
    const std::exception_ptr failure = s.failure;
    slots_.erase(item);
    if (failure) std::rethrow_exception(failure);
    return r;
  }

  std::int64_t by_workers() const {  // items the workers took on so far
    std::lock_guard<std::mutex> held(lock_);
    return by_workers_;
  }
  int workers() const { return int(computes_.size()); }

 private:
  enum class State { pending, running, done };
  struct Slot {
    State state = State::pending;
    Result result{};
    std::exception_ptr failure;
  };

  bool claim(Item& item) {  // the next pending item in order, marked running
    while (!order_.empty()) {
      const Item next = order_.front();
      order_.pop_front();
      const auto at = slots_.find(next);
      if (at == slots_.end() || at->second.state != State::pending) continue;  // a taker was first
      at->second.state = State::running;
      item = next;
      return true;
    }
    return false;
  }

  // Computes a claimed item (lock not held) and stores its result, or its failure for its taker.
  void finish(Item item, const Compute& compute) {
    Result r{};
    std::exception_ptr failure;
    try {
      r = compute(item);
    } catch (...) {
      failure = std::current_exception();
    }
    std::lock_guard<std::mutex> held(lock_);
    Slot& s = slots_.at(item);  // running: nobody erases it until it is done and taken
    s.result = std::move(r);
    s.failure = failure;
    s.state = State::done;
    item_done_.notify_all();
  }

  void work(const Compute& compute) {
    std::unique_lock<std::mutex> held(lock_);
    for (;;) {
      if (stopping_) return;  // a run that ended early leaves items nobody will take
      Item item{};
      if (!claim(item)) {
        work_ready_.wait(held);
        continue;
      }
      ++by_workers_;
      held.unlock();
      finish(item, compute);
      held.lock();
    }
  }

  std::deque<Item> order_;                 // expected, not yet handed to a worker or a helping taker
  std::unordered_map<Item, Slot> slots_;   // expected and not yet taken
  std::vector<Compute> computes_;
  mutable std::mutex lock_;
  std::condition_variable item_done_, work_ready_;
  bool stopping_ = false;
  std::int64_t by_workers_ = 0;
  std::vector<std::jthread> threads_;  // last: joined before the rest is destroyed
};

}  // namespace gcsim::apps
