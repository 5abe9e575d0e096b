#pragma once
// Virtual topologies' arithmetic (MPI 3.1 sections 7.5): MPI_Dims_create, Cartesian rank <->
// coordinates, shifts and sub-grids, and graph neighbours. Ranks are in row-major order: the
// last dimension varies fastest.
#include <span>
#include <vector>

#include "apps/mpi/include/mpi.h"

namespace gcsim::mpi_layer {

// Fills the zero entries of dims so that the product of all is nnodes, the filled ones as close
// to each other as possible and in non-increasing order; other entries stay. MPI_ERR_DIMS if that
// is impossible or an entry is negative.
void dims_create(int nnodes, std::span<int> dims);

class CartTopology {
 public:
  CartTopology(std::vector<int> dims, std::vector<bool> periods);
  int ndims() const { return static_cast<int>(dims_.size()); }
  int size() const;  // processes in the grid
  std::span<const int> dims() const { return dims_; }
  bool periodic(int d) const { return periods_[static_cast<std::size_t>(d)]; }

  // MPI_Cart_rank: periodic coordinates wrap; out of range on a non-periodic one is MPI_ERR_ARG.
  int rank(std::span<const int> coords) const;
  std::vector<int> coords(int rank) const;
  // MPI_Cart_shift: (source, destination) of rank for a shift by disp along direction;
  // MPI_PROC_NULL off a non-periodic end.
  std::pair<int, int> shift(int rank, int direction, int disp) const;
  // MPI_Cart_sub: the sub-grid kept, and for a rank which sub-grid it is in (the colour: its
  // coordinates in the dropped dimensions) and its rank there (the kept ones).
  CartTopology sub(const std::vector<bool>& remain) const;
  int sub_color(int rank, const std::vector<bool>& remain) const;
  int sub_rank(int rank, const std::vector<bool>& remain) const;
  // MPI_Cart_map without reordering: rank itself inside the grid, MPI_UNDEFINED beyond it.
  int map(int rank) const { return rank < size() ? rank : MPI_UNDEFINED; }

 private:
  void check_rank(int rank) const;
  std::vector<int> dims_;
  std::vector<bool> periods_;
};

class GraphTopology {
 public:
  // index[i] is the number of edges of nodes 0..i (MPI_Graph_create's index array).
  GraphTopology(std::vector<int> index, std::vector<int> edges);
  int nnodes() const { return static_cast<int>(index_.size()); }
  int nedges() const { return static_cast<int>(edges_.size()); }
  std::span<const int> index() const { return index_; }
  std::span<const int> edges() const { return edges_; }
  int neighbors_count(int rank) const;
  std::span<const int> neighbors(int rank) const;
  int map(int rank) const { return rank < nnodes() ? rank : MPI_UNDEFINED; }

 private:
  std::vector<int> index_;
  std::vector<int> edges_;
};

}  // namespace gcsim::mpi_layer
