/* Attributes, topologies and MPI_Comm_split_type as MPI 3.1 sections 6.4.2, 6.7 and 7.5 state
 * them, checked by the program itself on any number of ranks: copy callbacks run by MPI_Comm_dup
 * (the predefined null and duplicating ones, a user one that declines), delete callbacks run on
 * replace, delete and free, a freed key still serving its attributes, MPI-1's names, the
 * predefined attributes and MPI_COMM_SELF's attribute deleted at MPI_Finalize; MPI_Cart_sub's row
 * and column communicators, MPI_Cart_map; graph neighbours of a ring and a star, ranks left out of
 * a smaller graph, MPI_Graph_map; MPI_Comm_split_type's ranks sharing a node. Prints one line per
 * rank (and one more from MPI_Finalize); exits 1 if a check failed. The same source runs under
 * Open MPI (tests/mpi_run/CMakeLists.txt). */
#include <mpi.h>
#include <stdio.h>
#include <string.h>

#include "conformance_check.h"

static int rank, size;

struct Counts {
  int copies, deletes;
};

static int counting_copy(MPI_Comm comm, int keyval, void* extra, void* in, void* out, int* flag) {
  (void)comm, (void)keyval;
  ++((struct Counts*)extra)->copies;
  *(void**)out = (int*)in + 1; /* the copy's value: the next element */
  *flag = 1;
  return MPI_SUCCESS;
}
static int declining_copy(MPI_Comm comm, int keyval, void* extra, void* in, void* out, int* flag) {
  (void)comm, (void)keyval, (void)in, (void)out;
  ++((struct Counts*)extra)->copies;
  *flag = 0;
  return MPI_SUCCESS;
}
static int counting_delete(MPI_Comm comm, int keyval, void* value, void* extra) {
  (void)comm, (void)keyval, (void)value;
  ++((struct Counts*)extra)->deletes;
  return MPI_SUCCESS;
}
static int finalize_delete(MPI_Comm comm, int keyval, void* value, void* extra) {
  (void)keyval, (void)value, (void)extra;
  if (comm == MPI_COMM_SELF) printf("rank %d: MPI_COMM_SELF's attribute deleted at MPI_Finalize\n", rank);
  return MPI_SUCCESS;
}

static void attribute_callbacks(void) {
  static int values[4] = {10, 11, 12, 13};
  struct Counts counted = {0, 0}, declined = {0, 0};
  int key = MPI_KEYVAL_INVALID, no_copy = MPI_KEYVAL_INVALID, dup_key = MPI_KEYVAL_INVALID, decline = MPI_KEYVAL_INVALID;
  MPI_Comm_create_keyval(counting_copy, counting_delete, &key, &counted);
  MPI_Comm_create_keyval(MPI_COMM_NULL_COPY_FN, MPI_COMM_NULL_DELETE_FN, &no_copy, NULL);
  MPI_Comm_create_keyval(MPI_COMM_DUP_FN, MPI_COMM_NULL_DELETE_FN, &dup_key, NULL);
  MPI_Comm_create_keyval(declining_copy, counting_delete, &decline, &declined);
  MPI_Comm a, b;
  MPI_Comm_dup(MPI_COMM_WORLD, &a);
  MPI_Comm_set_attr(a, key, &values[0]);
  MPI_Comm_set_attr(a, key, &values[1]); /* replaces: the old value's delete callback runs */
  CHECK(counted.deletes == 1);
  MPI_Comm_set_attr(a, no_copy, &values[2]);
  MPI_Comm_set_attr(a, dup_key, &values[3]);
  MPI_Comm_set_attr(a, decline, &values[0]);
  MPI_Comm_dup(a, &b);
  CHECK(counted.copies == 1 && declined.copies == 1);
  int* got = NULL;
  int flag = 0;
  MPI_Comm_get_attr(b, key, &got, &flag);
  CHECK(flag && got == &values[2]);
  MPI_Comm_get_attr(b, no_copy, &got, &flag);
  CHECK(!flag);
  MPI_Comm_get_attr(b, decline, &got, &flag);
  CHECK(!flag);
  MPI_Comm_get_attr(b, dup_key, &got, &flag);
  CHECK(flag && got == &values[3]);
  MPI_Comm_delete_attr(a, key);
  CHECK(counted.deletes == 2);
  MPI_Comm_get_attr(a, key, &got, &flag);
  CHECK(!flag);
  MPI_Comm_free_keyval(&key); /* b's attribute keeps the key: its delete callback still runs */
  CHECK(key == MPI_KEYVAL_INVALID);
  MPI_Comm_free(&b);
  CHECK(counted.deletes == 3 && declined.deletes == 0);
  MPI_Comm_free(&a);
  CHECK(declined.deletes == 1 && a == MPI_COMM_NULL);
  MPI_Comm_free_keyval(&no_copy);
  MPI_Comm_free_keyval(&dup_key);
  MPI_Comm_free_keyval(&decline);
}

static void mpi1_attributes_and_predefined(void) {
  static int value = 42;
  int key = MPI_KEYVAL_INVALID, flag = 0;
  int* got = NULL;
  MPI_Comm c;
  MPI_Keyval_create(MPI_DUP_FN, MPI_NULL_DELETE_FN, &key, NULL);
  MPI_Attr_put(MPI_COMM_WORLD, key, &value);
  MPI_Comm_dup(MPI_COMM_WORLD, &c);
  MPI_Attr_get(c, key, &got, &flag);
  CHECK(flag && *got == 42);
  MPI_Attr_delete(c, key);
  MPI_Attr_get(c, key, &got, &flag);
  CHECK(!flag);
  MPI_Comm_free(&c);
  MPI_Attr_delete(MPI_COMM_WORLD, key);
  MPI_Keyval_free(&key);
  CHECK(key == MPI_KEYVAL_INVALID);
  MPI_Comm_get_attr(MPI_COMM_WORLD, MPI_TAG_UB, &got, &flag);
  CHECK(flag && *got >= 32767);
  MPI_Comm_get_attr(MPI_COMM_WORLD, MPI_HOST, &got, &flag);
  CHECK(flag && (*got == MPI_PROC_NULL || (*got >= 0 && *got < size)));
  MPI_Comm_get_attr(MPI_COMM_WORLD, MPI_IO, &got, &flag);
  CHECK(flag && (*got == MPI_ANY_SOURCE || *got == MPI_PROC_NULL || (*got >= 0 && *got < size)));
  MPI_Comm_get_attr(MPI_COMM_WORLD, MPI_WTIME_IS_GLOBAL, &got, &flag);
  CHECK(!flag || *got == 0 || *got == 1);
  int self_key = MPI_KEYVAL_INVALID;
  MPI_Comm_create_keyval(MPI_COMM_NULL_COPY_FN, finalize_delete, &self_key, NULL);
  MPI_Comm_set_attr(MPI_COMM_SELF, self_key, &value);
}

/* The grid dims[0] x dims[1]; a row keeps dimension 1, a column dimension 0. */
static void cart_sub(void) {
  int dims[2] = {0, 0}, periods[2] = {1, 0}, coords[2];
  MPI_Dims_create(size, 2, dims);
  MPI_Comm grid, row, column, point;
  MPI_Cart_create(MPI_COMM_WORLD, 2, dims, periods, 0, &grid);
  MPI_Cart_coords(grid, rank, 2, coords);
  const int keep_row[2] = {0, 1}, keep_column[2] = {1, 0}, keep_none[2] = {0, 0};
  MPI_Cart_sub(grid, keep_row, &row);
  MPI_Cart_sub(grid, keep_column, &column);
  MPI_Cart_sub(grid, keep_none, &point);
  int row_size, row_rank, column_size, column_rank, point_size, ndims = -1, topo = -1;
  MPI_Comm_size(row, &row_size);
  MPI_Comm_rank(row, &row_rank);
  MPI_Comm_size(column, &column_size);
  MPI_Comm_rank(column, &column_rank);
  MPI_Comm_size(point, &point_size);
  CHECK(row_size == dims[1] && row_rank == coords[1] && column_size == dims[0] && column_rank == coords[0]);
  CHECK(point_size == 1);
  MPI_Cartdim_get(row, &ndims);
  MPI_Topo_test(column, &topo);
  CHECK(ndims == 1 && topo == MPI_CART);
  int sub_dims = 0, sub_period = -1, sub_coord = -1;
  MPI_Cart_get(column, 1, &sub_dims, &sub_period, &sub_coord);
  CHECK(sub_dims == dims[0] && sub_period == 1 && sub_coord == coords[0]);
  int row_sum = 0, column_sum = 0; /* world ranks r = c0 * dims[1] + c1 */
  MPI_Allreduce(&rank, &row_sum, 1, MPI_INT, MPI_SUM, row);
  MPI_Allreduce(&rank, &column_sum, 1, MPI_INT, MPI_SUM, column);
  CHECK(row_sum == coords[0] * dims[1] * dims[1] + dims[1] * (dims[1] - 1) / 2);
  CHECK(column_sum == dims[1] * dims[0] * (dims[0] - 1) / 2 + dims[0] * coords[1]);
  MPI_Comm_free(&point);
  MPI_Comm_free(&column);
  MPI_Comm_free(&row);
  MPI_Comm_free(&grid);
}

/* newrank from a *_map: the ranks that get one are a permutation of 0..n-1. */
static void check_map(int newrank, int n) {
  int mapped = newrank == MPI_UNDEFINED ? 0 : 1, sum = newrank == MPI_UNDEFINED ? 0 : newrank, total = 0, total_sum = 0;
  MPI_Allreduce(&mapped, &total, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  MPI_Allreduce(&sum, &total_sum, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  CHECK(total == n && total_sum == n * (n - 1) / 2 && (mapped == 0 || (newrank >= 0 && newrank < n)));
}

/* On the whole communicator: Open MPI 4.1 gives ranks beyond a smaller grid a place in it where
 * the standard says MPI_UNDEFINED, so the smaller grid is left to the core's tests. */
static void cart_map(void) {
  const int n = size, period = 0;
  int newrank = -2;
  MPI_Cart_map(MPI_COMM_WORLD, 1, &n, &period, &newrank);
  check_map(newrank, n);
}

/* Every rank sends its rank to each neighbour and receives one from each: the sum of what came is
 * the sum of the neighbours. */
static int neighbour_sum(MPI_Comm g, const int* nb, int count) {
  int sum = 0, in[64];
  MPI_Request rs[128];
  for (int i = 0; i < count; ++i) {
    MPI_Irecv(&in[i], 1, MPI_INT, nb[i], 20, g, &rs[i]);
    MPI_Isend(&rank, 1, MPI_INT, nb[i], 20, g, &rs[count + i]);
  }
  MPI_Waitall(2 * count, rs, MPI_STATUSES_IGNORE);
  for (int i = 0; i < count; ++i) sum += in[i];
  return sum;
}

static void graph_ring(void) {
  int index[64], edges[128];
  for (int i = 0; i < size; ++i) {
    index[i] = 2 * (i + 1);
    edges[2 * i] = (i + size - 1) % size;
    edges[2 * i + 1] = (i + 1) % size;
  }
  MPI_Comm g;
  MPI_Graph_create(MPI_COMM_WORLD, size, index, edges, 0, &g);
  int topo = -1, nnodes = -1, nedges = -1, count = -1, nb[2] = {-1, -1}, got_index[64], got_edges[128];
  MPI_Topo_test(g, &topo);
  MPI_Graphdims_get(g, &nnodes, &nedges);
  CHECK(topo == MPI_GRAPH && nnodes == size && nedges == 2 * size);
  MPI_Graph_neighbors_count(g, rank, &count);
  MPI_Graph_neighbors(g, rank, 2, nb);
  CHECK(count == 2 && nb[0] == (rank + size - 1) % size && nb[1] == (rank + 1) % size);
  MPI_Graph_get(g, size, 2 * size, got_index, got_edges);
  CHECK(memcmp(got_index, index, sizeof(int) * (size_t)size) == 0 && memcmp(got_edges, edges, sizeof(int) * 2 * (size_t)size) == 0);
  CHECK(neighbour_sum(g, nb, 2) == nb[0] + nb[1]);
  int newrank = -2;
  MPI_Graph_map(MPI_COMM_WORLD, size, index, edges, &newrank);
  check_map(newrank, size);
  MPI_Comm_free(&g);
}

/* Node 0 is the centre, joined to every other; a graph on fewer nodes leaves the rest out. */
static void graph_star(void) {
  int index[64], edges[128], e = 0;
  for (int i = 1; i < size; ++i) edges[e++] = i;
  index[0] = e;
  for (int i = 1; i < size; ++i) {
    edges[e++] = 0;
    index[i] = e;
  }
  MPI_Comm g, part;
  MPI_Graph_create(MPI_COMM_WORLD, size, index, edges, 0, &g);
  int count = -1, nb[64];
  MPI_Graph_neighbors_count(g, rank, &count);
  MPI_Graph_neighbors(g, rank, 64, nb);
  CHECK(count == (rank == 0 ? size - 1 : 1) && (rank == 0 || nb[0] == 0));
  CHECK(neighbour_sum(g, nb, count) == (rank == 0 ? size * (size - 1) / 2 : 0));
  MPI_Comm_free(&g);
  const int part_nodes = (size + 1) / 2;
  int none[64] = {0};
  MPI_Graph_create(MPI_COMM_WORLD, part_nodes, none, edges, 0, &part);
  CHECK((rank < part_nodes) == (part != MPI_COMM_NULL));
  if (part != MPI_COMM_NULL) MPI_Comm_free(&part);
}

/* The ranks of one shared-memory communicator are those on one node: the same processor name, and
 * every rank of the world with that name; ordered by key (here the reverse of rank). */
static void split_type(void) {
  char names[64][MPI_MAX_PROCESSOR_NAME], mine[MPI_MAX_PROCESSOR_NAME], shared_names[64][MPI_MAX_PROCESSOR_NAME];
  int length = 0, members[64];
  memset(mine, 0, sizeof mine);
  MPI_Get_processor_name(mine, &length);
  MPI_Allgather(mine, MPI_MAX_PROCESSOR_NAME, MPI_CHAR, names, MPI_MAX_PROCESSOR_NAME, MPI_CHAR, MPI_COMM_WORLD);
  MPI_Comm shared, none;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, -rank, MPI_INFO_NULL, &shared);
  int shared_size = 0, same_name = 0, same_everywhere = 1, ordered = 1;
  MPI_Comm_size(shared, &shared_size);
  for (int i = 0; i < size; ++i) same_name += strcmp(names[i], mine) == 0;
  MPI_Allgather(mine, MPI_MAX_PROCESSOR_NAME, MPI_CHAR, shared_names, MPI_MAX_PROCESSOR_NAME, MPI_CHAR, shared);
  MPI_Allgather(&rank, 1, MPI_INT, members, 1, MPI_INT, shared);
  for (int i = 0; i < shared_size; ++i) same_everywhere &= strcmp(shared_names[i], mine) == 0;
  for (int i = 1; i < shared_size; ++i) ordered &= members[i] < members[i - 1];
  CHECK(shared_size == same_name && same_everywhere && ordered);
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_UNDEFINED, 0, MPI_INFO_NULL, &none);
  CHECK(none == MPI_COMM_NULL);
  MPI_Comm_free(&shared);
}

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size > 64) MPI_Abort(MPI_COMM_WORLD, 2);
  attribute_callbacks();
  mpi1_attributes_and_predefined();
  cart_sub();
  cart_map();
  graph_ring();
  graph_star();
  split_type();
  printf("rank %d: %d checks, %d failed\n", rank, checks, failures);
  MPI_Finalize();
  return failures == 0 ? 0 : 1;
}
