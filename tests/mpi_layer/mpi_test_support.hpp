#pragma once
// What several of the MPI layer's test files use: basic datatypes and the error code of a call.
#include "apps/mpi/datatype.hpp"
#include "apps/mpi/error.hpp"

namespace gcsim::mpi_layer {

inline const Datatype int_type = Datatype::of_basic(Basic::Int);
inline const Datatype double_type = Datatype::of_basic(Basic::Double);
inline const Datatype char_type = Datatype::of_basic(Basic::Char);
inline const Datatype float_type = Datatype::of_basic(Basic::Float);
inline const Datatype packed_type = Datatype::of_basic(Basic::Packed);

// The MPI error class f throws, MPI_SUCCESS if it returns.
template <class F>
int error_of(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.code();
  }
  return MPI_SUCCESS;
}

}  // namespace gcsim::mpi_layer
