#pragma once
// How a C entry point reports what the core throws: through the error handler of the
// communicator it names (error_handling.hpp; the runtime acts on MPI_ERRORS_ARE_FATAL, the
// default, MPI_ERRORS_RETURN and user handlers), then as its return value. The entry point names
// itself through std::source_location, so no call repeats its own name.
#include <new>
#include <source_location>

#include "apps/mpi/error.hpp"
#include "apps/mpi/error_handling.hpp"
#include "apps/mpi/registry.hpp"

namespace gcsim::mpi_layer {

// Not noexcept: a fatal error, or MPI_Abort from a user's handler, unwinds the rank's program.
template <class F>
int c_call(F&& body, std::source_location where = std::source_location::current()) {
  Registry& r = current_registry();
  CallScope scope(r, where.function_name());
  try {
    body(r);
    return MPI_SUCCESS;
  } catch (const Error& e) {
    return scope.raise(e);
  } catch (const std::bad_alloc&) {
    return scope.raise(Error(MPI_ERR_NO_MEM, "out of host memory"));
  } catch (...) {
    return scope.raise(Error(MPI_ERR_INTERN, "an internal error of the MPI layer"));
  }
}

// The datatype a handle names; MPI_ERR_TYPE if none, or if it must be committed and is not.
inline const Datatype& datatype_arg(Registry& r, MPI_Datatype handle, bool must_be_committed) {
  const Datatype* t = find_datatype(r, handle);
  if (!t) fail(MPI_ERR_TYPE, "invalid datatype");
  if (must_be_committed && !t->committed()) fail(MPI_ERR_TYPE, "datatype not committed");
  return *t;
}
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
