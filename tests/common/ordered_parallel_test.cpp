// run_ordered: results arrive in index order whatever the number of threads and however long each
// task takes, and an exception surfaces after the tasks before it were delivered. parallel_for:
// every task runs once, and a failure keeps what the tasks before it left.
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "apps/common/ordered_parallel.hpp"

namespace gcsim::apps {
namespace {

// Later tasks finish first: task i spins longer the smaller i is.
int slow_square(int i, int n) {
  volatile long sink = 0;
  for (long k = 0; k < long(n - i) * 200000; ++k) sink = sink + k;
  return i * i;
}

TEST(OrderedParallel, DeliversInIndexOrderForEveryJobCount) {
  constexpr int n = 12;
  for (int jobs : {1, 2, 3, 8, 32}) {
    std::vector<int> order, values;
    run_ordered<int>(
        n, jobs, [&](int i) { return slow_square(i, n); },
        [&](int i, int& v) {
          order.push_back(i);
          values.push_back(v);
        });
    ASSERT_EQ(order.size(), std::size_t(n)) << "jobs " << jobs;
    for (int i = 0; i < n; ++i) {
      EXPECT_EQ(order[i], i) << "jobs " << jobs;
      EXPECT_EQ(values[i], i * i) << "jobs " << jobs;
    }
  }
}

TEST(OrderedParallel, TasksRunOnSeveralThreadsWhenAsked) {
  std::vector<std::thread::id> ids(6);
  run_ordered<int>(
      6, 3,
      [&](int i) {
        ids[i] = std::this_thread::get_id();
        return slow_square(i, 6);
      },
      [](int, int&) {});
  for (const auto& id : ids) EXPECT_NE(id, std::this_thread::get_id());  // the caller only delivers
}

TEST(OrderedParallel, FirstFailureInIndexOrderIsRethrownAfterEarlierRows) {
  for (int jobs : {1, 4}) {
    std::vector<int> delivered;
    try {
      run_ordered<int>(
          10, jobs,
          [](int i) {
            if (i == 3 || i == 7) throw std::runtime_error("task " + std::to_string(i));
            return i;
          },
          [&](int i, int&) { delivered.push_back(i); });
      FAIL() << "no exception with jobs " << jobs;
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "task 3");
    }
    EXPECT_EQ(delivered, (std::vector<int>{0, 1, 2})) << "jobs " << jobs;
  }
}

TEST(ParallelFor, RunsEveryTaskOnceForEveryJobCount) {
  constexpr int n = 12;
  for (int jobs : {1, 2, 5, 32}) {
    std::vector<int> runs(n, 0);  // one slot per task: no lock needed
    parallel_for(n, jobs, [&](int i) { runs[i] += slow_square(i, n) == i * i; });
    EXPECT_EQ(runs, std::vector<int>(n, 1)) << "jobs " << jobs;
  }
}

TEST(ParallelFor, FirstFailureInIndexOrderIsRethrownAndEarlierTasksKeepTheirResults) {
  for (int jobs : {1, 4}) {
    std::vector<int> done(10, 0);
    try {
      parallel_for(10, jobs, [&](int i) {
        if (i == 3 || i == 7) throw std::runtime_error("task " + std::to_string(i));
        done[i] = 1;
      });
      FAIL() << "no exception with jobs " << jobs;
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "task 3");
    }
    for (int i = 0; i < 3; ++i) EXPECT_EQ(done[i], 1) << "task " << i << ", jobs " << jobs;
  }
}

}  // namespace
}  // namespace gcsim::apps
