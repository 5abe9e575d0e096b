#pragma once
// How a C entry point reports what the core throws: as its return value. Today every error is
// returned (MPI_ERRORS_RETURN); the runtime will send it through the communicator's error
// handler first, whose default, MPI_ERRORS_ARE_FATAL, aborts.
#include <new>

#include "apps/mpi/error.hpp"
#include "apps/mpi/registry.hpp"

namespace gcsim::mpi_layer {

template <class F>
int c_call(F&& body) noexcept {
  try {
    body(current_registry());
    return MPI_SUCCESS;
  } catch (const Error& e) {
    return e.code();
  } catch (const std::bad_alloc&) {
    return MPI_ERR_NO_MEM;
  } catch (...) {
    return MPI_ERR_INTERN;
  }
}

// The datatype a handle names; MPI_ERR_TYPE if none, or if it must be committed and is not.
const Datatype& datatype_arg(Registry& r, MPI_Datatype handle, bool must_be_committed);
const Op& op_arg(Registry& r, MPI_Op handle);
const Group& group_arg(Registry& r, MPI_Group handle);
template <class T>
T& out_arg(T* p) {
  if (!p) fail(MPI_ERR_ARG, "null output argument");
  return *p;
}
// A count argument: negative is MPI_ERR_COUNT.
inline void check_count_arg(long long count) {
  if (count < 0) fail(MPI_ERR_COUNT, "negative count");
}
// An int result; MPI_UNDEFINED if it does not fit.
int int_or_undefined(long long value);

}  // namespace gcsim::mpi_layer
