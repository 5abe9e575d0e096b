/* The Mandelbrot set on a W x H grid of [-2, 1] x [-1.5, 1.5], farmed out row by row: rank 0 is
 * the master, handing the next row to whichever worker returns one (MPI_ANY_SOURCE), and the
 * workers compute escape counts (at most 255 iterations). The checksum (each row's index + 1
 * times the sum of its counts, summed) does not depend on which worker did which row, so it is
 * the same for every rank count; on one rank the master computes every row itself.
 *   gcsim-mpicc -o mandelbrot mandelbrot.c && gcsim mpirun -np 8 ./mandelbrot 256 192 */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

enum { MAX_ITER = 255, TAG_ROW = 1, TAG_STOP = 2 };

static int escape(double cr, double ci) {
  double zr = 0, zi = 0;
  int k = 0;
  while (k < MAX_ITER && zr * zr + zi * zi <= 4.0) {
    const double t = zr * zr - zi * zi + cr;
    zi = 2 * zr * zi + ci;
    zr = t;
    ++k;
  }
  return k;
}

/* counts[0] = the row, counts[1..w] its escape counts. */
static void compute_row(int row, int w, int h, int* counts) {
  counts[0] = row;
  for (int x = 0; x < w; ++x) counts[1 + x] = escape(-2.0 + 3.0 * (x + 0.5) / w, -1.5 + 3.0 * (row + 0.5) / h);
}

static unsigned long long row_sum(const int* counts, int w) {
  unsigned long long s = 0;
  for (int x = 0; x < w; ++x) s += (unsigned long long)counts[1 + x];
  return s * (unsigned long long)(counts[0] + 1);
}

static unsigned long long master(int w, int h, int size, int* per_worker) {
  int* counts = malloc(sizeof(int) * (size_t)(w + 1));
  unsigned long long checksum = 0;
  int next = 0, busy = 0;
  if (size == 1) {
    for (; next < h; ++next) compute_row(next, w, h, counts), checksum += row_sum(counts, w);
  }
  for (int worker = 1; worker < size; ++worker) { /* a first row each, or stop at once */
    if (next < h) MPI_Send(&next, 1, MPI_INT, worker, TAG_ROW, MPI_COMM_WORLD), ++next, ++busy;
    else MPI_Send(&next, 1, MPI_INT, worker, TAG_STOP, MPI_COMM_WORLD);
  }
  while (busy > 0) {
    MPI_Status st;
    MPI_Recv(counts, w + 1, MPI_INT, MPI_ANY_SOURCE, TAG_ROW, MPI_COMM_WORLD, &st);
    checksum += row_sum(counts, w);
    ++per_worker[st.MPI_SOURCE];
    if (next < h) MPI_Send(&next, 1, MPI_INT, st.MPI_SOURCE, TAG_ROW, MPI_COMM_WORLD), ++next;
    else MPI_Send(&next, 1, MPI_INT, st.MPI_SOURCE, TAG_STOP, MPI_COMM_WORLD), --busy;
  }
  free(counts);
  return checksum;
}

static void worker(int w, int h) {
  int* counts = malloc(sizeof(int) * (size_t)(w + 1));
  for (;;) {
    int row;
    MPI_Status st;
    MPI_Recv(&row, 1, MPI_INT, 0, MPI_ANY_TAG, MPI_COMM_WORLD, &st);
    if (st.MPI_TAG == TAG_STOP) break;
    compute_row(row, w, h, counts);
    MPI_Send(counts, w + 1, MPI_INT, 0, TAG_ROW, MPI_COMM_WORLD);
  }
  free(counts);
}

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  const int w = argc > 1 ? atoi(argv[1]) : 256, h = argc > 2 ? atoi(argv[2]) : 192;
  int rank, size;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (rank == 0) {
    int* per_worker = calloc((size_t)size, sizeof(int));
    const unsigned long long checksum = master(w, h, size, per_worker);
    int rows = size == 1 ? h : 0;
    for (int r = 1; r < size; ++r) rows += per_worker[r];
    printf("mandelbrot %dx%d checksum %llu rows %d\n", w, h, checksum, rows);
    free(per_worker);
  } else {
    worker(w, h);
  }
  MPI_Finalize();
  return 0;
}
