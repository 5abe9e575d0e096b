/* Error handling as MPI 3.1 chapter 8.3 and the argument rules of chapters 3, 5 and 6 state it,
 * on any number of ranks: under MPI_ERRORS_RETURN each invalid argument gives its class; a user
 * handler is called with the communicator and the code (the call's own communicator, its
 * request's, or MPI_COMM_WORLD for a call without one); handlers are inherited by new
 * communicators; mismatched collectives (another call, root, op, count or type at the same point)
 * fail on the rank that arrives second with the class of the difference. Prints
 * "rank R: N checks, F failed" and exits 1 if any failed. gcsim mpirun only: the ranks that call
 * a mismatched collective first compute for a simulated second (gcsim_mpi_compute), so rank 0's
 * correct call is always the first to arrive. */
#include <gcsim/mpi_ext.h>
#include <mpi.h>
#include <stdio.h>

static int rank, size;
#include "conformance_check.h"

static int error_class(int code) {
  int cls = -1;
  MPI_Error_class(code, &cls);
  return cls;
}

/* What the user handler saw, reset before each call that should reach it. */
static int handler_calls = 0, handler_code = MPI_SUCCESS;
static MPI_Comm handler_comm = MPI_COMM_NULL;
static void record_error(MPI_Comm* comm, int* code, ...) {
  ++handler_calls;
  handler_comm = *comm;
  handler_code = *code;
}
static void reset_handler_record(void) {
  handler_calls = 0;
  handler_code = MPI_SUCCESS;
  handler_comm = MPI_COMM_NULL;
}

/* 8.3: MPI_ERRORS_ARE_FATAL is the default on the predefined communicators. */
static void default_handlers(void) {
  MPI_Errhandler h = MPI_ERRHANDLER_NULL;
  MPI_Comm_get_errhandler(MPI_COMM_WORLD, &h);
  CHECK(h == MPI_ERRORS_ARE_FATAL);
  MPI_Comm_get_errhandler(MPI_COMM_SELF, &h);
  CHECK(h == MPI_ERRORS_ARE_FATAL);
}

/* 3.2.2-3.2.3, 3.7.3: each invalid argument of a point-to-point call has its own class. */
static void point_to_point_classes(void) {
  int x = 1, y = 0;
  CHECK(error_class(MPI_Send(&x, 1, MPI_INT, size, 0, MPI_COMM_WORLD)) == MPI_ERR_RANK);
  CHECK(error_class(MPI_Send(&x, 1, MPI_INT, -5, 0, MPI_COMM_WORLD)) == MPI_ERR_RANK);
  CHECK(error_class(MPI_Send(&x, 1, MPI_INT, MPI_ANY_SOURCE, 0, MPI_COMM_WORLD)) == MPI_ERR_RANK);
  CHECK(error_class(MPI_Recv(&y, 1, MPI_INT, size + 2, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE)) == MPI_ERR_RANK);
  CHECK(error_class(MPI_Send(&x, 1, MPI_INT, rank, -3, MPI_COMM_WORLD)) == MPI_ERR_TAG);
  CHECK(error_class(MPI_Send(&x, 1, MPI_INT, rank, MPI_ANY_TAG, MPI_COMM_WORLD)) == MPI_ERR_TAG);
  CHECK(error_class(MPI_Recv(&y, 1, MPI_INT, rank, -4, MPI_COMM_WORLD, MPI_STATUS_IGNORE)) == MPI_ERR_TAG);
  CHECK(error_class(MPI_Send(&x, -1, MPI_INT, rank, 0, MPI_COMM_WORLD)) == MPI_ERR_COUNT);
  CHECK(error_class(MPI_Send(&x, 1, MPI_DATATYPE_NULL, rank, 0, MPI_COMM_WORLD)) == MPI_ERR_TYPE);
  CHECK(error_class(MPI_Send(NULL, 3, MPI_INT, rank, 0, MPI_COMM_WORLD)) == MPI_ERR_BUFFER);
  CHECK(error_class(MPI_Send(&x, 1, MPI_INT, 0, 0, MPI_COMM_NULL)) == MPI_ERR_COMM);
  MPI_Datatype pair;
  MPI_Type_contiguous(2, MPI_INT, &pair);  /* not committed: not usable for communication */
  CHECK(error_class(MPI_Send(&x, 1, pair, rank, 0, MPI_COMM_WORLD)) == MPI_ERR_TYPE);
  CHECK(error_class(MPI_Recv(&y, 1, pair, rank, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE)) == MPI_ERR_TYPE);
  MPI_Type_free(&pair);
  int flag = 0;
  CHECK(error_class(MPI_Iprobe(size, 0, MPI_COMM_WORLD, &flag, MPI_STATUS_IGNORE)) == MPI_ERR_RANK);
  CHECK(error_class(MPI_Iprobe(MPI_ANY_SOURCE, -2, MPI_COMM_WORLD, &flag, MPI_STATUS_IGNORE)) == MPI_ERR_TAG);
  CHECK(MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, MPI_STATUS_IGNORE) == MPI_SUCCESS);
  /* A request once completed is freed: its old handle names nothing. */
  MPI_Request r, s, kept;
  MPI_Irecv(&y, 1, MPI_INT, rank, 5, MPI_COMM_WORLD, &r);
  kept = r;
  MPI_Isend(&x, 1, MPI_INT, rank, 5, MPI_COMM_WORLD, &s);
  MPI_Wait(&s, MPI_STATUS_IGNORE);
  CHECK(MPI_Wait(&r, MPI_STATUS_IGNORE) == MPI_SUCCESS && r == MPI_REQUEST_NULL && y == 1);
  CHECK(error_class(MPI_Wait(&kept, MPI_STATUS_IGNORE)) == MPI_ERR_REQUEST);
  MPI_Request bogus = 987654;
  CHECK(error_class(MPI_Test(&bogus, &flag, MPI_STATUS_IGNORE)) == MPI_ERR_REQUEST);
  CHECK(error_class(MPI_Waitall(-1, &bogus, MPI_STATUSES_IGNORE)) == MPI_ERR_COUNT);
}

/* 6.4: calls on communicators; a freed one is invalid like MPI_COMM_NULL. */
static void communicator_classes(void) {
  MPI_Comm dup, split;
  int n = 0;
  CHECK(error_class(MPI_Comm_size(MPI_COMM_NULL, &n)) == MPI_ERR_COMM);
  CHECK(error_class(MPI_Comm_dup(MPI_COMM_NULL, &dup)) == MPI_ERR_COMM);
  MPI_Comm_dup(MPI_COMM_WORLD, &dup);
  const MPI_Comm freed = dup;
  MPI_Comm_free(&dup);
  CHECK(error_class(MPI_Comm_rank(freed, &n)) == MPI_ERR_COMM);
  CHECK(error_class(MPI_Barrier(freed)) == MPI_ERR_COMM);
  MPI_Comm world = MPI_COMM_WORLD;
  CHECK(error_class(MPI_Comm_free(&world)) == MPI_ERR_COMM);
  CHECK(error_class(MPI_Comm_split(MPI_COMM_WORLD, -7, 0, &split)) == MPI_ERR_ARG);
  CHECK(error_class(MPI_Comm_set_errhandler(MPI_COMM_WORLD, 4242)) == MPI_ERR_ARG);
}

/* 8.3.1: a new communicator inherits the handler of the one it is made from. */
static void inheritance(void) {
  MPI_Comm dup, split, cart;
  MPI_Errhandler h = MPI_ERRHANDLER_NULL, user;
  MPI_Comm_dup(MPI_COMM_WORLD, &dup);
  MPI_Comm_get_errhandler(dup, &h);
  CHECK(h == MPI_ERRORS_RETURN);
  MPI_Comm_create_errhandler(record_error, &user);
  MPI_Comm_set_errhandler(dup, user);
  MPI_Comm_split(dup, rank % 2, 0, &split);
  MPI_Comm_get_errhandler(split, &h);
  CHECK(h == user);
  int dims[1] = {size}, periods[1] = {0};
  MPI_Cart_create(dup, 1, dims, periods, 0, &cart);
  MPI_Comm_get_errhandler(cart, &h);
  CHECK(h == user);
  reset_handler_record();
  int x = 0;
  const int code = MPI_Send(&x, 1, MPI_INT, size, 0, cart);
  CHECK(handler_calls == 1 && handler_comm == cart && error_class(handler_code) == MPI_ERR_RANK && code == handler_code);
  MPI_Comm_free(&cart);
  MPI_Comm_free(&split);
  MPI_Comm_free(&dup);
  MPI_Errhandler_free(&user);
  CHECK(user == MPI_ERRHANDLER_NULL);
}

/* 8.3: which communicator's handler runs, and with what. */
static void user_handler(void) {
  MPI_Comm dup;
  MPI_Errhandler user, old_style;
  MPI_Comm_dup(MPI_COMM_WORLD, &dup);
  MPI_Comm_create_errhandler(record_error, &user);
  MPI_Comm_set_errhandler(dup, user);
  int x[2] = {1, 2}, y = 0;

  reset_handler_record();  /* the call's communicator */
  int code = MPI_Recv(&y, 1, MPI_INT, rank, -1 - 8, dup, MPI_STATUS_IGNORE);
  CHECK(handler_calls == 1 && handler_comm == dup && error_class(handler_code) == MPI_ERR_TAG && code == handler_code);

  reset_handler_record();  /* a request's: the truncation is found by MPI_Wait, a call with no communicator */
  MPI_Request r, s;
  MPI_Irecv(&y, 1, MPI_INT, rank, 3, dup, &r);
  MPI_Isend(x, 2, MPI_INT, rank, 3, dup, &s);
  MPI_Wait(&s, MPI_STATUS_IGNORE);
  code = MPI_Wait(&r, MPI_STATUS_IGNORE);
  CHECK(handler_calls == 1 && handler_comm == dup && error_class(handler_code) == MPI_ERR_TRUNCATE && code == handler_code);

  reset_handler_record();  /* MPI_ERRORS_RETURN on MPI_COMM_WORLD: the handler of dup is not involved */
  MPI_Type_contiguous(-1, MPI_INT, &(MPI_Datatype){0});
  CHECK(handler_calls == 0);

  MPI_Errhandler_create(record_error, &old_style);  /* MPI-1's name, the same handler kind */
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, old_style);
  reset_handler_record();  /* no communicator: MPI_COMM_WORLD's */
  MPI_Datatype t;
  code = MPI_Type_contiguous(-1, MPI_INT, &t);
  CHECK(handler_calls == 1 && handler_comm == MPI_COMM_WORLD && error_class(handler_code) == MPI_ERR_COUNT);
  reset_handler_record();  /* an invalid communicator has no handler: MPI_COMM_WORLD's */
  MPI_Barrier(MPI_COMM_NULL);
  CHECK(handler_calls == 1 && handler_comm == MPI_COMM_WORLD && error_class(handler_code) == MPI_ERR_COMM);
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  MPI_Errhandler_free(&old_style);

  reset_handler_record();  /* the program raises its own code; a freed handler still serves dup */
  MPI_Errhandler_free(&user);
  CHECK(MPI_Comm_call_errhandler(dup, 1234) == MPI_SUCCESS);
  CHECK(handler_calls == 1 && handler_comm == dup && handler_code == 1234);
  MPI_Errhandler h;
  MPI_Comm_set_errhandler(dup, MPI_ERRORS_RETURN);
  MPI_Comm_get_errhandler(dup, &h);
  CHECK(h == MPI_ERRORS_RETURN);
  CHECK(error_class(MPI_Comm_set_errhandler(dup, user)) == MPI_ERR_ARG);  /* freed: no longer a handle */
  MPI_Comm_free(&dup);
}

static void sum_ints(void* in, void* inout, int* len, MPI_Datatype* type) {
  (void)type;
  for (int i = 0; i < *len; ++i) ((int*)inout)[i] += ((int*)in)[i];
}

/* 5.1, 5.9: every rank of a communicator calls the same collective with the same root, op and
 * type signature. Rank 0 calls it right and first; the others call it wrong, get the class of
 * the difference, then call it right, which completes rank 0's. */
static void mismatched_collectives(void) {
  if (size == 1) return;
  const int late = rank != 0;
  int one[2] = {rank + 1, 1}, sum[2] = {0, 0};
  float f = 1.0f;
  const int expected = size * (size + 1) / 2;
  MPI_Op user_sum;
  MPI_Op_create(sum_ints, 1, &user_sum);
  if (late) gcsim_mpi_compute(1.0);
  if (late) CHECK(error_class(MPI_Bcast(one, 1, MPI_INT, 0, MPI_COMM_WORLD)) == MPI_ERR_OTHER);
  if (late) CHECK(error_class(MPI_Allreduce(one, sum, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD)) == MPI_ERR_OP);
  if (late) CHECK(error_class(MPI_Allreduce(one, sum, 1, MPI_INT, user_sum, MPI_COMM_WORLD)) == MPI_ERR_OP);
  if (late) CHECK(error_class(MPI_Allreduce(one, sum, 2, MPI_INT, MPI_SUM, MPI_COMM_WORLD)) == MPI_ERR_COUNT);
  if (late) CHECK(error_class(MPI_Allreduce(&f, sum, 1, MPI_FLOAT, MPI_SUM, MPI_COMM_WORLD)) == MPI_ERR_TYPE);
  CHECK(MPI_Allreduce(one, sum, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD) == MPI_SUCCESS && sum[0] == expected);

  if (late) gcsim_mpi_compute(1.0);
  if (late) CHECK(error_class(MPI_Reduce(one, sum, 1, MPI_INT, MPI_SUM, 1, MPI_COMM_WORLD)) == MPI_ERR_ROOT);
  sum[0] = 0;
  CHECK(MPI_Reduce(one, sum, 1, MPI_INT, MPI_SUM, 0, MPI_COMM_WORLD) == MPI_SUCCESS);
  if (rank == 0) CHECK(sum[0] == expected);

  /* Equal signatures written differently match: 2 x MPI_INT and 1 x contiguous(2, MPI_INT). */
  MPI_Datatype two;
  MPI_Type_contiguous(2, MPI_INT, &two);
  MPI_Type_commit(&two);
  int data[2] = {rank == 0 ? 7 : 0, rank == 0 ? 8 : 0};
  CHECK(MPI_Bcast(data, rank == 0 ? 2 : 1, rank == 0 ? MPI_INT : two, 0, MPI_COMM_WORLD) == MPI_SUCCESS);
  CHECK(data[0] == 7 && data[1] == 8);
  MPI_Type_free(&two);
  MPI_Op_free(&user_sum);
}

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  default_handlers();
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  point_to_point_classes();
  communicator_classes();
  inheritance();
  user_handler();
  mismatched_collectives();
  MPI_Barrier(MPI_COMM_WORLD);
  printf("rank %d: %d checks, %d failed\n", rank, checks, failures);
  MPI_Finalize();
  return failures == 0 ? 0 : 1;
}
