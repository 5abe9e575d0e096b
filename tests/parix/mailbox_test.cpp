// Addressed messages (parix/mailbox.hpp): no connect, per-pair sending order, the connection
// set-up paid once per pair, and await waking on an arrival or a finished request.
#include <gtest/gtest.h>

#include <vector>

#include "machine/connection_service.hpp"
#include "machine/interconnect_registry.hpp"
#include "machine/machine_config.hpp"
#include "machine/network_model.hpp"
#include "parix/mailbox.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::parix {
namespace {

SimulationOptions machine_of(int nodes) {
  SimulationOptions o;
  o.config = machine::with_nodes(machine::published_machine_config(), nodes);
  return o;
}

Letter next_letter(Mailbox& box, std::vector<Letter>& got) {
  while (got.empty()) {
    box.collect(got);
    if (got.empty()) box.await({}, "test", -1);
  }
  Letter l = std::move(got.front());
  got.erase(got.begin());
  return l;
}

TEST(Mailbox, LettersFromOneSenderArriveInSendingOrderWhateverTheirSizes) {
  std::vector<std::int64_t> order;
  run_simulated(machine_of(2), [&](Processor& p) {
    Mailbox& box = *mailbox_of(p);
    if (p.id() == 0) {
      std::vector<Request> sent;
      for (std::int64_t i = 0; i < 6; ++i) {
        Envelope e;
        e.words[0] = i;
        sent.push_back(box.post(1, e, Bytes(i % 2 == 0 ? 100000 : 1)));  // short ones could overtake
      }
      for (Request& r : sent) {
        while (r.state()->running()) box.await(std::span(&r, 1), "test", 1);
        EXPECT_TRUE(r.test());
      }
      return;
    }
    std::vector<Letter> got;
    for (int i = 0; i < 6; ++i) {
      Letter l = next_letter(box, got);
      EXPECT_EQ(l.source, 0);
      order.push_back(l.envelope.words[0]);
    }
  });
  EXPECT_EQ(order, (std::vector<std::int64_t>{0, 1, 2, 3, 4, 5}));
}

// send() is post() without a request: the same letters, in the same order, at the same times,
// mixed freely with posted ones on one pair.
TEST(Mailbox, SentLettersArriveAsPostedOnesDo) {
  auto arrivals = [](bool unwatched) {
    std::vector<std::pair<std::int64_t, machine::SimTime>> seen;
    run_simulated(machine_of(2), [&](Processor& p) {
      Mailbox& box = *mailbox_of(p);
      if (p.id() == 0) {
        for (std::int64_t i = 0; i < 6; ++i) {
          Envelope e;
          e.words[0] = i;
          const Bytes data(i % 2 == 0 ? 100000 : 1);
          if (unwatched && i % 3 != 0) box.send(1, e, data);
          else box.post(1, e, data);
        }
        return;
      }
      std::vector<Letter> got;
      for (int i = 0; i < 6; ++i) {
        const Letter l = next_letter(box, got);
        seen.emplace_back(l.envelope.words[0], p.now());
      }
    });
    return seen;
  };
  const auto posted = arrivals(false);
  EXPECT_EQ(arrivals(true), posted);
  ASSERT_EQ(posted.size(), 6u);
  for (std::size_t i = 0; i < posted.size(); ++i) EXPECT_EQ(posted[i].first, static_cast<std::int64_t>(i));
}

TEST(Mailbox, FirstLetterOfAPairPaysTheConnectionSetUpOnce) {
  const SimulationOptions o = machine_of(2);
  std::vector<machine::SimTime> arrivals;
  RunResult r = run_simulated(o, [&](Processor& p) {
    Mailbox& box = *mailbox_of(p);
    if (p.id() == 0) {
      box.post(1, {}, {});
      box.post(1, {}, {});
      return;
    }
    std::vector<Letter> got;
    next_letter(box, got);
    arrivals.push_back(p.now());
    next_letter(box, got);
    arrivals.push_back(p.now());
  });
  const auto interconnect = machine::make_interconnect(o.config);
  const machine::ConnectionService connections(o.config, *interconnect);
  machine::Kernel kernel;
  const auto network = machine::make_network_model(o.config.network_model, {kernel, *interconnect, o.config, nullptr});
  const machine::SimTime empty = network->uncontended_time(1, 0);
  ASSERT_EQ(arrivals.size(), 2u);
  EXPECT_EQ(arrivals[0], connections.duration(0, 1) + empty);
  EXPECT_EQ(arrivals[1], connections.duration(0, 1) + empty);  // left together once the link was up
  EXPECT_EQ(r.processors[0].connections, 1);
}

TEST(Mailbox, EveryProcessorAwaitingMailWithNoneComingIsADeadlockNamingTheCall) {
  try {
    run_simulated(machine_of(2), [](Processor& p) { mailbox_of(p)->await({}, "MPI_Recv(source 1)", -1); });
    FAIL() << "no deadlock reported";
  } catch (const DeadlockError& e) {
    EXPECT_NE(std::string(e.what()).find("processor 1: blocked in MPI_Recv(source 1)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace gcsim::parix
