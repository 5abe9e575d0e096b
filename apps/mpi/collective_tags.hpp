#pragma once
// The tags of collective messages. Collectives run on a context of their own (the channel's), and
// every rank calls a communicator's collectives in the same order, so the communicator's count of
// collectives started (the sequence number) names one call on every rank. A tag is
//   (sequence mod 2^24) * 64 + phase
// with phase (0..63) one step kind of one algorithm (collective_phases below), so the messages of
// one call never match a receive of the next, nor one phase's those of another phase of a
// composite algorithm. Tags stay below 2^30, inside any int. A rank would have to run 2^24
// collectives ahead of a peer on one communicator for two calls to share tags.
#include <cstdint>

namespace gcsim::mpi_layer {

enum class CollectivePhase : std::uint8_t {
  Barrier = 1, BcastTree, BcastScatter, BcastAllgather, ReduceTree, ReduceForward, AllreduceFold,
  AllreduceExchange, AllreduceUnfold, AllreduceRingScatter, AllreduceRingGather, RabenseifnerHalving,
  RabenseifnerDoubling, Gather, Gatherv, Scatter, Scatterv, Allgather, Alltoall, Alltoallv, ReduceScatter,
  Scan, Exscan, ReduceScatterFold, ReduceScatterHalving, ReduceScatterUnfold,
};

inline constexpr int collective_tag(std::uint32_t sequence, CollectivePhase phase) {
  return static_cast<int>((sequence & 0xFFFFFFu) * 64u + static_cast<std::uint32_t>(phase));
}

}  // namespace gcsim::mpi_layer
