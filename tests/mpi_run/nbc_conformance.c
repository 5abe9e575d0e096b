/* Non-blocking collectives in flight together, as MPI 3.1 section 5.12 allows: several on one
 * communicator (matched by their order of starting, waited in another order), on two
 * communicators at once, interleaved with point-to-point on the same ranks, completed by
 * MPI_Testall polling loops, and every I-form outstanding at once. A bad argument is the request's
 * error and takes no sequence number. Each expected value is computed from the standard's
 * definition of the result. Prints one line per rank; exits 1 if a check failed. */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

static int rank, size;
#include "conformance_check.h"

enum { MAXR = 64 };

/* Two on one communicator, waited for in the reverse order of their starts. */
static void two_outstanding(void) {
  MPI_Request req[2];
  int sum = 0, one = rank + 1, b = rank == size - 1 ? 42 : 0;
  MPI_Iallreduce(&one, &sum, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD, &req[0]);
  MPI_Ibcast(&b, 1, MPI_INT, size - 1, MPI_COMM_WORLD, &req[1]);
  CHECK(MPI_Wait(&req[1], MPI_STATUS_IGNORE) == MPI_SUCCESS && b == 42);
  CHECK(MPI_Wait(&req[0], MPI_STATUS_IGNORE) == MPI_SUCCESS && sum == size * (size + 1) / 2);
  CHECK(req[0] == MPI_REQUEST_NULL && req[1] == MPI_REQUEST_NULL);
}

/* A collective, a ring exchange and another collective, all outstanding; one Waitall. */
static void mixed_with_point_to_point(void) {
  MPI_Request req[4];
  int max = -1, left = (rank + size - 1) % size, right = (rank + 1) % size;
  int from_left = -1, to_right = 100 + rank, all[MAXR];
  MPI_Iallreduce(&rank, &max, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD, &req[0]);
  MPI_Irecv(&from_left, 1, MPI_INT, left, 3, MPI_COMM_WORLD, &req[1]);
  MPI_Isend(&to_right, 1, MPI_INT, right, 3, MPI_COMM_WORLD, &req[2]);
  MPI_Iallgather(&to_right, 1, MPI_INT, all, 1, MPI_INT, MPI_COMM_WORLD, &req[3]);
  MPI_Status st[4];
  CHECK(MPI_Waitall(4, req, st) == MPI_SUCCESS);
  CHECK(max == size - 1 && from_left == 100 + left && st[1].MPI_SOURCE == left && st[1].MPI_TAG == 3);
  for (int r = 0; r < size; ++r) CHECK(all[r] == 100 + r);
  /* A blocking collective while a non-blocking one of the same communicator is in flight: the
   * Ibarrier started first, so it is the first on every rank, and the Reduce after it matches. */
  MPI_Request barrier;
  int total = 0;
  MPI_Ibarrier(MPI_COMM_WORLD, &barrier);
  MPI_Reduce(&rank, &total, 1, MPI_INT, MPI_SUM, 0, MPI_COMM_WORLD);
  CHECK(MPI_Wait(&barrier, MPI_STATUS_IGNORE) == MPI_SUCCESS);
  CHECK(rank != 0 || total == size * (size - 1) / 2);
}

/* Polling: MPI_Testall until everything completed, with a message the left neighbour sends only
 * after it started its own collectives (so the polls must progress them meanwhile). */
static void testall_polling(void) {
  MPI_Request req[3];
  int prod = 0, two = 2, got = -1, left = (rank + size - 1) % size, right = (rank + 1) % size;
  MPI_Ibarrier(MPI_COMM_WORLD, &req[0]);
  MPI_Ireduce(&two, &prod, 1, MPI_INT, MPI_PROD, 0, MPI_COMM_WORLD, &req[1]);
  MPI_Irecv(&got, 1, MPI_INT, left, 4, MPI_COMM_WORLD, &req[2]);
  MPI_Send(&rank, 1, MPI_INT, right, 4, MPI_COMM_WORLD);
  int flag = 0, polls = 0;
  while (!flag) {
    CHECK(MPI_Testall(3, req, &flag, MPI_STATUSES_IGNORE) == MPI_SUCCESS);
    ++polls;
    if (polls > 1000000) break; /* never: each failed test advances simulated time */
  }
  CHECK(flag && polls >= 1 && got == left);
  CHECK(rank != 0 || prod == 1 << size);
  /* Testing a started collective does not block: a rank whose partner has not started yet sees
   * it incomplete. Rank 0 tests before releasing rank 1, which starts only after the release. */
  if (size > 1 && rank < 2) {
    MPI_Comm pair;
    MPI_Comm_split(MPI_COMM_WORLD, 0, rank, &pair);
    MPI_Request r;
    int token = 0, done = 1;
    if (rank == 0) {
      MPI_Ibarrier(pair, &r);
      MPI_Test(&r, &done, MPI_STATUS_IGNORE);
      CHECK(!done);
      MPI_Send(&token, 1, MPI_INT, 1, 5, MPI_COMM_WORLD);
    } else {
      MPI_Recv(&token, 1, MPI_INT, 0, 5, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      MPI_Ibarrier(pair, &r);
    }
    CHECK(MPI_Wait(&r, MPI_STATUS_IGNORE) == MPI_SUCCESS);
    MPI_Comm_free(&pair);
  } else if (size > 1) {
    MPI_Comm none;
    MPI_Comm_split(MPI_COMM_WORLD, MPI_UNDEFINED, rank, &none);
  }
}

/* Collectives on two communicators in flight at once, each numbered on its own. */
static void two_communicators(void) {
  MPI_Comm half;
  MPI_Comm_split(MPI_COMM_WORLD, rank % 2, rank, &half);
  MPI_Request req[2];
  int world_sum = 0, half_sum = 0;
  MPI_Iallreduce(&rank, &half_sum, 1, MPI_INT, MPI_SUM, half, &req[0]);
  MPI_Iallreduce(&rank, &world_sum, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD, &req[1]);
  CHECK(MPI_Waitall(2, req, MPI_STATUSES_IGNORE) == MPI_SUCCESS);
  int expected = 0;
  for (int r = rank % 2; r < size; r += 2) expected += r;
  CHECK(half_sum == expected && world_sum == size * (size - 1) / 2);
  MPI_Comm_free(&half);
}

/* Every rooted and all-to-all I-form outstanding at once, then one Waitall. */
static void every_form_at_once(void) {
  enum { K = 11 };
  MPI_Request req[K];
  int mine = rank + 1, gathered[MAXR], gatheredv[MAXR], scattered = -1, scatteredv = -1;
  int to_all[MAXR], from_all[MAXR], from_allv[MAXR], from_allw[MAXR], counts[MAXR], displs[MAXR], bytes[MAXR];
  int source[MAXR], block[MAXR], rs = -1, rsb = -1, scan = -1, exscan = -1;
  MPI_Datatype types[MAXR];
  for (int r = 0; r < size; ++r) {
    source[r] = 10 * r + 1, to_all[r] = 1000 * rank + r, counts[r] = 1, displs[r] = r;
    bytes[r] = r * (int)sizeof(int), types[r] = MPI_INT, block[r] = r + rank;
  }
  int root = size / 2;
  MPI_Igather(&mine, 1, MPI_INT, gathered, 1, MPI_INT, root, MPI_COMM_WORLD, &req[0]);
  MPI_Igatherv(&mine, 1, MPI_INT, gatheredv, counts, displs, MPI_INT, 0, MPI_COMM_WORLD, &req[1]);
  MPI_Iscatter(source, 1, MPI_INT, &scattered, 1, MPI_INT, root, MPI_COMM_WORLD, &req[2]);
  MPI_Iscatterv(source, counts, displs, MPI_INT, &scatteredv, 1, MPI_INT, 0, MPI_COMM_WORLD, &req[3]);
  MPI_Ialltoall(to_all, 1, MPI_INT, from_all, 1, MPI_INT, MPI_COMM_WORLD, &req[4]);
  MPI_Ialltoallv(to_all, counts, displs, MPI_INT, from_allv, counts, displs, MPI_INT, MPI_COMM_WORLD, &req[5]);
  MPI_Ialltoallw(to_all, counts, bytes, types, from_allw, counts, bytes, types, MPI_COMM_WORLD, &req[6]);
  MPI_Ireduce_scatter(block, &rs, counts, MPI_INT, MPI_SUM, MPI_COMM_WORLD, &req[7]);
  MPI_Ireduce_scatter_block(block, &rsb, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD, &req[8]);
  MPI_Iscan(&mine, &scan, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD, &req[9]);
  MPI_Iexscan(&mine, &exscan, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD, &req[10]);
  CHECK(MPI_Waitall(K, req, MPI_STATUSES_IGNORE) == MPI_SUCCESS);
  for (int r = 0; r < size; ++r) {
    CHECK(rank != root || gathered[r] == r + 1);
    CHECK(rank != 0 || gatheredv[r] == r + 1);
    CHECK(from_all[r] == 1000 * r + rank && from_allv[r] == 1000 * r + rank && from_allw[r] == 1000 * r + rank);
  }
  CHECK(scattered == 10 * rank + 1 && scatteredv == 10 * rank + 1);
  CHECK(rs == size * rank + size * (size - 1) / 2 && rsb == rank + size - 1);
  CHECK(scan == (rank + 1) * (rank + 2) / 2 && (rank == 0 || exscan == rank * (rank + 1) / 2));
}

static int error_class(int code) {
  int c = -1;
  MPI_Error_class(code, &c);
  return c;
}

/* A root outside the communicator: the request carries MPI_ERR_ROOT, raised by its wait, and the
 * refused call takes no sequence number, so the next collective matches on every rank. */
static void errors(void) {
  MPI_Request req;
  int x = rank == 0 ? 9 : 0;
  CHECK(MPI_Ibcast(&x, 1, MPI_INT, size, MPI_COMM_WORLD, &req) == MPI_SUCCESS);
  CHECK(error_class(MPI_Wait(&req, MPI_STATUS_IGNORE)) == MPI_ERR_ROOT);
  CHECK(error_class(MPI_Ibarrier(MPI_COMM_NULL, &req)) == MPI_ERR_COMM);
  CHECK(MPI_Ibcast(&x, 1, MPI_INT, 0, MPI_COMM_WORLD, &req) == MPI_SUCCESS);
  CHECK(MPI_Wait(&req, MPI_STATUS_IGNORE) == MPI_SUCCESS && x == 9);
  /* A communicator cannot be freed under a collective still in flight on it (this layer's limit):
   * refused with MPI_ERR_COMM on the rank that has one; freed once it completed. */
  MPI_Comm dup;
  MPI_Comm_dup(MPI_COMM_WORLD, &dup);
  MPI_Comm_set_errhandler(dup, MPI_ERRORS_RETURN);
  CHECK(MPI_Ibarrier(dup, &req) == MPI_SUCCESS);
  int flag = 0;
  MPI_Test(&req, &flag, MPI_STATUS_IGNORE);
  if (!flag) CHECK(error_class(MPI_Comm_free(&dup)) == MPI_ERR_COMM && dup != MPI_COMM_NULL);
  if (!flag) CHECK(MPI_Wait(&req, MPI_STATUS_IGNORE) == MPI_SUCCESS);
  CHECK(MPI_Comm_free(&dup) == MPI_SUCCESS && dup == MPI_COMM_NULL);
}

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  if (size > MAXR) MPI_Abort(MPI_COMM_WORLD, 2);
  two_outstanding();
  mixed_with_point_to_point();
  testall_polling();
  two_communicators();
  every_form_at_once();
  errors();
  printf("rank %d: %d checks, %d failed\n", rank, checks, failures);
  MPI_Finalize();
  return failures ? 1 : 0;
}
