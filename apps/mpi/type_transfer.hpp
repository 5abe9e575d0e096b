#pragma once
// Moving data described by datatypes (MPI 3.1 sections 3.3, 4.1.11, 4.2): pack and unpack, the
// copy a receive makes from the sender's type map into its own, the type-signature check that
// decides MPI_ERR_TRUNCATE and type mismatch, and counts from a number of bytes received.
#include <cstddef>
#include <span>

#include "apps/mpi/datatype.hpp"

namespace gcsim::mpi_layer {

// Packs count elements of type from buffer into out at position, advancing it (MPI_Pack);
// MPI_ERR_TRUNCATE if they do not fit.
void pack(const void* buffer, MPI_Count count, const Datatype& type, std::span<std::byte> out, MPI_Count& position);
// Unpacks count elements from in at position into buffer, advancing it (MPI_Unpack).
void unpack(std::span<const std::byte> in, MPI_Count& position, void* buffer, MPI_Count count, const Datatype& type);
// What pack needs for count elements (MPI_Pack_size): their bytes, packed with no header.
MPI_Count pack_size(MPI_Count count, const Datatype& type);
// The bytes pack would write, where they lie in buffer as one block already (a dense type: one
// run covering its extent); an empty span with a null data() otherwise, or for no bytes.
std::span<const std::byte> contiguous_bytes(const void* buffer, MPI_Count count, const Datatype& type);

// Copies from (count_from, from) into (count_to, to), element by element in type-map order, as a
// receive does; stops at the end of either. Returns the bytes copied. The signatures are not
// checked here (see match_signatures).
MPI_Count copy_typed(const void* source, MPI_Count count_from, const Datatype& from, void* destination,
                     MPI_Count count_to, const Datatype& to);

enum class SignatureMatch {
  Match,     // the sent signature is a prefix of (or equal to) the receive's
  Truncate,  // it is longer than the receive's but they agree as far as the receive goes
  Mismatch,  // a basic type differs: an erroneous program (MPI_ERR_TYPE)
};
// The standard's type matching of a send of (count_sent, sent) against a receive of
// (count_received, received). MPI_PACKED on either side matches any type, byte for byte.
SignatureMatch match_signatures(const Datatype& sent, MPI_Count count_sent, const Datatype& received,
                                MPI_Count count_received);

// MPI_Get_count: whole elements of type in bytes, MPI_UNDEFINED if bytes is not a whole number.
MPI_Count count_of(MPI_Count bytes, const Datatype& type);
// MPI_Get_elements: basic elements of type's map in bytes, MPI_UNDEFINED if bytes ends inside one.
MPI_Count elements_of(MPI_Count bytes, const Datatype& type);
// The inverse (MPI_Status_set_elements): the bytes of the first elements basic elements of a
// sequence of type's elements.
MPI_Count bytes_of_elements(MPI_Count elements, const Datatype& type);

}  // namespace gcsim::mpi_layer
