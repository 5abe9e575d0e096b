#pragma once
// MPI's collective operations as schedules of point-to-point messages over a CollectiveChannel
// (collective_channel.hpp). Every function runs on packed bytes, so it needs no datatype: the C
// entry point packs the user's buffer with type_transfer.hpp's pack (or passes it directly when
// its datatype is dense), calls the function here, and unpacks the result.
//
// Calling convention, for a C entry point holding (buf, count, datatype, op, root, comm):
//  - call: the communicator's channel and its collective sequence number. The communicator counts
//    the collectives it has started (every rank calls them in the same order, so every rank has
//    the same number for one call) and passes that count; tags are collective_tag(sequence, phase)
//    (collective_tags.hpp), so a rank that is already in the next collective cannot match a
//    message of this one.
//  - sizes are bytes, and every rank passes sizes that agree with the others' (as the standard
//    requires of matching type signatures); a mismatch is an internal error the channel throws.
//  - reductions take a Reduction (reduction_for(op, datatype, handle) makes one from the layer's
//    Op and Datatype) and count elements of Reduction::element_size packed bytes each.
//  - MPI_IN_PLACE: each function below says what the caller passes for the in-place form.
//  - algorithm: Algorithm::Auto selects as MPICH does (collective_selection.hpp); a named one
//    runs that one, except where its comment names a fallback (an algorithm that cannot keep a
//    non-commutative op's order, or needs a power-of-two rank count, runs the one named instead).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>

#include "apps/mpi/collective_channel.hpp"
#include "apps/mpi/collective_selection.hpp"
#include "apps/mpi/reduction.hpp"

namespace gcsim::mpi_layer {

struct CollectiveCall {
  CollectiveChannel& channel;
  std::uint32_t sequence;  // this collective's number on its communicator, counted from 0
};

// A reduction on packed elements: combine(in, inout, count) sets inout = in op inout element by
// element, in being the lower ranks' operand (the standard's order for a non-commutative op).
struct Reduction {
  std::size_t element_size = 0;  // packed bytes of one element
  bool commutative = true;
  std::function<void(const std::byte* in, std::byte* inout, std::size_t count)> combine;
};
// The Reduction of the layer's op on count elements of type (handle is what a user function
// receives as its datatype argument). Works on packed bytes for any committed type.
Reduction reduction_for(const Op& op, const Datatype& type, MPI_Datatype handle);

void barrier(const CollectiveCall& call, Algorithm algorithm = Algorithm::Auto);

// buffer: the root's data on entry at the root, the same number of bytes everywhere.
void bcast(const CollectiveCall& call, std::span<std::byte> buffer, int root, Algorithm algorithm = Algorithm::Auto);

// Reductions: send holds this rank's count elements (MPI_IN_PLACE: the caller packs recvbuf as
// send). send and result may not overlap.
// reduce: result (count elements) is written at the root only; other ranks may pass an empty span.
// A non-commutative op is reduced at rank 0 in rank order and the result sent to the root.
void reduce(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result,
            std::size_t count, const Reduction& reduction, int root, Algorithm algorithm = Algorithm::Auto);
// Ring needs a commutative op and falls back to recursive doubling for another; Rabenseifner
// falls back to recursive doubling when count is smaller than the largest power of two <= ranks.
void allreduce(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result,
               std::size_t count, const Reduction& reduction, Algorithm algorithm = Algorithm::Auto);
// send: the rank's ranks * count_per_rank elements, in rank order of their destination; result:
// its count_per_rank elements. Pairwise and recursive halving need a commutative op (else
// reduce_then_scatter runs).
void reduce_scatter_block(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result,
                          std::size_t count_per_rank, const Reduction& reduction,
                          Algorithm algorithm = Algorithm::Auto);
// counts: elements each rank receives (every rank passes all of them); send holds their sum.
void reduce_scatter(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result,
                    std::span<const std::size_t> counts, const Reduction& reduction,
                    Algorithm algorithm = Algorithm::Auto);
// Inclusive prefix: result = send of rank 0 op ... op send of this rank.
void scan(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result, std::size_t count,
          const Reduction& reduction, Algorithm algorithm = Algorithm::Auto);
// Exclusive prefix: result = ranks 0 .. this-1; rank 0's result is left untouched (undefined).
void exscan(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result,
            std::size_t count, const Reduction& reduction, Algorithm algorithm = Algorithm::Auto);

// gather: every rank's send (block bytes, the same everywhere) lands in rank order in the root's
// result (ranks * block bytes; other ranks may pass an empty span). MPI_IN_PLACE at the root: pass
// as send the root's own block of result.
void gather(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result, int root,
            Algorithm algorithm = Algorithm::Auto);
// gatherv: at the root, counts and displacements (bytes into result) of every rank's block; at
// the others they are not read (may be empty). Linear.
void gatherv(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result,
             std::span<const std::size_t> counts, std::span<const std::size_t> displacements, int root,
             Algorithm algorithm = Algorithm::Auto);
// scatter: the root's send (ranks * block bytes) is cut into blocks in rank order; each rank's
// arrives in result (block bytes). MPI_IN_PLACE at the root: pass as result the root's block of send.
void scatter(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result, int root,
             Algorithm algorithm = Algorithm::Auto);
void scatterv(const CollectiveCall& call, std::span<const std::byte> send, std::span<const std::size_t> counts,
              std::span<const std::size_t> displacements, std::span<std::byte> result, int root,
              Algorithm algorithm = Algorithm::Auto);

// allgather: result holds ranks blocks of block bytes; on entry this rank's block is already at
// its place (the caller copies its send there; MPI_IN_PLACE: it is there already). Recursive
// doubling needs a power-of-two rank count and runs Bruck otherwise.
void allgather(const CollectiveCall& call, std::span<std::byte> result, std::size_t block,
               Algorithm algorithm = Algorithm::Auto);
// allgatherv: the same with counts and displacements (bytes into result) of every rank's block.
void allgatherv(const CollectiveCall& call, std::span<std::byte> result, std::span<const std::size_t> counts,
                std::span<const std::size_t> displacements, Algorithm algorithm = Algorithm::Auto);

// alltoall: send and result hold ranks blocks of block bytes, block i of send goes to rank i.
// MPI_IN_PLACE: the caller copies result to a scratch buffer and passes that as send.
void alltoall(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result,
              std::size_t block, Algorithm algorithm = Algorithm::Auto);
// alltoallv, and alltoallw once the caller has packed each block with its own datatype: per-peer
// counts and displacements, in bytes, for both sides.
struct BlockLayout {
  std::span<const std::size_t> counts;
  std::span<const std::size_t> displacements;
};
void alltoallv(const CollectiveCall& call, std::span<const std::byte> send, BlockLayout send_layout,
               std::span<std::byte> result, BlockLayout result_layout, Algorithm algorithm = Algorithm::Auto);
inline void alltoallw(const CollectiveCall& call, std::span<const std::byte> send, BlockLayout send_layout,
                      std::span<std::byte> result, BlockLayout result_layout, Algorithm algorithm = Algorithm::Auto) {
  alltoallv(call, send, send_layout, result, result_layout, algorithm);
}

}  // namespace gcsim::mpi_layer
