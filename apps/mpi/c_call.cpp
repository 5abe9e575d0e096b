#include "apps/mpi/c_call.hpp"

#include <climits>

namespace gcsim::mpi_layer {

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
