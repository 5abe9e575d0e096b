/* Persistent requests, MPI_Request_free and MPI_Cancel as MPI 3.1 sections 3.7.3, 3.8.4 and 3.9
 * state them, checked by the program itself on any number of ranks: a persistent ring over many
 * iterations (standard sends below the eager size, synchronous ones above it), MPI_Startall,
 * inactive requests completing at once with an empty status and skipped by MPI_Testany, buffered
 * and ready persistent sends, cancel of an unmatched receive (persistent too, started again after),
 * cancel of a matched one (which completes as usual), cancel of an unmatched synchronous send
 * (either cancelled, and never received, or completed, and received: never both), and
 * MPI_Request_free of an active send whose message still arrives. Prints one line per rank; exits
 * 1 if a check failed. The same source runs under Open MPI (tests/mpi_run/CMakeLists.txt). */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

#include "conformance_check.h"

static int rank, size, right, left;
enum { ITERATIONS = 60, BIG = 6000 };

static void persistent_ring(void) {
  static double big_out[BIG], big_in[BIG];
  int out = 0, in = -1;
  MPI_Request rs[4];
  MPI_Send_init(&out, 1, MPI_INT, right, 1, MPI_COMM_WORLD, &rs[0]);
  MPI_Recv_init(&in, 1, MPI_INT, left, 1, MPI_COMM_WORLD, &rs[1]);
  MPI_Ssend_init(big_out, BIG, MPI_DOUBLE, right, 2, MPI_COMM_WORLD, &rs[2]);
  MPI_Recv_init(big_in, BIG, MPI_DOUBLE, left, 2, MPI_COMM_WORLD, &rs[3]);
  int ring_ok = 1, big_ok = 1, kept = 1;
  for (int it = 0; it < ITERATIONS; ++it) {
    out = 1000 * rank + it; /* the start reads the buffer as it is now */
    for (int i = 0; i < BIG; i += 997) big_out[i] = rank + 0.5 * it;
    if (it % 2 == 0) {
      MPI_Startall(4, rs);
    } else {
      for (int i = 3; i >= 0; --i) MPI_Start(&rs[i]);
    }
    MPI_Waitall(4, rs, MPI_STATUSES_IGNORE);
    for (int i = 0; i < 4; ++i) kept &= rs[i] != MPI_REQUEST_NULL;
    ring_ok &= in == 1000 * left + it;
    for (int i = 0; i < BIG; i += 997) big_ok &= big_in[i] == left + 0.5 * it;
  }
  CHECK(ring_ok);
  CHECK(big_ok);
  CHECK(kept); /* a finished persistent request stays, inactive */
  /* Inactive: a wait returns at once with an empty status; Testany skips them all. */
  MPI_Status st;
  int count = -1, flag = 0, index = 0;
  CHECK(MPI_Wait(&rs[1], &st) == MPI_SUCCESS);
  MPI_Get_count(&st, MPI_INT, &count);
  CHECK(st.MPI_SOURCE == MPI_ANY_SOURCE && st.MPI_TAG == MPI_ANY_TAG && count == 0 && rs[1] != MPI_REQUEST_NULL);
  MPI_Testany(4, rs, &index, &flag, MPI_STATUS_IGNORE);
  CHECK(flag == 1 && index == MPI_UNDEFINED);
  for (int i = 0; i < 4; ++i) MPI_Request_free(&rs[i]);
  CHECK(rs[0] == MPI_REQUEST_NULL && rs[3] == MPI_REQUEST_NULL);
}

/* MPI_Bsend_init through an attached buffer, MPI_Rsend_init to a receive posted before. */
static void buffered_and_ready(void) {
  int size_needed = 0, out = 7 + rank, in = -1;
  MPI_Pack_size(1, MPI_INT, MPI_COMM_WORLD, &size_needed);
  const int bytes = size_needed + MPI_BSEND_OVERHEAD;
  char* buffer = malloc((size_t)bytes);
  MPI_Buffer_attach(buffer, bytes);
  MPI_Request s, r;
  MPI_Bsend_init(&out, 1, MPI_INT, right, 3, MPI_COMM_WORLD, &s);
  MPI_Irecv(&in, 1, MPI_INT, left, 3, MPI_COMM_WORLD, &r);
  MPI_Start(&s);
  MPI_Wait(&s, MPI_STATUS_IGNORE);
  MPI_Wait(&r, MPI_STATUS_IGNORE);
  CHECK(in == 7 + left);
  MPI_Request_free(&s);
  void* detached = NULL;
  int detached_size = 0;
  MPI_Buffer_detach(&detached, &detached_size);
  free(buffer);
  in = -1;
  MPI_Irecv(&in, 1, MPI_INT, left, 4, MPI_COMM_WORLD, &r);
  MPI_Barrier(MPI_COMM_WORLD); /* every ready send's receive is posted */
  MPI_Rsend_init(&out, 1, MPI_INT, right, 4, MPI_COMM_WORLD, &s);
  MPI_Start(&s);
  MPI_Wait(&s, MPI_STATUS_IGNORE);
  MPI_Wait(&r, MPI_STATUS_IGNORE);
  CHECK(in == 7 + left);
  MPI_Request_free(&s);
}

static void cancel_receives(void) {
  int buf = 0, cancelled = 0;
  MPI_Status st;
  MPI_Request r;
  MPI_Irecv(&buf, 1, MPI_INT, MPI_ANY_SOURCE, 999, MPI_COMM_WORLD, &r); /* never sent */
  MPI_Cancel(&r);
  MPI_Wait(&r, &st);
  MPI_Test_cancelled(&st, &cancelled);
  CHECK(cancelled && r == MPI_REQUEST_NULL);
  /* A persistent receive cancelled, then started again and matched. */
  MPI_Recv_init(&buf, 1, MPI_INT, left, 5, MPI_COMM_WORLD, &r);
  MPI_Start(&r);
  MPI_Cancel(&r);
  MPI_Wait(&r, &st);
  MPI_Test_cancelled(&st, &cancelled);
  CHECK(cancelled && r != MPI_REQUEST_NULL);
  int out = 50 + rank;
  MPI_Start(&r);
  MPI_Barrier(MPI_COMM_WORLD); /* no tag-5 message is sent before every rank's cancel */
  MPI_Send(&out, 1, MPI_INT, right, 5, MPI_COMM_WORLD);
  MPI_Wait(&r, &st);
  MPI_Test_cancelled(&st, &cancelled);
  CHECK(!cancelled && buf == 50 + left);
  MPI_Request_free(&r);
}

/* A receive matched before the cancel completes as usual: its message (sent before the tag-7 one
 * it is known to precede) has arrived and matched by the time MPI_Recv of tag 7 returns. */
static void cancel_matched_receive(void) {
  static int big_out[BIG], big_in[BIG];
  for (int i = 0; i < BIG; ++i) big_out[i] = rank * 3 + i;
  int token = 0, cancelled = 1;
  MPI_Request r, s;
  MPI_Status st;
  MPI_Irecv(big_in, BIG, MPI_INT, left, 6, MPI_COMM_WORLD, &r);
  MPI_Isend(big_out, BIG, MPI_INT, right, 6, MPI_COMM_WORLD, &s);
  MPI_Send(&token, 1, MPI_INT, right, 7, MPI_COMM_WORLD);
  MPI_Recv(&token, 1, MPI_INT, left, 7, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  MPI_Cancel(&r);
  MPI_Wait(&r, &st);
  MPI_Wait(&s, MPI_STATUS_IGNORE);
  MPI_Test_cancelled(&st, &cancelled);
  CHECK(!cancelled && big_in[0] == left * 3 && big_in[BIG - 1] == left * 3 + BIG - 1 && st.MPI_SOURCE == left);
}

/* An unmatched synchronous send, cancelled: either the cancel succeeds and the message is never
 * received, or the send completes and the receiver takes it; the sender says which it saw. */
static void cancel_unmatched_send(void) {
  int out = 77, in = 0, cancelled = 0, arrived = 0, sender_cancelled = -1, token = 0;
  MPI_Request s;
  MPI_Status st;
  MPI_Issend(&out, 1, MPI_INT, right, 8, MPI_COMM_WORLD, &s);
  MPI_Cancel(&s);
  MPI_Send(&token, 1, MPI_INT, right, 9, MPI_COMM_WORLD);
  MPI_Recv(&token, 1, MPI_INT, left, 9, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  MPI_Iprobe(left, 8, MPI_COMM_WORLD, &arrived, MPI_STATUS_IGNORE);
  if (arrived) MPI_Recv(&in, 1, MPI_INT, left, 8, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  MPI_Wait(&s, &st);
  MPI_Test_cancelled(&st, &cancelled);
  MPI_Sendrecv(&cancelled, 1, MPI_INT, right, 10, &sender_cancelled, 1, MPI_INT, left, 10, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  CHECK(sender_cancelled == !arrived && (!arrived || in == 77));
  if (rank == 0) fprintf(stderr, "rank 0: unmatched synchronous send cancelled: %s\n", cancelled ? "yes" : "no");
}

/* A freed active send runs on: its message arrives whole; the receiver's answer says the buffer
 * may be reused. */
static void free_active_send(void) {
  static int big_out[BIG], big_in[BIG];
  for (int i = 0; i < BIG; ++i) big_out[i] = i ^ rank;
  MPI_Request s;
  MPI_Isend(big_out, BIG, MPI_INT, right, 11, MPI_COMM_WORLD, &s);
  MPI_Request_free(&s);
  CHECK(s == MPI_REQUEST_NULL);
  MPI_Recv(big_in, BIG, MPI_INT, left, 11, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  int whole = 1;
  for (int i = 0; i < BIG; ++i) whole &= big_in[i] == (i ^ left);
  CHECK(whole);
  MPI_Barrier(MPI_COMM_WORLD);
}

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  right = (rank + 1) % size;
  left = (rank + size - 1) % size;
  persistent_ring();
  buffered_and_ready();
  cancel_receives();
  cancel_matched_receive();
  cancel_unmatched_send();
  free_active_send();
  printf("rank %d: %d checks, %d failed\n", rank, checks, failures);
  MPI_Finalize();
  return failures == 0 ? 0 : 1;
}
