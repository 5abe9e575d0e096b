#pragma once
// The argument checks of point-to-point calls and probes (MPI 3.1 sections 3.2.2-3.2.3, 3.11):
// each failure is the standard's class, its text saying what was wrong ("invalid rank 9
// (communicator of 4 ranks)"). Wildcards are receive-side only.
#include <string>

#include "apps/mpi/c_call.hpp"
#include "apps/mpi/runtime/communicator.hpp"

namespace gcsim::mpi_layer {

// The failures, out of line: each check inlines into every send and receive as a few compares.
[[noreturn, gnu::cold, gnu::noinline]] inline void bad_peer(const Communicator& c, int peer) {
  if (peer == MPI_ANY_SOURCE) fail(MPI_ERR_RANK, "MPI_ANY_SOURCE is not a destination");
  fail(MPI_ERR_RANK, ("invalid rank " + std::to_string(peer) + " (communicator of " + std::to_string(c.size()) + " ranks)").c_str());
}

[[noreturn, gnu::cold, gnu::noinline]] inline void bad_tag(int tag) {
  if (tag == MPI_ANY_TAG) fail(MPI_ERR_TAG, "MPI_ANY_TAG is not a tag to send with");
  fail(MPI_ERR_TAG, ("invalid tag " + std::to_string(tag) + " (tags are 0 to MPI_TAG_UB)").c_str());
}

inline void check_peer(const Communicator& c, int peer, bool any_allowed) {
  if (peer == MPI_PROC_NULL || (any_allowed && peer == MPI_ANY_SOURCE)) return;
  if (peer < 0 || peer >= c.size()) [[unlikely]] bad_peer(c, peer);  // MPI_ANY_SOURCE is negative
}

// MPI_TAG_UB is INT_MAX here (MPI_Comm_get_attr), so every non-negative int is a valid tag.
inline void check_tag(int tag, bool any_allowed) {
  if (any_allowed && tag == MPI_ANY_TAG) return;
  if (tag < 0) [[unlikely]] bad_tag(tag);  // MPI_ANY_TAG is negative
}

[[noreturn, gnu::cold, gnu::noinline]] inline void bad_count(long long count) {
  fail(MPI_ERR_COUNT, ("negative count " + std::to_string(count)).c_str());
}

inline void check_message_count(long long count) {
  if (count < 0) [[unlikely]] bad_count(count);
}

[[noreturn, gnu::cold, gnu::noinline]] inline void null_buffer(long long count) {
  fail(MPI_ERR_BUFFER, ("null buffer for " + std::to_string(count) + " elements").c_str());
}

// A predefined datatype's data starts at the buffer itself, so null is no buffer (MPI_BOTTOM
// with a derived type of absolute displacements is a valid null buffer).
inline void check_message_buffer(const void* buf, long long count, MPI_Datatype datatype) {
  if (!buf && count > 0 && is_predefined_datatype(datatype)) [[unlikely]] null_buffer(count);
}

}  // namespace gcsim::mpi_layer
