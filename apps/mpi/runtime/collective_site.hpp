#pragma once
// What every collective C entry point does before and after its algorithm: checks its arguments
// (each failure is the standard's error class, its text naming the call), takes the communicator's
// next collective sequence number, and packs the user's typed buffers into the packed bytes the
// algorithms (apps/mpi/collective_algorithms.hpp) work on, then unpacks the result.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "apps/mpi/c_call.hpp"
#include "apps/mpi/collective_algorithms.hpp"
#include "apps/mpi/runtime/collective_ledger.hpp"
#include "apps/mpi/runtime/rank_channel.hpp"

namespace gcsim::mpi_layer {

using Bytes = std::vector<std::byte>;

// [[noreturn]]: throws Error(code) with "CALL: what".
[[noreturn]] void fail_in(const std::string& call, int code, const std::string& what);

// One collective call on one rank: its channel, sequence number and the algorithm chosen for it.
class CollectiveSite {
 public:
  // call: "MPI_Bcast"; details are appended to it in deadlock reports ("root=0").
  CollectiveSite(Rank& rank, const char* call, MPI_Comm comm, const std::string& details = "");
  const char* name() const { return call_; }
  int rank() const { return channel_.rank(); }
  int size() const { return channel_.size(); }
  Registry& registry() { return rank_.registry(); }
  Algorithm algorithm(Collective c) const { return rank_.collective_algorithms[c]; }
  // The sequence number is taken here, once the arguments are checked, so a call refused on one
  // rank does not shift the numbering of the next ones. Then the call's signature (its name, and
  // the root, op and data the checks below recorded) must agree with the other ranks'
  // (collective_ledger.hpp), or the call fails.
  CollectiveCall call();
  // Every rank's block has the signature of count x type (bcast, the reductions, the uniform
  // gathers and scatters); the v-forms' blocks are checked by their sizes as they arrive.
  void agree_on_data(long long count, const Datatype& type, MPI_Datatype handle);

  [[noreturn]] void fail(int code, const std::string& what) const { fail_in(call_, code, what); }
  void check_root(int root);
  void check_count(long long count, const char* which = "count") const;
  const Datatype& datatype(MPI_Datatype handle) const;
  const Op& op(MPI_Op handle);
  // A buffer that holds count > 0 elements must not be null; MPI_IN_PLACE only where allowed.
  void check_buffer(const void* buf, long long count, bool in_place_allowed, const char* which) const;
  // counts[i] >= 0 for every rank; null arrays are MPI_ERR_ARG.
  void check_counts(const int* counts, const char* which) const;
  // The per-rank blocks of a gather- or scatter-like call: the v-form's counts and displacements
  // (checked), or for the uniform form `count` elements per rank at rank * count. side names the
  // arguments in errors: "recv" (recvcounts, recvcount) or "send".
  struct Blocks {
    std::vector<int> counts, displs;
  };
  Blocks blocks(const int* counts, const int* displs, int count, bool varying, const char* side = "recv") const;

 private:
  Rank& rank_;
  const char* call_;
  Communicator& comm_;
  RankChannel channel_;
  CollectiveSignature signature_;
};

// A non-blocking collective runs its blocking form on its own schedule (collective_progress.hpp)
// with the sequence number it took at its start: while one of these lives, the next
// CollectiveSite::call() uses `sequence`.
class ReservedSequence {
 public:
  explicit ReservedSequence(std::uint32_t sequence);
  ~ReservedSequence();
  ReservedSequence(const ReservedSequence&) = delete;
  ReservedSequence& operator=(const ReservedSequence&) = delete;
};
// The communicator a collective names; MPI_ERR_COMM naming the call if none.
Communicator& communicator_of(Rank& rank, const char* call, MPI_Comm comm);

// Typed buffers <-> packed bytes. at(buf, index, type): the address of element `index`.
Bytes pack_of(const void* buf, long long count, const Datatype& type);
void unpack_into(std::span<const std::byte> bytes, void* buf, long long count, const Datatype& type);
const void* element_at(const void* buf, long long index, const Datatype& type);
void* element_at(void* buf, long long index, const Datatype& type);
inline std::size_t packed_bytes(long long count, const Datatype& type) {
  return static_cast<std::size_t>(count) * static_cast<std::size_t>(type.size());
}
// Exclusive prefix sums of sizes: the packed displacements of blocks laid end to end.
std::vector<std::size_t> end_to_end(const std::vector<std::size_t>& sizes);

}  // namespace gcsim::mpi_layer
