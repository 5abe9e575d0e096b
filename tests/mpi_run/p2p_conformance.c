/* Point-to-point as MPI 3.1 chapter 3 states it, checked by the program itself on any number of
 * ranks: self messages, MPI_PROC_NULL, zero counts, MPI_TAG_UB, truncation, wildcards with arrival
 * out of rank order, non-overtaking, tag selection among posted receives, probes and counts, and
 * MPI_Issend completing only once matched, and communicators' own contexts (dup, split, compare,
 * free). Prints one line per rank; exits 1 if a check failed.
 * The same source runs under Open MPI (tests/mpi_run/CMakeLists.txt). */
#include <mpi.h>
#include <stdio.h>
#include <string.h>

#include "conformance_check.h"

static int rank, size;

static void self_and_null(void) {
  int out[4] = {1, 2, 3, 4}, in[4] = {0}, count = -1;
  MPI_Status st;
  MPI_Request r;
  MPI_Isend(out, 4, MPI_INT, rank, 3, MPI_COMM_WORLD, &r);
  MPI_Recv(in, 4, MPI_INT, rank, 3, MPI_COMM_WORLD, &st);
  MPI_Wait(&r, MPI_STATUS_IGNORE);
  CHECK(memcmp(in, out, sizeof in) == 0 && st.MPI_SOURCE == rank && st.MPI_TAG == 3);
  CHECK(MPI_Send(out, 4, MPI_INT, MPI_PROC_NULL, 1, MPI_COMM_WORLD) == MPI_SUCCESS);
  CHECK(MPI_Recv(in, 4, MPI_INT, MPI_PROC_NULL, 1, MPI_COMM_WORLD, &st) == MPI_SUCCESS);
  MPI_Get_count(&st, MPI_INT, &count);
  CHECK(st.MPI_SOURCE == MPI_PROC_NULL && st.MPI_TAG == MPI_ANY_TAG && count == 0);
}

static void zero_counts_and_tag_ub(void) {
  int* tag_ub = NULL;
  int flag = 0, count = -1, dummy = 0;
  MPI_Comm_get_attr(MPI_COMM_WORLD, MPI_TAG_UB, &tag_ub, &flag);
  CHECK(flag && *tag_ub >= 32767);
  const int right = (rank + 1) % size, left = (rank + size - 1) % size;
  MPI_Status st;
  MPI_Sendrecv(&dummy, 0, MPI_INT, right, *tag_ub, &dummy, 0, MPI_INT, left, *tag_ub, MPI_COMM_WORLD, &st);
  MPI_Get_count(&st, MPI_INT, &count);
  CHECK(count == 0 && st.MPI_SOURCE == left && st.MPI_TAG == *tag_ub);
}

/* A message longer than the receive is MPI_ERR_TRUNCATE, short (eager) or long (rendezvous). */
static void truncation(void) {
  static int out[20000], in[10000];
  for (int n = 10; n <= 20000; n *= 2000) {
    MPI_Request r;
    MPI_Status st;
    MPI_Isend(out, n, MPI_INT, rank, 9, MPI_COMM_WORLD, &r);
    const int code = MPI_Recv(in, n / 2, MPI_INT, rank, 9, MPI_COMM_WORLD, &st);
    int cls = -1;
    MPI_Error_class(code, &cls);
    CHECK(cls == MPI_ERR_TRUNCATE);
    MPI_Wait(&r, MPI_STATUS_IGNORE);
  }
}

/* Every other rank sends two messages to rank 0, tags 1 then 2, the larger ones from the lower
 * ranks, so that arrival is not in rank order; rank 0 takes them with wildcards. */
static void wildcards_and_order(void) {
  static double big[4096];
  if (rank != 0) {
    const int n = 4096 / rank;
    MPI_Send(big, n, MPI_DOUBLE, 0, 1, MPI_COMM_WORLD);
    MPI_Send(big, 1, MPI_DOUBLE, 0, 2, MPI_COMM_WORLD);
    return;
  }
  int seen[64] = {0};
  for (int i = 0; i < 2 * (size - 1); ++i) {
    MPI_Status st;
    MPI_Recv(big, 4096, MPI_DOUBLE, MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &st);
    int count = -1;
    MPI_Get_count(&st, MPI_DOUBLE, &count);
    CHECK(st.MPI_SOURCE > 0 && st.MPI_SOURCE < size);
    CHECK(st.MPI_TAG == seen[st.MPI_SOURCE] + 1);  /* tag 1 before tag 2 from each sender */
    CHECK(count == (st.MPI_TAG == 1 ? 4096 / st.MPI_SOURCE : 1));
    seen[st.MPI_SOURCE] = st.MPI_TAG;
  }
  for (int r = 1; r < size; ++r) CHECK(seen[r] == 2);
}

/* Receives posted for tag 2 then tag 1 each take their own message; probes see them, in order. */
static void tag_selection_and_probe(void) {
  int a = 10, b = 20, got1 = 0, got2 = 0, flag = 0, count = -1;
  MPI_Request rs[2], ss[2];
  MPI_Status st;
  MPI_Isend(&a, 1, MPI_INT, rank, 1, MPI_COMM_WORLD, &ss[0]);
  MPI_Isend(&b, 1, MPI_INT, rank, 2, MPI_COMM_WORLD, &ss[1]);
  MPI_Probe(rank, MPI_ANY_TAG, MPI_COMM_WORLD, &st);
  MPI_Get_count(&st, MPI_INT, &count);
  CHECK(st.MPI_TAG == 1 && count == 1);
  MPI_Probe(rank, 2, MPI_COMM_WORLD, &st);  /* it may not have arrived yet: Iprobe could say no */
  CHECK(st.MPI_TAG == 2);
  MPI_Iprobe(rank, 2, MPI_COMM_WORLD, &flag, &st);  /* now it has */
  CHECK(flag && st.MPI_SOURCE == rank);
  MPI_Irecv(&got2, 1, MPI_INT, rank, 2, MPI_COMM_WORLD, &rs[0]);
  MPI_Irecv(&got1, 1, MPI_INT, rank, 1, MPI_COMM_WORLD, &rs[1]);
  MPI_Waitall(2, rs, MPI_STATUSES_IGNORE);
  MPI_Waitall(2, ss, MPI_STATUSES_IGNORE);
  CHECK(got1 == 10 && got2 == 20 && rs[0] == MPI_REQUEST_NULL);
}

/* Rank 0's MPI_Issend cannot complete before rank 1 posts the matching receive, which rank 1 does
 * only after rank 0 told it (by another message) that its tests found the send incomplete. */
static void synchronous_send(void) {
  if (size < 2 || rank > 1) return;
  int value = 42, go = 1, flag = 0;
  if (rank == 0) {
    MPI_Request r;
    MPI_Issend(&value, 1, MPI_INT, 1, 5, MPI_COMM_WORLD, &r);
    for (int i = 0; i < 10; ++i) {
      MPI_Test(&r, &flag, MPI_STATUS_IGNORE);
      if (flag) break;
    }
    CHECK(!flag);
    MPI_Send(&go, 1, MPI_INT, 1, 6, MPI_COMM_WORLD);
    MPI_Wait(&r, MPI_STATUS_IGNORE);
  } else {
    int got = 0;
    MPI_Recv(&go, 1, MPI_INT, 0, 6, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    MPI_Recv(&got, 1, MPI_INT, 0, 5, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    CHECK(got == 42);
  }
}

/* Messages never cross communicators: a wildcard receive on MPI_COMM_WORLD does not take what was
 * sent on its duplicate; split and compare as the standard defines them. */
static void communicators(void) {
  MPI_Comm dup, half;
  int on_dup = 1, on_world = 2, got = 0, result = -1, half_size = 0;
  MPI_Comm_dup(MPI_COMM_WORLD, &dup);
  MPI_Comm_compare(MPI_COMM_WORLD, dup, &result);
  CHECK(result == MPI_CONGRUENT);
  MPI_Request r[2];
  MPI_Isend(&on_dup, 1, MPI_INT, rank, 0, dup, &r[0]);
  MPI_Isend(&on_world, 1, MPI_INT, rank, 0, MPI_COMM_WORLD, &r[1]);
  MPI_Recv(&got, 1, MPI_INT, MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  CHECK(got == 2);
  MPI_Recv(&got, 1, MPI_INT, MPI_ANY_SOURCE, MPI_ANY_TAG, dup, MPI_STATUS_IGNORE);
  CHECK(got == 1);
  MPI_Waitall(2, r, MPI_STATUSES_IGNORE);
  MPI_Comm_split(MPI_COMM_WORLD, rank % 2, rank, &half);
  MPI_Comm_size(half, &half_size);
  CHECK(half_size == (size + 1 - rank % 2) / 2);
  MPI_Comm_compare(MPI_COMM_WORLD, half, &result);
  CHECK(result == (size == 1 ? MPI_CONGRUENT : MPI_UNEQUAL));
  MPI_Comm_free(&half);
  MPI_Comm_free(&dup);
  CHECK(dup == MPI_COMM_NULL);
}

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  self_and_null();
  zero_counts_and_tag_ub();
  truncation();
  wildcards_and_order();
  tag_selection_and_probe();
  synchronous_send();
  communicators();
  MPI_Barrier(MPI_COMM_WORLD);
  printf("rank %d: %d checks, %d failed\n", rank, checks, failures);
  MPI_Finalize();
  return failures == 0 ? 0 : 1;
}
