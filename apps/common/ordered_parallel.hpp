#pragma once
// Independent jobs on host threads (gcsim sweep --jobs, calibration's --jobs): runs tasks 0..n-1
// on up to `jobs` host threads and hands their results to `deliver` on the calling thread in
// index order, each as soon as it and all before it are done. The output is therefore the same
// as running them one after another. The first exception (in index order) is rethrown once the
// tasks before it have been delivered; remaining tasks are abandoned.
#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace gcsim::apps {

template <class Result>
void run_ordered(int n, int jobs, const std::function<Result(int)>& task, const std::function<void(int, Result&)>& deliver) {
  if (jobs <= 1 || n <= 1) {  // one job: each task on this thread, delivered as soon as it is done
    for (int i = 0; i < n; ++i) {
      Result r = task(i);
      deliver(i, r);
    }
    return;
  }
  struct Slot {
    std::optional<Result> result;
    std::exception_ptr error;
    bool done = false;
  };
  std::vector<Slot> slots(n);
  std::mutex m;
  std::condition_variable cv;
  std::atomic<int> next{0};
  std::atomic<bool> stop{false};
  auto worker = [&] {
    for (int i = next++; i < n && !stop; i = next++) {
      Slot s;
      try {
        s.result.emplace(task(i));
      } catch (...) {
        s.error = std::current_exception();
      }
      s.done = true;
      std::lock_guard lock(m);
      slots[i] = std::move(s);
      cv.notify_all();
    }
  };
  std::vector<std::jthread> threads;
  for (int t = 0; t < std::min(jobs, n); ++t) threads.emplace_back(worker);  // this thread only delivers
  try {
    for (int i = 0; i < n; ++i) {
      std::unique_lock lock(m);
      cv.wait(lock, [&] { return slots[i].done; });
      Slot s = std::move(slots[i]);
      lock.unlock();
      if (s.error) std::rethrow_exception(s.error);
      deliver(i, *s.result);
    }
  } catch (...) {
    stop = true;  // the jthreads join when they leave scope, after their current task
    throw;
  }
}

// For tasks that leave their results in place themselves (each its own slot, or under a lock):
// task(i) for i in [0, n) as run_ordered runs them. On a failure, what the finished tasks left
// stays, whichever index they had.
template <class Task>
void parallel_for(int n, int jobs, Task&& task) {
  run_ordered<bool>(
      n, jobs,
      [&](int i) {
        task(i);
        return true;
      },
      [](int, bool&) {});
}

}  // namespace gcsim::apps
