/* The collectives as MPI 3.1 chapter 5 states them, checked by the program itself on any number
 * of ranks: every root, zero counts, MPI_IN_PLACE where the standard allows it, a
 * non-commutative user op (string concatenation as hashes: associative, not commutative), a
 * derived datatype with holes (the holes must stay untouched), a sub-communicator, the
 * non-blocking forms, and the error classes of bad arguments. Each rank's expected values are
 * computed from the standard's definition of the result. Prints one line per rank; exits 1 if a
 * check failed. Run with any --coll choice, the results must be the same. */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int rank, size;
#include "conformance_check.h"

enum { N = 5, HOLE = -7 };
static int value(int r, int i) { return 1000 * r + i; }

/* A string as (B^length, hash) mod P: concat(a, b) = (a.p * b.p, a.h * b.p + b.h). */
typedef struct { long long p, h; } Str;
enum { B = 31, P = 1000003 };
static MPI_Datatype str_type;
static MPI_Op concat_op;
static Str str_of(int r) { Str s = {B, r + 1}; return s; }
static Str concat(Str a, Str b) {
  Str c = {(a.p * b.p) % P, (a.h * b.p + b.h) % P};
  return c;
}
static void concat_fn(void* in, void* inout, int* len, MPI_Datatype* type) {
  (void)type;
  Str* a = in;
  Str* b = inout;
  for (int i = 0; i < *len; ++i) b[i] = concat(a[i], b[i]);
}
static Str concat_range(int from, int to) { /* ranks from..to inclusive */
  Str s = str_of(from);
  for (int r = from + 1; r <= to; ++r) s = concat(s, str_of(r));
  return s;
}
static int same_str(Str a, Str b) { return a.p == b.p && a.h == b.h; }

static void bcast_every_root(MPI_Datatype holes) {
  for (int root = 0; root < size; ++root) {
    int buf[N], zero = 42;
    for (int i = 0; i < N; ++i) buf[i] = rank == root ? value(root, i) : -1;
    CHECK(MPI_Bcast(buf, N, MPI_INT, root, MPI_COMM_WORLD) == MPI_SUCCESS);
    for (int i = 0; i < N; ++i) CHECK(buf[i] == value(root, i));
    MPI_Bcast(&zero, 0, MPI_INT, root, MPI_COMM_WORLD);
    CHECK(zero == 42);
    int strided[6];
    for (int i = 0; i < 6; ++i) strided[i] = rank == root ? (i % 2 ? HOLE : value(root, i)) : HOLE;
    MPI_Bcast(strided, 1, holes, root, MPI_COMM_WORLD); /* 3 ints at stride 2 */
    for (int i = 0; i < 6; ++i) CHECK(strided[i] == (i % 2 ? HOLE : value(root, i)));
  }
}

static void reduce_every_root(void) {
  long long sum_r = 0;
  for (int r = 0; r < size; ++r) sum_r += r;
  for (int root = 0; root < size; ++root) {
    int mine[N], out[N];
    for (int i = 0; i < N; ++i) mine[i] = value(rank, i), out[i] = -1;
    MPI_Reduce(mine, out, N, MPI_INT, MPI_SUM, root, MPI_COMM_WORLD);
    if (rank == root) {
      for (int i = 0; i < N; ++i) CHECK(out[i] == 1000 * sum_r + size * i);
    }
    double d = rank + 0.5, dmax = 0;
    MPI_Reduce(&d, &dmax, 1, MPI_DOUBLE, MPI_MAX, root, MPI_COMM_WORLD);
    if (rank == root) CHECK(dmax == size - 0.5);
    int in_place[N];
    for (int i = 0; i < N; ++i) in_place[i] = value(rank, i);
    MPI_Reduce(rank == root ? MPI_IN_PLACE : in_place, in_place, N, MPI_INT, MPI_SUM, root, MPI_COMM_WORLD);
    if (rank == root) CHECK(in_place[N - 1] == 1000 * sum_r + size * (N - 1));
    Str s = str_of(rank), result = {0, 0};
    MPI_Reduce(&s, &result, 1, str_type, concat_op, root, MPI_COMM_WORLD);
    if (rank == root) CHECK(same_str(result, concat_range(0, size - 1)));
    struct { double v; int i; } loc = {(rank * 7) % size, rank}, best = {0, -1};
    MPI_Reduce(&loc, &best, 1, MPI_DOUBLE_INT, MPI_MINLOC, root, MPI_COMM_WORLD);
    if (rank == root) CHECK(best.v == 0 && best.i == 0);
  }
}

static void allreduce_forms(void) {
  int mine[N], out[N], prod = rank % 3 + 1, expected_prod = 1;
  for (int i = 0; i < N; ++i) mine[i] = value(rank, i);
  MPI_Allreduce(mine, out, N, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  for (int i = 0; i < N; ++i) CHECK(out[i] == 1000 * (size * (size - 1) / 2) + size * i);
  MPI_Allreduce(MPI_IN_PLACE, mine, N, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  for (int i = 0; i < N; ++i) CHECK(mine[i] == i);
  for (int r = 0; r < size; ++r) expected_prod *= r % 3 + 1;
  MPI_Allreduce(MPI_IN_PLACE, &prod, 1, MPI_INT, MPI_PROD, MPI_COMM_WORLD);
  CHECK(prod == expected_prod);
  int bits = 1 << rank, all_bits = 0, untouched = 9;
  MPI_Allreduce(&bits, &all_bits, 1, MPI_INT, MPI_BOR, MPI_COMM_WORLD);
  CHECK(all_bits == (1 << size) - 1);
  MPI_Allreduce(&bits, &untouched, 0, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  CHECK(untouched == 9);
  Str many[N], result[N];
  for (int i = 0; i < N; ++i) many[i] = str_of(rank);
  MPI_Allreduce(many, result, N, str_type, concat_op, MPI_COMM_WORLD);
  for (int i = 0; i < N; ++i) CHECK(same_str(result[i], concat_range(0, size - 1)));
}

/* Rank r contributes r % 3 elements to the v-forms (zero counts included). */
static int vcount(int r) { return r % 3; }

static void gather_scatter_every_root(void) {
  int* all = malloc(sizeof(int) * (size_t)(size * N + 1));
  int counts[64], displs[64], mine[N];
  for (int r = 0, at = 0; r < size; ++r) counts[r] = vcount(r), displs[r] = at, at += vcount(r) + 1; /* gaps */
  for (int root = 0; root < size; ++root) {
    for (int i = 0; i < N; ++i) mine[i] = value(rank, i);
    for (int i = 0; i < size * N; ++i) all[i] = rank == root && i / N == root ? value(root, i % N) : -1;
    MPI_Gather(rank == root ? MPI_IN_PLACE : mine, N, MPI_INT, all, N, MPI_INT, root, MPI_COMM_WORLD);
    if (rank == root) {
      for (int i = 0; i < size * N; ++i) CHECK(all[i] == value(i / N, i % N));
    }
    for (int i = 0; i < size * N; ++i) all[i] = HOLE;
    MPI_Gatherv(mine, vcount(rank), MPI_INT, all, counts, displs, MPI_INT, root, MPI_COMM_WORLD);
    if (rank == root) {
      for (int r = 0; r < size; ++r) {
        for (int i = 0; i < vcount(r); ++i) CHECK(all[displs[r] + i] == value(r, i));
        CHECK(all[displs[r] + vcount(r)] == HOLE);
      }
    }
    for (int i = 0; i < size * N; ++i) all[i] = rank == root ? value(i / N, i % N) : -1;
    for (int i = 0; i < N; ++i) mine[i] = -1;
    MPI_Scatter(all, N, MPI_INT, mine, N, MPI_INT, root, MPI_COMM_WORLD);
    for (int i = 0; i < N; ++i) CHECK(mine[i] == value(rank, i));
    MPI_Scatter(all, N, MPI_INT, rank == root ? MPI_IN_PLACE : mine, N, MPI_INT, root, MPI_COMM_WORLD);
    if (rank == root) CHECK(all[root * N] == value(root, 0));
    for (int i = 0; i < size * N; ++i) all[i] = -1;
    if (rank == root) {
      for (int r = 0; r < size; ++r) {
        for (int i = 0; i < vcount(r); ++i) all[displs[r] + i] = value(r, i);
      }
    }
    for (int i = 0; i < N; ++i) mine[i] = HOLE;
    MPI_Scatterv(all, counts, displs, MPI_INT, mine, vcount(rank), MPI_INT, root, MPI_COMM_WORLD);
    for (int i = 0; i < vcount(rank); ++i) CHECK(mine[i] == value(rank, i));
    CHECK(mine[vcount(rank)] == HOLE);
  }
  free(all);
}

static void allgather_forms(MPI_Datatype holes) {
  int* all = malloc(sizeof(int) * (size_t)(size * 6));
  int counts[64], displs[64], mine[N];
  for (int i = 0; i < N; ++i) mine[i] = value(rank, i);
  MPI_Allgather(mine, N, MPI_INT, all, N, MPI_INT, MPI_COMM_WORLD);
  for (int i = 0; i < size * N; ++i) CHECK(all[i] == value(i / N, i % N));
  for (int i = 0; i < size * N; ++i) all[i] = i / N == rank ? value(rank, i % N) : -1;
  MPI_Allgather(MPI_IN_PLACE, 0, MPI_DATATYPE_NULL, all, N, MPI_INT, MPI_COMM_WORLD);
  for (int i = 0; i < size * N; ++i) CHECK(all[i] == value(i / N, i % N));
  /* Received as one element of the holed type per rank (3 ints at stride 2, extent 5 ints). */
  for (int i = 0; i < size * 6; ++i) all[i] = HOLE;
  MPI_Allgather(mine, 3, MPI_INT, all, 1, holes, MPI_COMM_WORLD);
  for (int r = 0; r < size; ++r) {
    for (int k = 0; k < 3; ++k) CHECK(all[5 * r + 2 * k] == value(r, k));
    CHECK(all[5 * r + 1] == HOLE && all[5 * r + 3] == HOLE);
  }
  for (int r = 0, at = 0; r < size; ++r) counts[r] = vcount(r), displs[r] = at, at += vcount(r) + 1;
  for (int i = 0; i < size * N; ++i) all[i] = HOLE;
  MPI_Allgatherv(mine, vcount(rank), MPI_INT, all, counts, displs, MPI_INT, MPI_COMM_WORLD);
  for (int r = 0; r < size; ++r) {
    for (int i = 0; i < vcount(r); ++i) CHECK(all[displs[r] + i] == value(r, i));
    CHECK(all[displs[r] + vcount(r)] == HOLE);
  }
  free(all);
}

static void alltoall_forms(void) {
  int* out = malloc(sizeof(int) * (size_t)(size * 4));
  int* in = malloc(sizeof(int) * (size_t)(size * 4));
  int sc[64], sd[64], rc[64], rd[64];
  for (int i = 0; i < size * 2; ++i) out[i] = value(rank, i); /* block i/2 goes to rank i/2 */
  MPI_Alltoall(out, 2, MPI_INT, in, 2, MPI_INT, MPI_COMM_WORLD);
  for (int i = 0; i < size * 2; ++i) CHECK(in[i] == value(i / 2, rank * 2 + i % 2));
  MPI_Alltoall(MPI_IN_PLACE, 0, MPI_DATATYPE_NULL, out, 2, MPI_INT, MPI_COMM_WORLD);
  for (int i = 0; i < size * 2; ++i) CHECK(out[i] == value(i / 2, rank * 2 + i % 2));
  /* v: rank r sends (r + d) % 3 ints to rank d, from value(r, 10 d). */
  for (int d = 0, at = 0; d < size; ++d) sc[d] = (rank + d) % 3, sd[d] = at, at += 3;
  for (int s = 0, at = 0; s < size; ++s) rc[s] = (s + rank) % 3, rd[s] = at, at += 4;
  for (int d = 0; d < size; ++d) {
    for (int i = 0; i < 3; ++i) out[sd[d] + i] = value(rank, 10 * d + i);
  }
  for (int i = 0; i < size * 4; ++i) in[i] = HOLE;
  MPI_Alltoallv(out, sc, sd, MPI_INT, in, rc, rd, MPI_INT, MPI_COMM_WORLD);
  for (int s = 0; s < size; ++s) {
    for (int i = 0; i < rc[s]; ++i) CHECK(in[rd[s] + i] == value(s, 10 * rank + i));
    CHECK(in[rd[s] + rc[s]] == HOLE);
  }
  /* w: the same exchange with byte displacements and a datatype per peer. */
  MPI_Datatype types[64];
  for (int p = 0; p < size; ++p) types[p] = MPI_INT, sd[p] *= (int)sizeof(int), rd[p] *= (int)sizeof(int);
  for (int i = 0; i < size * 4; ++i) in[i] = HOLE;
  MPI_Alltoallw(out, sc, sd, types, in, rc, rd, types, MPI_COMM_WORLD);
  for (int s = 0; s < size; ++s) {
    for (int i = 0; i < rc[s]; ++i) CHECK(in[rd[s] / (int)sizeof(int) + i] == value(s, 10 * rank + i));
  }
  free(out);
  free(in);
}

static void reduce_scatter_forms(void) {
  int* vec = malloc(sizeof(int) * (size_t)(size * 3));
  int counts[64], mine[3], total = 0, before = 0;
  for (int r = 0; r < size; ++r) counts[r] = vcount(r), before += r < rank ? vcount(r) : 0, total += vcount(r);
  for (int i = 0; i < total; ++i) vec[i] = rank + i;
  MPI_Reduce_scatter(vec, mine, counts, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  for (int i = 0; i < vcount(rank); ++i) CHECK(mine[i] == size * (size - 1) / 2 + size * (before + i));
  for (int i = 0; i < size * 2; ++i) vec[i] = rank + i;
  MPI_Reduce_scatter_block(MPI_IN_PLACE, vec, 2, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  for (int i = 0; i < 2; ++i) CHECK(vec[i] == size * (size - 1) / 2 + size * (2 * rank + i));
  Str* strs = malloc(sizeof(Str) * (size_t)size);
  Str got = {0, 0};
  for (int i = 0; i < size; ++i) strs[i] = str_of(rank);
  MPI_Reduce_scatter_block(strs, &got, 1, str_type, concat_op, MPI_COMM_WORLD);
  CHECK(same_str(got, concat_range(0, size - 1)));
  free(strs);
  free(vec);
}

static void scans(void) {
  int v = rank + 1, inclusive = 0, exclusive = -5;
  MPI_Scan(&v, &inclusive, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  CHECK(inclusive == (rank + 1) * (rank + 2) / 2);
  MPI_Exscan(&v, &exclusive, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  if (rank > 0) CHECK(exclusive == rank * (rank + 1) / 2);
  int in_place = rank + 1;
  MPI_Scan(MPI_IN_PLACE, &in_place, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  CHECK(in_place == rank + 1);
  Str s = str_of(rank), prefix = {0, 0}, before = {0, 0};
  MPI_Scan(&s, &prefix, 1, str_type, concat_op, MPI_COMM_WORLD);
  CHECK(same_str(prefix, concat_range(0, rank)));
  MPI_Exscan(&s, &before, 1, str_type, concat_op, MPI_COMM_WORLD);
  if (rank > 0) CHECK(same_str(before, concat_range(0, rank - 1)));
}

/* Collectives on the even and the odd ranks at once: each communicator numbers its own calls. */
static void sub_communicator(void) {
  MPI_Comm half;
  MPI_Comm_split(MPI_COMM_WORLD, rank % 2, rank, &half);
  int n = 0, sum = 0, hr = 0;
  MPI_Comm_size(half, &n);
  MPI_Comm_rank(half, &hr);
  MPI_Allreduce(&rank, &sum, 1, MPI_INT, MPI_SUM, half);
  int expected = 0;
  for (int r = rank % 2; r < size; r += 2) expected += r;
  CHECK(sum == expected && hr == rank / 2);
  int b = rank;
  MPI_Bcast(&b, 1, MPI_INT, n - 1, half);
  CHECK(b == rank % 2 + 2 * (n - 1));
  MPI_Comm_free(&half);
}

static void nonblocking(void) {
  MPI_Request req[4];
  int b = rank == 0 ? 77 : 0, s = 0, all[64], one = rank;
  MPI_Ibarrier(MPI_COMM_WORLD, &req[0]);
  MPI_Ibcast(&b, 1, MPI_INT, 0, MPI_COMM_WORLD, &req[1]);
  MPI_Iallreduce(&one, &s, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD, &req[2]);
  MPI_Iallgather(&one, 1, MPI_INT, all, 1, MPI_INT, MPI_COMM_WORLD, &req[3]);
  CHECK(MPI_Waitall(4, req, MPI_STATUSES_IGNORE) == MPI_SUCCESS);
  CHECK(b == 77 && s == size * (size - 1) / 2);
  for (int r = 0; r < size; ++r) CHECK(all[r] == r);
  /* Valid only because a non-blocking collective does not block its start: rank 1 enters the
   * barrier after rank 0's synchronous send, which rank 0 makes after entering it. */
  int token = rank == 0 ? 5 : 0;
  if (rank == 1) MPI_Recv(&token, 1, MPI_INT, 0, 99, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  MPI_Ibarrier(MPI_COMM_WORLD, &req[0]);
  if (rank == 0 && size > 1) MPI_Ssend(&token, 1, MPI_INT, 1, 99, MPI_COMM_WORLD);
  MPI_Wait(&req[0], MPI_STATUS_IGNORE);
  CHECK(rank > 1 || token == 5);
}

static int error_class(int code) {
  int c = -1;
  MPI_Error_class(code, &c);
  return c;
}

static void errors(void) {
  int x = 0, y = 0;
  CHECK(error_class(MPI_Bcast(&x, 1, MPI_INT, size, MPI_COMM_WORLD)) == MPI_ERR_ROOT);
  CHECK(error_class(MPI_Bcast(&x, -1, MPI_INT, 0, MPI_COMM_WORLD)) == MPI_ERR_COUNT);
  CHECK(error_class(MPI_Bcast(&x, 1, MPI_DATATYPE_NULL, 0, MPI_COMM_WORLD)) == MPI_ERR_TYPE);
  CHECK(error_class(MPI_Allreduce(&x, &y, 1, MPI_INT, MPI_OP_NULL, MPI_COMM_WORLD)) == MPI_ERR_OP);
  CHECK(error_class(MPI_Reduce(&x, &y, 1, MPI_INT, MPI_SUM, -1, MPI_COMM_WORLD)) == MPI_ERR_ROOT);
  CHECK(error_class(MPI_Gather(&x, 1, MPI_INT, &y, 1, MPI_INT, size + 3, MPI_COMM_WORLD)) == MPI_ERR_ROOT);
  CHECK(error_class(MPI_Barrier(MPI_COMM_NULL)) == MPI_ERR_COMM);
  /* A refused call takes no sequence number: the next collective still matches everywhere. */
  x = rank == 0 ? 5 : 0;
  CHECK(MPI_Bcast(&x, 1, MPI_INT, 0, MPI_COMM_WORLD) == MPI_SUCCESS && x == 5);
}

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  if (size > 64) MPI_Abort(MPI_COMM_WORLD, 2);
  MPI_Type_contiguous(2, MPI_LONG_LONG, &str_type);
  MPI_Type_commit(&str_type);
  MPI_Op_create(concat_fn, 0, &concat_op);
  MPI_Datatype holes;
  MPI_Type_vector(3, 1, 2, MPI_INT, &holes);
  MPI_Type_commit(&holes);
  CHECK(MPI_Barrier(MPI_COMM_WORLD) == MPI_SUCCESS);
  bcast_every_root(holes);
  reduce_every_root();
  allreduce_forms();
  gather_scatter_every_root();
  allgather_forms(holes);
  alltoall_forms();
  reduce_scatter_forms();
  scans();
  sub_communicator();
  nonblocking();
  errors();
  MPI_Op_free(&concat_op);
  MPI_Type_free(&str_type);
  MPI_Type_free(&holes);
  printf("rank %d: %d checks, %d failed\n", rank, checks, failures);
  MPI_Finalize();
  return failures ? 1 : 0;
}
