// Choosing algorithms: the spec parser's results and errors, MPICH's default selection at and
// around each threshold, and the tag scheme that keeps consecutive collectives apart.
#include <stdexcept>
#include <string>

#include "apps/mpi/collective_tags.hpp"
#include "tests/mpi_layer/collective_test_support.hpp"

namespace gcsim::mpi_layer::testing {
namespace {

using A = Algorithm;
using C = Collective;

std::string error_of_spec(std::string_view spec) {
  try {
    parse_algorithm_spec(spec);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(MpiCollectiveSelection, ParsesNamedAlgorithmsAndLeavesTheRestAuto) {
  const AlgorithmChoice c = parse_algorithm_spec(" bcast=binomial, allreduce = ring,alltoall=bruck ");
  EXPECT_EQ(c[C::Bcast], A::Binomial);
  EXPECT_EQ(c[C::Allreduce], A::Ring);
  EXPECT_EQ(c[C::Alltoall], A::Bruck);
  EXPECT_EQ(c[C::Gather], A::Auto);
  EXPECT_EQ(parse_algorithm_spec("bcast=binomial,bcast=auto")[C::Bcast], A::Auto);
  EXPECT_EQ(parse_algorithm_spec("")[C::Scan], A::Auto);
}

TEST(MpiCollectiveSelection, EveryCollectiveAcceptsEachOfItsAlgorithmsByName) {
  for (std::size_t i = 0; i < collective_count; ++i) {
    const auto c = static_cast<Collective>(i);
    ASSERT_FALSE(algorithms_of(c).empty()) << collective_name(c);
    for (Algorithm a : algorithms_of(c)) {
      const std::string spec = std::string(collective_name(c)) + "=" + std::string(algorithm_name(a));
      EXPECT_EQ(parse_algorithm_spec(spec)[c], a) << spec;
    }
  }
}

TEST(MpiCollectiveSelection, AnUnknownCollectiveIsNamedWithTheKnownOnes) {
  const std::string e = error_of_spec("bcast=binomial,broadcast=ring");
  EXPECT_NE(e.find("unknown collective 'broadcast'"), std::string::npos) << e;
  EXPECT_NE(e.find("reduce_scatter_block"), std::string::npos) << e;
}

TEST(MpiCollectiveSelection, AnUnknownAlgorithmIsNamedWithTheCollectivesKnownOnes) {
  const std::string e = error_of_spec("allreduce=bruck");
  EXPECT_NE(e.find("unknown algorithm 'bruck' for allreduce"), std::string::npos) << e;
  EXPECT_NE(e.find("auto, recursive_doubling, ring, rabenseifner"), std::string::npos) << e;
}

TEST(MpiCollectiveSelection, MalformedItemsAreRejected) {
  EXPECT_NE(error_of_spec("bcast").find("is not collective=algorithm"), std::string::npos);
  EXPECT_NE(error_of_spec("bcast=binomial,,scan=linear").find("empty item"), std::string::npos);
  EXPECT_NE(error_of_spec("bcast=binomial,").find("trailing"), std::string::npos);
}

TEST(MpiCollectiveSelection, AnAlgorithmACollectiveDoesNotHaveIsRefusedByName) {
  try {
    resolve_algorithm(C::Bcast, A::Ring, {.bytes = 8, .ranks = 4});
    ADD_FAILURE() << "bcast accepted ring";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("bcast has no algorithm 'ring' (known: auto, binomial, scatter_allgather)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(resolve_algorithm(C::Bcast, A::ScatterAllgather, {.bytes = 8, .ranks = 4}), A::ScatterAllgather);
}

TEST(MpiCollectiveSelection, BcastSwitchesToScatterAllgatherForLongMessagesOnEnoughRanks) {
  EXPECT_EQ(select_algorithm(C::Bcast, {.bytes = bcast_short_msg_size - 1, .ranks = 64}), A::Binomial);
  EXPECT_EQ(select_algorithm(C::Bcast, {.bytes = bcast_short_msg_size, .ranks = 64}), A::ScatterAllgather);
  EXPECT_EQ(select_algorithm(C::Bcast, {.bytes = 1 << 20, .ranks = bcast_min_procs - 1}), A::Binomial);
}

TEST(MpiCollectiveSelection, AllreduceUsesRabenseifnerOnlyForLongCommutativeVectors) {
  EXPECT_EQ(select_algorithm(C::Allreduce, {.bytes = allreduce_short_msg_size, .ranks = 16, .count = 512}),
            A::RecursiveDoubling);
  EXPECT_EQ(select_algorithm(C::Allreduce, {.bytes = allreduce_short_msg_size + 4, .ranks = 16, .count = 513}),
            A::Rabenseifner);
  EXPECT_EQ(select_algorithm(C::Allreduce, {.bytes = 1 << 20, .ranks = 16, .commutative = false, .count = 1 << 18}),
            A::RecursiveDoubling);
  EXPECT_EQ(select_algorithm(C::Allreduce, {.bytes = 1 << 20, .ranks = 64, .count = 32}), A::RecursiveDoubling);
}

TEST(MpiCollectiveSelection, AllgatherByTotalSizeAndPowerOfTwo) {
  EXPECT_EQ(select_algorithm(C::Allgather, {.bytes = allgather_long_msg_size - 1, .ranks = 16}), A::RecursiveDoubling);
  EXPECT_EQ(select_algorithm(C::Allgather, {.bytes = allgather_long_msg_size, .ranks = 16}), A::Ring);
  EXPECT_EQ(select_algorithm(C::Allgather, {.bytes = allgather_short_msg_size - 1, .ranks = 12}), A::Bruck);
  EXPECT_EQ(select_algorithm(C::Allgatherv, {.bytes = allgather_short_msg_size, .ranks = 12}), A::Ring);
}

TEST(MpiCollectiveSelection, AlltoallBruckForSmallBlocksScatteredForMediumPairwiseForLong) {
  EXPECT_EQ(select_algorithm(C::Alltoall, {.bytes = alltoall_short_msg_size, .ranks = 8}), A::Bruck);
  EXPECT_EQ(select_algorithm(C::Alltoall, {.bytes = alltoall_short_msg_size, .ranks = 7}), A::Linear);
  EXPECT_EQ(select_algorithm(C::Alltoall, {.bytes = alltoall_medium_msg_size, .ranks = 64}), A::Linear);
  EXPECT_EQ(select_algorithm(C::Alltoall, {.bytes = alltoall_medium_msg_size + 1, .ranks = 64}), A::Pairwise);
}

TEST(MpiCollectiveSelection, TheRestFollowMpichsFixedChoices) {
  EXPECT_EQ(select_algorithm(C::Barrier, {.ranks = 5}), A::Dissemination);
  EXPECT_EQ(select_algorithm(C::Gather, {.bytes = 1 << 20, .ranks = 5}), A::Binomial);
  EXPECT_EQ(select_algorithm(C::Scan, {.bytes = 1 << 20, .ranks = 5}), A::RecursiveDoubling);
  EXPECT_EQ(select_algorithm(C::ReduceScatter, {.ranks = 5, .commutative = false}), A::ReduceThenScatter);
  EXPECT_EQ(select_algorithm(C::ReduceScatter, {.bytes = redscat_commutative_long_msg_size - 1, .ranks = 5}),
            A::RecursiveHalving);
  EXPECT_EQ(select_algorithm(C::ReduceScatterBlock, {.bytes = redscat_commutative_long_msg_size, .ranks = 5}),
            A::Pairwise);
  for (std::size_t i = 0; i < collective_count; ++i)
    EXPECT_NE(select_algorithm(static_cast<Collective>(i), {.bytes = 100, .ranks = 9}), A::Auto);
}

TEST(MpiCollectiveTags, CallsAndPhasesGetDistinctTagsInsideAnInt) {
  EXPECT_NE(collective_tag(0, CollectivePhase::BcastTree), collective_tag(1, CollectivePhase::BcastTree));
  EXPECT_NE(collective_tag(3, CollectivePhase::BcastScatter), collective_tag(3, CollectivePhase::BcastAllgather));
  EXPECT_GT(collective_tag(0xFFFFFFFFu, CollectivePhase::Exscan), 0);
  EXPECT_LT(collective_tag(0xFFFFFFFFu, CollectivePhase::Exscan), 1 << 30);
}

// Rank 0 runs its two broadcasts (from itself) without waiting for anyone, so the second's
// messages are queued while the others still receive the first's: each lands in its own call.
TEST(MpiCollectiveTags, BackToBackCollectivesOnOneCommunicatorStayApart) {
  for (int n : {2, 5, 8}) {
    InMemoryNetwork network(n);
    std::vector<Bytes> first(static_cast<std::size_t>(n)), second(static_cast<std::size_t>(n));
    network.run([&](CollectiveChannel& channel) {
      const auto r = static_cast<std::size_t>(channel.rank());
      first[r] = channel.rank() == 0 ? pattern(0, 40, 1) : Bytes(40);
      second[r] = channel.rank() == 0 ? pattern(0, 40, 2) : Bytes(40);
      bcast({channel, 0}, first[r], 0, A::Binomial);
      bcast({channel, 1}, second[r], 0, A::ScatterAllgather);
    });
    for (int r = 0; r < n; ++r) {
      EXPECT_EQ(first[static_cast<std::size_t>(r)], pattern(0, 40, 1));
      EXPECT_EQ(second[static_cast<std::size_t>(r)], pattern(0, 40, 2));
    }
  }
}

// With synchronous sends, two ranks that each send before receiving deadlock; started together
// (as steps::exchange does) they do not, and buffered sends never do.
TEST(MpiCollectiveChannelDouble, SynchronousSendsCatchAScheduleThatReliesOnBuffering) {
  const auto send_then_receive = [](CollectiveChannel& c) {
    Bytes out(4), in(4);
    c.wait_all(std::array{c.start_send(1 - c.rank(), 3, out)});
    c.wait_all(std::array{c.start_recv(1 - c.rank(), 3, in)});
  };
  EXPECT_NO_THROW(InMemoryNetwork(2, SendMode::Buffered).run(send_then_receive));
  EXPECT_THROW(InMemoryNetwork(2, SendMode::Synchronous).run(send_then_receive), std::runtime_error);
  EXPECT_NO_THROW(InMemoryNetwork(2, SendMode::Synchronous).run([](CollectiveChannel& c) {
    Bytes out(4), in(4);
    c.wait_all(std::array{c.start_send(1 - c.rank(), 3, out), c.start_recv(1 - c.rank(), 3, in)});
  }));
}

// The double itself: a wrong size and a receive nobody sends are errors, not silent or hanging.
TEST(MpiCollectiveChannelDouble, AWrongSizeThrowsAndADeadlockIsReported) {
  InMemoryNetwork network(2);
  EXPECT_THROW(network.run([](CollectiveChannel& c) {
                 Bytes b(c.rank() == 0 ? 4 : 5);
                 if (c.rank() == 0) c.wait_all(std::array{c.start_send(1, 9, b)});
                 else c.wait_all(std::array{c.start_recv(0, 9, b)});
               }),
               std::logic_error);
  EXPECT_THROW(network.run([](CollectiveChannel& c) {
                 Bytes b(4);
                 c.wait_all(std::array{c.start_recv(1 - c.rank(), 9, b)});
               }),
               std::runtime_error);
}

}  // namespace
}  // namespace gcsim::mpi_layer::testing
