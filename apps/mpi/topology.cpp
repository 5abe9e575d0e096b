#include "apps/mpi/topology.hpp"

#include <algorithm>
#include <climits>

#include "apps/mpi/error.hpp"

namespace gcsim::mpi_layer {
namespace {

std::vector<int> divisors(int n) {
  std::vector<int> small, large;
  for (int d = 1; d <= n / d; ++d) {
    if (n % d != 0) continue;
    small.push_back(d);
    if (d != n / d) large.push_back(n / d);
  }
  small.insert(small.end(), large.rbegin(), large.rend());
  return small;
}

// The most balanced way to write n as a product of k non-increasing factors: the least spread
// (largest - smallest), then the least largest factor.
struct Balanced {
  std::vector<int> best, current;
  const std::vector<int>* divisors_of_n = nullptr;

  bool better(const std::vector<int>& f) const {
    if (best.empty()) return true;
    const int spread = f.front() - f.back(), best_spread = best.front() - best.back();
    return spread != best_spread ? spread < best_spread : f.front() < best.front();
  }
  void search(int n, int k, int ceiling) {
    if (k == 1) {
      if (n > ceiling) return;
      current.push_back(n);
      if (better(current)) best = current;
      current.pop_back();
      return;
    }
    for (int d : *divisors_of_n) {
      if (d > ceiling || d > n) break;
      if (n % d != 0) continue;
      // d is the largest of the k factors left: d^k must reach n.
      long long reach = 1;
      for (int i = 0; i < k && reach < n; ++i) reach *= d;
      if (reach < n) continue;
      current.push_back(d);
      search(n / d, k - 1, d);
      current.pop_back();
    }
  }
};

}  // namespace

void dims_create(int nnodes, std::span<int> dims) {
  if (nnodes <= 0) fail(MPI_ERR_ARG, "MPI_Dims_create needs a positive number of nodes");
  long long fixed = 1;
  int free_dims = 0;
  for (int d : dims) {
    if (d < 0) fail(MPI_ERR_DIMS, "negative dimension");
    if (d == 0) ++free_dims;
    else fixed *= d;
    if (fixed > nnodes) fail(MPI_ERR_DIMS, "the given dimensions exceed the number of nodes");
  }
  if (nnodes % fixed != 0) fail(MPI_ERR_DIMS, "the given dimensions do not divide the number of nodes");
  const int rest = static_cast<int>(nnodes / fixed);
  if (free_dims == 0) {
    if (rest != 1) fail(MPI_ERR_DIMS, "the dimensions' product is not the number of nodes");
    return;
  }
  const std::vector<int> ds = divisors(rest);
  Balanced b;
  b.divisors_of_n = &ds;
  b.search(rest, free_dims, rest);
  auto factor = b.best.begin();
  for (int& d : dims)
    if (d == 0) d = *factor++;
}

CartTopology::CartTopology(std::vector<int> dims, std::vector<bool> periods)
    : dims_(std::move(dims)), periods_(std::move(periods)) {
  if (periods_.size() != dims_.size()) fail(MPI_ERR_ARG, "dims and periods differ in length");
  long long n = 1;
  for (int d : dims_) {
    if (d <= 0) fail(MPI_ERR_DIMS, "a Cartesian dimension must be positive");
    n *= d;
    if (n > INT_MAX) fail(MPI_ERR_DIMS, "the grid has too many processes");
  }
}

int CartTopology::size() const {
  int n = 1;
  for (int d : dims_) n *= d;
  return n;
}

void CartTopology::check_rank(int rank) const {
  if (rank < 0 || rank >= size()) fail(MPI_ERR_RANK, "rank outside the grid");
}

int CartTopology::rank(std::span<const int> coords) const {
  if (static_cast<int>(coords.size()) != ndims()) fail(MPI_ERR_ARG, "wrong number of coordinates");
  int r = 0;
  for (int d = 0; d < ndims(); ++d) {
    const int n = dims_[static_cast<std::size_t>(d)];
    int c = coords[static_cast<std::size_t>(d)];
    if (c < 0 || c >= n) {
      if (!periodic(d)) fail(MPI_ERR_ARG, "coordinate outside a non-periodic dimension");
      c = ((c % n) + n) % n;
    }
    r = r * n + c;
  }
  return r;
}

std::vector<int> CartTopology::coords(int rank) const {
  check_rank(rank);
  std::vector<int> c(dims_.size());
  for (int d = ndims() - 1; d >= 0; --d) {
    const int n = dims_[static_cast<std::size_t>(d)];
    c[static_cast<std::size_t>(d)] = rank % n;
    rank /= n;
  }
  return c;
}

std::pair<int, int> CartTopology::shift(int rank, int direction, int disp) const {
  if (direction < 0 || direction >= ndims()) fail(MPI_ERR_ARG, "shift direction outside the grid's dimensions");
  const std::vector<int> here = coords(rank);
  const auto neighbour = [&](long long step) {
    std::vector<int> c = here;
    const int n = dims_[static_cast<std::size_t>(direction)];
    const long long moved = c[static_cast<std::size_t>(direction)] + step;
    if (!periodic(direction) && (moved < 0 || moved >= n)) return MPI_PROC_NULL;
    c[static_cast<std::size_t>(direction)] = static_cast<int>(((moved % n) + n) % n);
    return this->rank(c);
  };
  return {neighbour(-static_cast<long long>(disp)), neighbour(disp)};
}

CartTopology CartTopology::sub(const std::vector<bool>& remain) const {
  if (static_cast<int>(remain.size()) != ndims()) fail(MPI_ERR_ARG, "remain_dims has the wrong length");
  std::vector<int> dims;
  std::vector<bool> periods;
  for (int d = 0; d < ndims(); ++d)
    if (remain[static_cast<std::size_t>(d)]) {
      dims.push_back(dims_[static_cast<std::size_t>(d)]);
      periods.push_back(periodic(d));
    }
  return CartTopology(std::move(dims), std::move(periods));
}

// Row-major index of rank's coordinates in the dimensions where remain equals keep.
static int linear_index(const CartTopology& t, int rank, const std::vector<bool>& remain, bool keep) {
  if (static_cast<int>(remain.size()) != t.ndims()) fail(MPI_ERR_ARG, "remain_dims has the wrong length");
  const std::vector<int> c = t.coords(rank);
  int index = 0;
  for (int d = 0; d < t.ndims(); ++d)
    if (remain[static_cast<std::size_t>(d)] == keep) index = index * t.dims()[static_cast<std::size_t>(d)] + c[static_cast<std::size_t>(d)];
  return index;
}

int CartTopology::sub_color(int rank, const std::vector<bool>& remain) const { return linear_index(*this, rank, remain, false); }

int CartTopology::sub_rank(int rank, const std::vector<bool>& remain) const { return linear_index(*this, rank, remain, true); }

GraphTopology::GraphTopology(std::vector<int> index, std::vector<int> edges)
    : index_(std::move(index)), edges_(std::move(edges)) {
  int previous = 0;
  for (int i : index_) {
    if (i < previous) fail(MPI_ERR_ARG, "graph index must not decrease");
    previous = i;
  }
  if (previous != nedges()) fail(MPI_ERR_ARG, "graph index does not end at the number of edges");
  for (int e : edges_)
    if (e < 0 || e >= nnodes()) fail(MPI_ERR_ARG, "graph edge to a node outside the graph");
}

int GraphTopology::neighbors_count(int rank) const { return static_cast<int>(neighbors(rank).size()); }

std::span<const int> GraphTopology::neighbors(int rank) const {
  if (rank < 0 || rank >= nnodes()) fail(MPI_ERR_RANK, "rank outside the graph");
  const int begin = rank == 0 ? 0 : index_[static_cast<std::size_t>(rank - 1)];
  const int end = index_[static_cast<std::size_t>(rank)];
  return std::span<const int>(edges_).subspan(static_cast<std::size_t>(begin), static_cast<std::size_t>(end - begin));
}

}  // namespace gcsim::mpi_layer
