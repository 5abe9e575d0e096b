#include "parix/sim/simulated_runtime.hpp"
#include "tests/support/published_machine.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <span>
#include <sstream>
#include "tests/support/scratch_path.hpp"

namespace gcsim::parix {
namespace {

using test_support::on_nodes;
using test_support::kConnectNeighbour;
using test_support::kEmptyMessageNeighbour;
using test_support::bytes_of;

using machine::kMicrosecond;
using machine::kMillisecond;

TEST(Runtime, EveryProcessorKnowsItsIdAndTheCount) {
  std::vector<int> seen(8, 0);
  run_simulated(on_nodes(8), [&](Processor& p) {
    EXPECT_EQ(p.count(), 8);
    ++seen[p.id()];
  });
  for (int s : seen) EXPECT_EQ(s, 1);
}

TEST(Runtime, ComputeChargesCyclesOverClock) {
  SimTime after = -1;
  RunResult r = run_simulated(on_nodes(1), [&](Processor& p) {
    p.compute("cycle", 80);  // 80 cycles at 80 MHz
    p.compute({{"cycle", 40}, {"flop", 40}});
    after = p.now();
  });
  EXPECT_EQ(after, 2 * kMicrosecond);
  EXPECT_EQ(r.makespan, 2 * kMicrosecond);
  EXPECT_EQ(r.processors[0].compute, 2 * kMicrosecond);
  EXPECT_EQ(r.processors[0].ops.at("cycle"), 120);
}

TEST(Runtime, UnknownOperationIsAnError) {
  EXPECT_THROW(run_simulated(on_nodes(1), [](Processor& p) { p.compute("teleport", 1); }), ParixError);
}

TEST(Runtime, ConnectIsARendezvousCostingConnectionTime) {
  std::vector<SimTime> up(2);
  run_simulated(on_nodes(2), [&](Processor& p) {
    if (p.id() == 1) p.compute("cycle", 80'000);  // arrives 1 ms late
    Link l = p.connect(1 - p.id());
    up[p.id()] = p.now();
  });
  EXPECT_EQ(up[0], kMillisecond + kConnectNeighbour);
  EXPECT_EQ(up[1], kMillisecond + kConnectNeighbour);
}

TEST(Runtime, ConnectionCostGrowsWithHops) {
  SimTime up = -1;
  run_simulated(on_nodes(64), [&](Processor& p) {
    if (p.id() == 0 || p.id() == 63) {
      Link l = p.connect(63 - p.id());
      up = p.now();
    }
  });
  EXPECT_EQ(up, 550 * kMicrosecond + 14 * 240 * kMicrosecond);
}

TEST(Runtime, SynchronousSendReturnsWhenReceived) {
  SimTime sent = -1, received = -1;
  Bytes got;
  run_simulated(on_nodes(2), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) {
      p.send(l, bytes_of("hello"));
      sent = p.now();
    } else {
      p.compute("cycle", 800'000);  // 10 ms before receiving
      got = p.recv(l);
      received = p.now();
    }
  });
  EXPECT_EQ(got, bytes_of("hello"));
  EXPECT_EQ(received, kConnectNeighbour + 10 * kMillisecond);
  EXPECT_EQ(sent, received);
}

TEST(Runtime, ReceiveWaitsForArrival) {
  SimTime received = -1;
  run_simulated(on_nodes(2), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) p.send(l, {});
    else {
      p.recv(l);
      received = p.now();
    }
  });
  EXPECT_EQ(received, kConnectNeighbour + kEmptyMessageNeighbour);
}

TEST(Runtime, AsynchronousSendReturnsAtOnceAndCompletesOnDelivery) {
  SimTime after_isend = -1, after_wait = -1;
  run_simulated(on_nodes(2), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) {
      Request r = p.isend(l, bytes_of("x"));
      after_isend = p.now();
      EXPECT_FALSE(r.done());
      p.wait(r);
      after_wait = p.now();
    } else {
      p.compute("cycle", 8'000'000);  // receives 100 ms later; the async send does not wait for it
      p.recv(l);
    }
  });
  EXPECT_EQ(after_isend, kConnectNeighbour);
  const SimTime one_byte = machine::from_seconds(1.0 / (4 * 35e6 / 16));
  EXPECT_EQ(after_wait, kConnectNeighbour + kEmptyMessageNeighbour + one_byte);
}

TEST(Runtime, MessagesOnALinkArriveInOrder) {
  std::vector<int> got;
  run_simulated(on_nodes(2), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) {
      std::vector<Request> rs;
      for (int i = 0; i < 20; ++i) rs.push_back(p.isend(l, Bytes(std::size_t(20 - i) * 100, std::byte(i))));
      for (auto& r : rs) p.wait(r);
    } else {
      for (int i = 0; i < 20; ++i) got.push_back(static_cast<int>(p.recv(l).at(0)));
    }
  });
  for (int i = 0; i < 20; ++i) EXPECT_EQ(got[i], i);
}

// Messages in flight live in slots that never move, which their arrival events name by address:
// a burst of 300 isends (about five chunks of slots, added while the first ones travel) on two
// links arrives whole and in order, and so does a second burst sent once the first is delivered.
TEST(Runtime, MessagesInFlightKeepTheirSlotsWhileMoreAreSent) {
  constexpr int kBurst = 300;
  std::vector<std::uint16_t> got[2];
  run_simulated(on_nodes(3), [&](Processor& p) {
    if (p.id() == 2) {
      Link from[2] = {p.connect(0), p.connect(1)};
      Bytes in;
      for (int i = 0; i < 2 * kBurst; ++i) {
        for (int s = 0; s < 2; ++s) {
          p.recv(from[s], in);
          std::uint16_t v = 0;
          std::memcpy(&v, in.data(), sizeof v);
          got[s].push_back(v);
        }
      }
      return;
    }
    Link to = p.connect(2);
    for (int burst = 0; burst < 2; ++burst) {
      std::vector<Request> rs;
      for (int i = 0; i < kBurst; ++i) {
        const std::uint16_t v = static_cast<std::uint16_t>(burst * kBurst + i + p.id() * 1000);
        rs.push_back(p.isend(to, std::as_bytes(std::span(&v, 1))));
      }
      for (auto& r : rs) p.wait(r);
    }
  });
  for (int s = 0; s < 2; ++s) {
    ASSERT_EQ(got[s].size(), 2u * kBurst);
    for (int i = 0; i < 2 * kBurst; ++i) ASSERT_EQ(got[s][i], i + s * 1000) << "link " << s << ", message " << i;
  }
}

TEST(Runtime, IrecvAndWaitAnyReturnTheFirstArrival) {
  std::size_t first = 99;
  Bytes first_data;
  run_simulated(on_nodes(3), [&](Processor& p) {
    if (p.id() == 0) {
      Link a = p.connect(1), b = p.connect(2);
      Request ra = p.irecv(a), rb = p.irecv(b);
      Request* both[] = {&ra, &rb};
      first = p.wait_any(both);
      first_data = both[first]->take();
      p.wait(first == 0 ? rb : ra);
    } else {
      Link l = p.connect(0);
      if (p.id() == 1) p.compute("cycle", 800'000);  // processor 1 is 10 ms late
      p.send(l, bytes_of(p.id() == 1 ? "one" : "two"));
    }
  });
  EXPECT_EQ(first, 1u);
  EXPECT_EQ(first_data, bytes_of("two"));
}

TEST(Runtime, TypedHelpersRoundTrip) {
  run_simulated(on_nodes(2), [&](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) {
      p.send_value(l, 3.25);
      const std::vector<int> v{1, 2, 3};
      p.send_vector(l, std::span<const int>(v));
    } else {
      EXPECT_EQ(p.recv_value<double>(l), 3.25);
      EXPECT_EQ(p.recv_vector<int>(l), (std::vector<int>{1, 2, 3}));
    }
  });
}

TEST(Runtime, MemoryPerNodeIsEnforced) {
  run_simulated(on_nodes(1), [](Processor& p) {
    p.use_memory(30 << 20, "data");
    EXPECT_THROW(p.use_memory(3 << 20, "data"), OutOfMemoryError);
    p.use_memory(-(10 << 20), "data");
    EXPECT_NO_THROW(p.use_memory(3 << 20, "data"));
  });
}

TEST(Runtime, ThreadsShareTheNodesTwoCpus) {
  SimTime joined = -1;
  run_simulated(on_nodes(1), [&](Processor& p) {
    std::vector<Thread> ts;
    for (int i = 0; i < 3; ++i) ts.push_back(p.spawn([](Processor& t) { t.compute("cycle", 80'000); }));
    for (auto& t : ts) t.join();
    joined = p.now();
  });
  // Two threads run at once on the two CPUs; the third waits for one: 2 ms in all.
  EXPECT_EQ(joined, 2 * kMillisecond);
}

TEST(Runtime, ThreadsCanCommunicate) {
  int got = 0;
  run_simulated(on_nodes(2), [&](Processor& p) {
    if (p.id() == 0) {
      Thread t = p.spawn([&](Processor& me) {
        Link l = me.connect(1);
        got = me.recv_value<int>(l);
      });
    } else {
      Link l = p.connect(0);
      p.send_value(l, 42);
    }
  });
  EXPECT_EQ(got, 42);
}

TEST(Runtime, BothReceivingFirstIsReportedAsDeadlock) {
  try {
    run_simulated(on_nodes(2), [](Processor& p) {
      Link l = p.connect(1 - p.id());
      p.recv(l);
      p.send(l, {});
    });
    FAIL() << "expected a deadlock";
  } catch (const DeadlockError& e) {
    const std::string report = e.what();
    EXPECT_NE(report.find("processor 0: blocked in recv on processor 1"), std::string::npos) << report;
    EXPECT_NE(report.find("processor 1: blocked in recv on processor 0"), std::string::npos) << report;
  }
}

TEST(Runtime, UnmatchedConnectIsReportedAsDeadlock) {
  try {
    run_simulated(on_nodes(3), [](Processor& p) {
      if (p.id() == 0) Link l = p.connect(2, 7);
      if (p.id() == 2) Link l = p.connect(0, 8);  // different tag: never matches
    });
    FAIL() << "expected a deadlock";
  } catch (const DeadlockError& e) {
    EXPECT_NE(std::string(e.what()).find("blocked in connect on processor 2"), std::string::npos) << e.what();
  }
}

TEST(Runtime, AnApplicationErrorStopsTheRunAndIsRethrown) {
  try {
    run_simulated(on_nodes(4), [](Processor& p) {
      if (p.id() == 3) throw std::runtime_error("boom on 3");
      Link l = p.connect(p.id() == 0 ? 1 : 0);
      p.recv(l);  // never satisfied
    });
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "boom on 3");
  }
}

TEST(Runtime, MisusedLinksAreErrors) {
  EXPECT_THROW(run_simulated(on_nodes(2), [](Processor& p) { p.connect(p.id()); }), ParixError);
  EXPECT_THROW(run_simulated(on_nodes(2), [](Processor& p) { p.connect(5); }), ParixError);
  EXPECT_THROW(run_simulated(on_nodes(1), [](Processor& p) {
                 Link none;
                 p.send(none, {});
               }),
               ParixError);
}

// A program with uneven compute and crossing messages, to compare two runs.
void busy_program(Processor& p) {
  const int n = p.count();
  for (int round = 0; round < 3; ++round) {
    p.compute("cycle", 1000 * (p.id() * 7 % 5 + 1));
    const int peer = p.id() ^ 1;
    if (peer < n) {
      Link l = p.connect(peer, round);
      Request s = p.isend(l, Bytes(std::size_t(100 * (p.id() + 1))));
      p.recv(l);
      p.wait(s);
    }
  }
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(Runtime, IdenticalRunsGiveIdenticalResultsAndTraces) {
  const auto dir = test_support::scratch_path("gcsim_runtime_test");
  std::filesystem::create_directories(dir);
  RunResult r[2];
  for (int i = 0; i < 2; ++i) {
    SimulationOptions o = on_nodes(8, "flow");
    o.trace.path = (dir / ("run" + std::to_string(i) + ".json")).string();
    r[i] = run_simulated(o, busy_program);
  }
  EXPECT_EQ(r[0].makespan, r[1].makespan);
  EXPECT_EQ(r[0].events, r[1].events);
  for (int p = 0; p < 8; ++p) EXPECT_EQ(r[0].processors[p].comm, r[1].processors[p].comm);
  const std::string a = slurp((dir / "run0.json").string()), b = slurp((dir / "run1.json").string());
  EXPECT_GT(a.size(), 1000u);
  EXPECT_EQ(a, b);
  EXPECT_EQ(slurp((dir / "run0.csv").string()), slurp((dir / "run1.csv").string()));
  std::filesystem::remove_all(dir);
}

TEST(Runtime, ReportsStatsPerProcessor) {
  RunResult r = run_simulated(on_nodes(2), [](Processor& p) {
    Link l = p.connect(1 - p.id());
    if (p.id() == 0) p.send(l, Bytes(1000));
    else p.recv(l);
  });
  EXPECT_EQ(r.processors[0].messages_sent, 1);
  EXPECT_EQ(r.processors[0].bytes_sent, 1000);
  EXPECT_EQ(r.processors[1].messages_sent, 0);
  EXPECT_EQ(r.processors[0].connections, 1);
  EXPECT_EQ(r.processors[0].connect, kConnectNeighbour);
  EXPECT_EQ(r.makespan, r.processors[1].finish);
  const auto j = r.to_json();
  EXPECT_DOUBLE_EQ(j["simulated"]["total_s"].get<double>(), r.simulated_seconds());
  EXPECT_EQ(j["nodes"].get<int>(), 2);
  EXPECT_EQ(j["model"].get<std::string>(), "analytic");
}

TEST(Runtime, ManyProcessorsBeyondTheGC) {
  SimulationOptions o;
  o.config = machine::load_machine_config(GCSIM_SOURCE_DIR "/configs/whatif-1024-nodes.toml");
  o.config = machine::with_nodes(o.config, 1024);
  int sum = 0;
  run_simulated(o, [&](Processor& p) {
    p.compute("cycle", p.id());
    ++sum;
  });
  EXPECT_EQ(sum, 1024);
}

}  // namespace
}  // namespace gcsim::parix
