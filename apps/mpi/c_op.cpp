// The C entry points of reduction operations that need no communication.
#include "apps/mpi/c_call.hpp"

using namespace gcsim::mpi_layer;

extern "C" {

int MPI_Op_create(MPI_User_function* user_fn, int commute, MPI_Op* op) {
  return c_call([&](Registry& r) {
    MPI_Op& out = out_arg(op);
    if (!user_fn) fail(MPI_ERR_ARG, "null user function");
    out = r.ops.insert(Op::user(user_fn, commute != 0));
  });
}

int MPI_Op_free(MPI_Op* op) {
  return c_call([&](Registry& r) {
    MPI_Op& handle = out_arg(op);
    if (handle >= MPI_MAX && handle <= MPI_NO_OP) fail(MPI_ERR_OP, "a predefined operation cannot be freed");
    if (!r.ops.erase(handle)) fail(MPI_ERR_OP, "invalid operation");
    handle = MPI_OP_NULL;
  });
}

int MPI_Op_commutative(MPI_Op op, int* commute) {
  return c_call([&](Registry& r) { out_arg(commute) = op_arg(r, op).commutative() ? 1 : 0; });
}

int MPI_Reduce_local(const void* inbuf, void* inoutbuf, int count, MPI_Datatype datatype, MPI_Op op) {
  return c_call([&](Registry& r) {
    check_count_arg(count);
    if (count > 0 && (!inbuf || !inoutbuf)) fail(MPI_ERR_BUFFER, "null buffer");
    apply_op(op_arg(r, op), inbuf, inoutbuf, count, datatype_arg(r, datatype, true), datatype);
  });
}

}  // extern "C"
