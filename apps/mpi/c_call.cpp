#include "apps/mpi/c_call.hpp"

#include <climits>

namespace gcsim::mpi_layer {

const Datatype& datatype_arg(Registry& r, MPI_Datatype handle, bool must_be_committed) {
  const Datatype* t = find_datatype(r, handle);
  if (!t) fail(MPI_ERR_TYPE, "invalid datatype");
  if (must_be_committed && !t->committed()) fail(MPI_ERR_TYPE, "datatype not committed");
  return *t;
}

const Op& op_arg(Registry& r, MPI_Op handle) {
  const Op* op = find_op(r, handle);
  if (!op) fail(MPI_ERR_OP, "invalid operation");
  return *op;
}

const Group& group_arg(Registry& r, MPI_Group handle) {
  const Group* g = find_group(r, handle);
  if (!g) fail(MPI_ERR_GROUP, "invalid group");
  return *g;
}

int int_or_undefined(long long value) { return value > INT_MAX || value < INT_MIN ? MPI_UNDEFINED : static_cast<int>(value); }

}  // namespace gcsim::mpi_layer
