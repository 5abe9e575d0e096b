#pragma once
// The standard's datatype constructors (MPI 3.1 sections 4.1.2-4.1.7) on resolved old types.
// Counts and block lengths are checked as the standard requires: a negative count is
// MPI_ERR_COUNT, a negative block length MPI_ERR_ARG.
#include <span>

#include "apps/mpi/datatype.hpp"

namespace gcsim::mpi_layer {

Datatype type_contiguous(MPI_Count count, const Datatype& old);
Datatype type_vector(MPI_Count count, MPI_Count blocklength, MPI_Aint stride_elements, const Datatype& old);
Datatype type_hvector(MPI_Count count, MPI_Count blocklength, MPI_Aint stride_bytes, const Datatype& old);
Datatype type_indexed(std::span<const int> blocklengths, std::span<const int> displacements_elements,
                      const Datatype& old);
Datatype type_hindexed(std::span<const int> blocklengths, std::span<const MPI_Aint> displacements_bytes,
                       const Datatype& old);
Datatype type_indexed_block(MPI_Count blocklength, std::span<const int> displacements_elements, const Datatype& old);
Datatype type_hindexed_block(MPI_Count blocklength, std::span<const MPI_Aint> displacements_bytes,
                             const Datatype& old);
// types[i] are the resolved array_of_types.
Datatype type_struct(std::span<const int> blocklengths, std::span<const MPI_Aint> displacements_bytes,
                     std::span<const Datatype* const> types);
Datatype type_resized(const Datatype& old, MPI_Aint lb, MPI_Aint extent);
// MPI_Type_create_subarray: the block subsizes at starts of an array of sizes elements of old,
// in row-major (MPI_ORDER_C) or column-major (MPI_ORDER_FORTRAN) order; its extent is the whole
// array's. MPI_ERR_ARG if the block does not lie inside the array.
Datatype type_subarray(std::span<const int> sizes, std::span<const int> subsizes, std::span<const int> starts,
                       int order, const Datatype& old);
// A copy, uncommitted unless old is (MPI_Type_dup keeps the committed state).
Datatype type_dup(const Datatype& old);

// The predefined pair types of MINLOC/MAXLOC, laid out as the C struct { value; int; }.
Datatype pair_type(MPI_Datatype handle);

}  // namespace gcsim::mpi_layer
