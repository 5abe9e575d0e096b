/* Steady heat on the unit square by Jacobi iteration: an N x N grid of interior points, the top
 * edge held at 1 and the other edges at 0. The ranks form a 2D Cartesian grid (MPI_Dims_create,
 * MPI_Cart_create); each owns a block and exchanges one-point halos with its four neighbours
 * (MPI_Cart_shift, MPI_Sendrecv; columns as a vector datatype). The residual, the root of the sum
 * of squared updates, comes from MPI_Allreduce. Every point's update is the same arithmetic
 * whatever the decomposition, so the field, and the printed digits, do not depend on the rank
 * count. Prints the residual every 50 iterations, whether it kept decreasing, and two probes.
 *   gcsim-mpicc -o jacobi jacobi.c -lm && gcsim mpirun -np 4 ./jacobi 48 400 */
#include <math.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

/* The first index and the count of the part `p` of `parts` gets of n points. */
static void block(int n, int parts, int p, int* first, int* count) {
  *count = n / parts + (p < n % parts);
  *first = p * (n / parts) + (p < n % parts ? p : n % parts);
}

typedef struct {
  int rows, cols, row0, col0; /* owned block and its first global indices */
  int up, down, left, right;  /* neighbours, MPI_PROC_NULL at the boundary */
  MPI_Comm grid;
  MPI_Datatype column;
  double *u, *next; /* (rows + 2) x (cols + 2) with halos */
} Block;

#define AT(b, a, i, j) ((a)[(size_t)(i) * (size_t)((b)->cols + 2) + (size_t)(j)])

static void setup(Block* b, int n) {
  int size, dims[2] = {0, 0}, periods[2] = {0, 0}, coords[2];
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Dims_create(size, 2, dims);
  MPI_Cart_create(MPI_COMM_WORLD, 2, dims, periods, 0, &b->grid);
  int me;
  MPI_Comm_rank(b->grid, &me);
  MPI_Cart_coords(b->grid, me, 2, coords);
  MPI_Cart_shift(b->grid, 0, 1, &b->up, &b->down);
  MPI_Cart_shift(b->grid, 1, 1, &b->left, &b->right);
  block(n, dims[0], coords[0], &b->row0, &b->rows);
  block(n, dims[1], coords[1], &b->col0, &b->cols);
  MPI_Type_vector(b->rows, 1, b->cols + 2, MPI_DOUBLE, &b->column);
  MPI_Type_commit(&b->column);
  const size_t cells = (size_t)(b->rows + 2) * (size_t)(b->cols + 2);
  b->u = calloc(cells, sizeof(double));
  b->next = calloc(cells, sizeof(double));
  if (b->row0 == 0) { /* the hot top edge lives in the top blocks' upper halo row */
    for (int j = 0; j < b->cols + 2; ++j) AT(b, b->u, 0, j) = AT(b, b->next, 0, j) = 1.0;
  }
}

static void exchange_halos(Block* b) {
  const int w = b->cols + 2;
  double* u = b->u;
  MPI_Sendrecv(&u[1 * w + 1], b->cols, MPI_DOUBLE, b->up, 0, &u[(b->rows + 1) * w + 1], b->cols, MPI_DOUBLE, b->down, 0,
               b->grid, MPI_STATUS_IGNORE);
  MPI_Sendrecv(&u[b->rows * w + 1], b->cols, MPI_DOUBLE, b->down, 1, &u[0 * w + 1], b->cols, MPI_DOUBLE, b->up, 1,
               b->grid, MPI_STATUS_IGNORE);
  MPI_Sendrecv(&u[w + 1], 1, b->column, b->left, 2, &u[w + b->cols + 1], 1, b->column, b->right, 2, b->grid,
               MPI_STATUS_IGNORE);
  MPI_Sendrecv(&u[w + b->cols], 1, b->column, b->right, 3, &u[w], 1, b->column, b->left, 3, b->grid, MPI_STATUS_IGNORE);
}

/* One sweep; returns the global residual. */
static double sweep(Block* b) {
  exchange_halos(b);
  double local = 0.0;
  for (int i = 1; i <= b->rows; ++i) {
    for (int j = 1; j <= b->cols; ++j) {
      const double v = 0.25 * (AT(b, b->u, i - 1, j) + AT(b, b->u, i + 1, j) + AT(b, b->u, i, j - 1) + AT(b, b->u, i, j + 1));
      const double d = v - AT(b, b->u, i, j);
      local += d * d;
      AT(b, b->next, i, j) = v;
    }
  }
  double* t = b->u;
  b->u = b->next;
  b->next = t;
  double global = 0.0;
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_SUM, b->grid);
  return sqrt(global);
}

/* u at global (i, j), exact: its owner contributes it, every other rank an exact zero. */
static double probe(const Block* b, int i, int j) {
  double mine = 0.0, value = 0.0;
  if (i >= b->row0 && i < b->row0 + b->rows && j >= b->col0 && j < b->col0 + b->cols) {
    mine = AT(b, b->u, i - b->row0 + 1, j - b->col0 + 1);
  }
  MPI_Allreduce(&mine, &value, 1, MPI_DOUBLE, MPI_SUM, b->grid);
  return value;
}

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  const int n = argc > 1 ? atoi(argv[1]) : 48, iterations = argc > 2 ? atoi(argv[2]) : 400;
  int rank;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  Block b;
  setup(&b, n);
  int decreasing = 1;
  double previous = INFINITY, residual = 0.0;
  for (int it = 1; it <= iterations; ++it) {
    residual = sweep(&b);
    decreasing &= residual < previous;
    previous = residual;
    if (rank == 0 && it % 50 == 0) printf("jacobi %dx%d iteration %d residual %.9e\n", n, n, it, residual);
  }
  const double centre = probe(&b, n / 2, n / 2), near_top = probe(&b, 0, n / 2);
  if (rank == 0) {
    printf("jacobi residual decreased at every iteration: %s\n", decreasing ? "yes" : "no");
    printf("jacobi u(centre) %.15e u(top middle) %.15e\n", centre, near_top);
  }
  MPI_Type_free(&b.column);
  MPI_Comm_free(&b.grid);
  free(b.u);
  free(b.next);
  MPI_Finalize();
  return 0;
}
