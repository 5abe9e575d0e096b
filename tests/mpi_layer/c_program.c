/* A C99 program against gcsim's <mpi.h>, through the C ABI only: the runtime-independent calls
 * (datatypes, subarrays, MPI_BOTTOM, pack, status counts, local reductions, groups, Dims_create,
 * error texts). Compiled with -std=c99 -Wall -Wextra -pedantic -Werror; it names every check
 * that fails and exits non-zero. */
#include <mpi.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

static int failures = 0;
#define CHECK(cond)                                              \
  do {                                                           \
    if (!(cond)) {                                               \
      fprintf(stderr, "%s:%d: %s\n", __FILE__, __LINE__, #cond); \
      ++failures;                                                \
    }                                                            \
  } while (0)

struct particle {
  char tag;
  double position[3];
  int id;
};

static void check_struct_type(void) {
  struct particle p[2];
  int lengths[3] = {1, 3, 1};
  MPI_Aint base, displacements[3], lb, extent;
  MPI_Datatype types[3] = {MPI_CHAR, MPI_DOUBLE, MPI_INT}, t;
  int size;
  memset(p, 0, sizeof p);
  CHECK(MPI_Get_address(&p[0], &base) == MPI_SUCCESS);
  MPI_Get_address(&p[0].tag, &displacements[0]);
  MPI_Get_address(&p[0].position, &displacements[1]);
  MPI_Get_address(&p[0].id, &displacements[2]);
  for (int i = 0; i < 3; ++i) displacements[i] -= base;
  CHECK(MPI_Type_create_struct(3, lengths, displacements, types, &t) == MPI_SUCCESS);
  CHECK(MPI_Type_get_extent(t, &lb, &extent) == MPI_SUCCESS);
  CHECK(lb == 0 && extent == (MPI_Aint)sizeof(struct particle));
  MPI_Type_size(t, &size);
  CHECK(size == 1 + 3 * 8 + 4);
  CHECK(MPI_Type_free(&t) == MPI_SUCCESS && t == MPI_DATATYPE_NULL);
}

static void check_pack_round_trip(void) {
  int matrix[4][4], column[4] = {0}, position = 0, packed_size = 0;
  char buffer[64];
  MPI_Datatype column_type;
  for (int i = 0; i < 16; ++i) matrix[i / 4][i % 4] = i;
  CHECK(MPI_Type_vector(4, 1, 4, MPI_INT, &column_type) == MPI_SUCCESS);
  CHECK(MPI_Pack(&matrix[0][2], 1, column_type, buffer, sizeof buffer, &position, MPI_COMM_WORLD) == MPI_ERR_TYPE);
  MPI_Type_commit(&column_type);
  CHECK(MPI_Pack_size(1, column_type, MPI_COMM_WORLD, &packed_size) == MPI_SUCCESS && packed_size == 16);
  CHECK(MPI_Pack(&matrix[0][2], 1, column_type, buffer, sizeof buffer, &position, MPI_COMM_WORLD) == MPI_SUCCESS);
  CHECK(position == 16);
  position = 0;
  CHECK(MPI_Unpack(buffer, 16, &position, column, 4, MPI_INT, MPI_COMM_WORLD) == MPI_SUCCESS);
  CHECK(column[0] == 2 && column[1] == 6 && column[2] == 10 && column[3] == 14);
  position = 0;
  CHECK(MPI_Pack(matrix, 1, column_type, buffer, 8, &position, MPI_COMM_WORLD) == MPI_ERR_TRUNCATE);
  MPI_Type_free(&column_type);
  CHECK(MPI_Type_commit(&column_type) == MPI_ERR_TYPE);
  CHECK(MPI_Type_free(&(MPI_Datatype){MPI_INT}) == MPI_ERR_TYPE);
}

static void check_subarray(void) {
  int grid[4][5], halo[3] = {0}, sizes[2] = {4, 5}, subsizes[2] = {3, 1}, starts[2] = {1, 4}, position = 0;
  char buffer[12];
  MPI_Datatype column;
  MPI_Aint lb, extent;
  for (int i = 0; i < 20; ++i) grid[i / 5][i % 5] = i;
  CHECK(MPI_Type_create_subarray(2, sizes, subsizes, starts, MPI_ORDER_C, MPI_INT, &column) == MPI_SUCCESS);
  MPI_Type_commit(&column);
  MPI_Type_get_extent(column, &lb, &extent);
  CHECK(lb == 0 && extent == (MPI_Aint)sizeof grid);
  MPI_Pack(grid, 1, column, buffer, sizeof buffer, &position, MPI_COMM_SELF);
  position = 0;
  MPI_Unpack(buffer, sizeof buffer, &position, halo, 3, MPI_INT, MPI_COMM_SELF);
  CHECK(halo[0] == 9 && halo[1] == 14 && halo[2] == 19);
  MPI_Type_free(&column);
}

/* Absolute addresses from MPI_Get_address, with MPI_BOTTOM as the buffer. */
static void check_absolute_addresses(void) {
  int a = 7, a2 = 0, lengths[2] = {1, 1}, position = 0;
  double b = 2.5, b2 = 0;
  MPI_Aint addresses[2];
  MPI_Datatype types[2] = {MPI_INT, MPI_DOUBLE}, t;
  char buffer[16];
  MPI_Get_address(&a, &addresses[0]);
  MPI_Get_address(&b, &addresses[1]);
  CHECK(MPI_Type_create_struct(2, lengths, addresses, types, &t) == MPI_SUCCESS);
  MPI_Type_commit(&t);
  CHECK(MPI_Pack(MPI_BOTTOM, 1, t, buffer, sizeof buffer, &position, MPI_COMM_SELF) == MPI_SUCCESS);
  CHECK(position == 12);
  position = 0;
  MPI_Unpack(buffer, 12, &position, &a2, 1, MPI_INT, MPI_COMM_SELF);
  MPI_Unpack(buffer, 12, &position, &b2, 1, MPI_DOUBLE, MPI_COMM_SELF);
  CHECK(a2 == 7 && b2 == 2.5);
  MPI_Type_free(&t);
}

static void check_status_counts(void) {
  MPI_Status status;
  int count = 0;
  MPI_Datatype pair = MPI_DOUBLE_INT;
  CHECK(MPI_Status_set_elements(&status, pair, 3) == MPI_SUCCESS);
  CHECK(MPI_Get_elements(&status, pair, &count) == MPI_SUCCESS && count == 3);
  CHECK(MPI_Get_count(&status, pair, &count) == MPI_SUCCESS && count == MPI_UNDEFINED);
  MPI_Status_set_elements(&status, MPI_INT, 5);
  CHECK(MPI_Get_count(&status, MPI_INT, &count) == MPI_SUCCESS && count == 5);
  MPI_Status_set_cancelled(&status, 1);
  CHECK(MPI_Test_cancelled(&status, &count) == MPI_SUCCESS && count == 1);
}

/* Decimal concatenation, associative but not commutative: (digits, 10^length) pairs, so the
 * order of ranks shows in the result. */
static void concatenate(void* in, void* inout, int* len, MPI_Datatype* type) {
  int* a = (int*)in;
  int* b = (int*)inout;
  (void)type;
  for (int i = 0; i < *len; ++i) {
    b[2 * i] = a[2 * i] * b[2 * i + 1] + b[2 * i];
    b[2 * i + 1] = a[2 * i + 1] * b[2 * i + 1];
  }
}

static void check_reductions(void) {
  int in[3] = {1, 2, 3}, inout[3] = {10, 20, 30}, commute = 1;
  struct { double value; int index; } a = {2.0, 5}, b = {2.0, 3};
  MPI_Op digits;
  CHECK(MPI_Reduce_local(in, inout, 3, MPI_INT, MPI_SUM) == MPI_SUCCESS);
  CHECK(inout[0] == 11 && inout[2] == 33);
  CHECK(MPI_Reduce_local(in, inout, 3, MPI_CHAR, MPI_SUM) == MPI_ERR_OP);
  CHECK(MPI_Reduce_local(in, inout, 1, MPI_INT, MPI_MAXLOC) == MPI_ERR_OP);
  CHECK(MPI_Reduce_local(&a, &b, 1, MPI_DOUBLE_INT, MPI_MINLOC) == MPI_SUCCESS && b.index == 3);
  CHECK(MPI_Op_create(concatenate, 0, &digits) == MPI_SUCCESS);
  CHECK(MPI_Op_commutative(digits, &commute) == MPI_SUCCESS && commute == 0);
  /* Ranks 0, 1, 2 hold the digits 1, 2, 3; folded from the highest rank down, in is the lower. */
  int acc[2] = {3, 10};
  for (int rank = 1; rank >= 0; --rank) {
    int mine[2] = {rank + 1, 10};
    MPI_Reduce_local(mine, acc, 1, MPI_2INT, digits);
  }
  CHECK(acc[0] == 123 && acc[1] == 1000);
  CHECK(MPI_Op_free(&digits) == MPI_SUCCESS && digits == MPI_OP_NULL);
  CHECK(MPI_Reduce_local(in, inout, 1, MPI_INT, digits) == MPI_ERR_OP);
}

static void check_groups_dims_errors(void) {
  int size = -1, result = -1, dims[3] = {0, 0, 0}, length = 0;
  char text[MPI_MAX_ERROR_STRING], library[MPI_MAX_LIBRARY_VERSION_STRING];
  MPI_Group g = MPI_GROUP_EMPTY;
  CHECK(MPI_Get_library_version(library, &length) == MPI_SUCCESS && strstr(library, "gcsim") != NULL);
  CHECK(MPI_Pcontrol(1) == MPI_SUCCESS);
  CHECK(MPI_Group_size(MPI_GROUP_EMPTY, &size) == MPI_SUCCESS && size == 0);
  CHECK(MPI_Group_compare(MPI_GROUP_EMPTY, MPI_GROUP_EMPTY, &result) == MPI_SUCCESS && result == MPI_IDENT);
  CHECK(MPI_Group_union(MPI_GROUP_EMPTY, MPI_GROUP_EMPTY, &g) == MPI_SUCCESS && g == MPI_GROUP_EMPTY);
  CHECK(MPI_Group_size(12345, &size) == MPI_ERR_GROUP);
  CHECK(MPI_Dims_create(24, 3, dims) == MPI_SUCCESS && dims[0] == 4 && dims[1] == 3 && dims[2] == 2);
  CHECK(MPI_Error_string(MPI_ERR_TRUNCATE, text, &length) == MPI_SUCCESS);
  CHECK(strstr(text, "truncated") != NULL && length == (int)strlen(text));
  CHECK(MPI_Error_class(MPI_ERR_TOPOLOGY, &result) == MPI_SUCCESS && result == MPI_ERR_TOPOLOGY);
}

int main(void) {
  check_struct_type();
  check_pack_round_trip();
  check_subarray();
  check_absolute_addresses();
  check_status_counts();
  check_reductions();
  check_groups_dims_errors();
  if (failures == 0) printf("all C checks passed\n");
  return failures == 0 ? 0 : 1;
}
