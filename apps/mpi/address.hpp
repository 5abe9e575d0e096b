#pragma once
// The address of a type-map entry: buffer + displacement, computed on integers. A buffer may be
// MPI_BOTTOM (null) with absolute displacements from MPI_Get_address, where pointer arithmetic on
// the null pointer would be undefined.
#include <cstddef>
#include <cstdint>

#include "apps/mpi/include/mpi.h"

namespace gcsim::mpi_layer {

inline std::byte* address_at(void* buffer, MPI_Aint displacement) {
  return reinterpret_cast<std::byte*>(reinterpret_cast<std::uintptr_t>(buffer) + static_cast<std::uintptr_t>(displacement));
}

inline const std::byte* address_at(const void* buffer, MPI_Aint displacement) {
  return reinterpret_cast<const std::byte*>(reinterpret_cast<std::uintptr_t>(buffer) +
                                            static_cast<std::uintptr_t>(displacement));
}

}  // namespace gcsim::mpi_layer
