#pragma once
// Which algorithm runs a collective: chosen by name (a user's spec such as
// "bcast=binomial,allreduce=ring") or, left to Auto, by message size and rank count as MPICH
// chooses (the thresholds below are MPICH 3.x's published defaults of its MPIR_CVAR_* control
// variables, stated as such; apps/mpi/README.md lists them).
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace gcsim::mpi_layer {

enum class Collective : std::uint8_t {
  Barrier, Bcast, Reduce, Allreduce, Gather, Gatherv, Scatter, Scatterv, Allgather, Allgatherv,
  Alltoall, Alltoallv, ReduceScatter, ReduceScatterBlock, Scan, Exscan,
};
inline constexpr std::size_t collective_count = 16;

enum class Algorithm : std::uint8_t {
  Auto,               // chosen by select_algorithm
  Dissemination,      // barrier
  Binomial,           // bcast, reduce, gather, scatter
  ScatterAllgather,   // bcast: binomial scatter + ring allgather (van de Geijn)
  RecursiveDoubling,  // allreduce, allgather(v), scan, exscan
  Ring,               // allreduce, allgather(v)
  Rabenseifner,       // allreduce: recursive-halving reduce-scatter + recursive-doubling allgather
  Linear,             // gather(v), scatter(v), alltoall(v) (all messages posted at once), scan, exscan
  Bruck,              // allgather(v), alltoall
  Pairwise,           // alltoall(v), reduce_scatter(_block)
  ReduceThenScatter,  // reduce_scatter(_block): binomial reduce to rank 0, linear scatterv
  RecursiveHalving,   // reduce_scatter(_block), commutative ops
};

std::string_view collective_name(Collective c);  // "bcast", "reduce_scatter_block", ...
std::string_view algorithm_name(Algorithm a);    // "binomial", "scatter_allgather", ...
// The algorithms a collective can run by name (Auto excluded), in the order the docs list them.
std::span<const Algorithm> algorithms_of(Collective c);

// One algorithm per collective, Auto where the spec says nothing.
class AlgorithmChoice {
 public:
  Algorithm operator[](Collective c) const { return chosen_[static_cast<std::size_t>(c)]; }
  void set(Collective c, Algorithm a) { chosen_[static_cast<std::size_t>(c)] = a; }

 private:
  std::array<Algorithm, collective_count> chosen_{};
};

// Parses "name=algorithm" items separated by commas (spaces around them allowed; "auto" resets
// one). Throws std::invalid_argument naming the unknown collective or algorithm and listing the
// known ones, or the malformed item.
AlgorithmChoice parse_algorithm_spec(std::string_view spec);

// MPICH 3.x defaults (bytes), the MPIR_CVAR_* of the same name.
inline constexpr std::size_t bcast_short_msg_size = 12288;
inline constexpr int bcast_min_procs = 8;
inline constexpr std::size_t allreduce_short_msg_size = 2048;
inline constexpr std::size_t allgather_short_msg_size = 81920;
inline constexpr std::size_t allgather_long_msg_size = 524288;
inline constexpr std::size_t alltoall_short_msg_size = 256;
inline constexpr std::size_t alltoall_medium_msg_size = 32768;
inline constexpr std::size_t redscat_commutative_long_msg_size = 524288;

// What the selection looks at. bytes: the message of one rank (bcast: the buffer; allreduce: the
// vector; allgather(v): the total gathered; alltoall: one block; reduce_scatter: the whole vector).
struct MessageShape {
  std::size_t bytes = 0;
  int ranks = 1;
  bool commutative = true;
  std::size_t count = 0;  // elements of a reduction
};
// The algorithm MPICH's default selection picks (never Auto).
Algorithm select_algorithm(Collective c, const MessageShape& shape);
// requested, or select_algorithm's pick when it is Auto; std::invalid_argument if c has no such
// algorithm (a caller that bypassed parse_algorithm_spec).
Algorithm resolve_algorithm(Collective c, Algorithm requested, const MessageShape& shape);

}  // namespace gcsim::mpi_layer
