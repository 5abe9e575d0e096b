// The C entry points of Cartesian topologies that need a communicator (MPI 3.1 section 7.5):
// MPI_Cart_create (no reordering: rank r of the old communicator is rank r of the grid; ranks
// beyond the grid get MPI_COMM_NULL), the queries, MPI_Cart_shift, MPI_Cart_sub, MPI_Cart_map
// and MPI_Topo_test; the arithmetic is the core's (topology.hpp).
#include <algorithm>
#include <memory>
#include <vector>

#include "apps/mpi/c_call.hpp"
#include "apps/mpi/runtime/rank.hpp"

using namespace gcsim::mpi_layer;

namespace {

const CartTopology& cart_of(Rank& rank, MPI_Comm comm) {
  const Communicator& c = rank.comm(comm);
  if (!c.cart) fail(MPI_ERR_TOPOLOGY, "the communicator has no Cartesian topology");
  return *c.cart;
}

CartTopology grid_of(int ndims, const int* dims, const int* periods, int size) {
  if (ndims < 0) fail(MPI_ERR_DIMS, "MPI_Cart_create: negative ndims");
  if (ndims > 0 && (!dims || !periods)) fail(MPI_ERR_ARG, "MPI_Cart_create: null dims or periods");
  std::vector<int> d(dims, dims + ndims);
  std::vector<bool> p;
  for (int i = 0; i < ndims; ++i) p.push_back(periods[i] != 0);
  if (std::any_of(d.begin(), d.end(), [](int x) { return x <= 0; })) fail(MPI_ERR_DIMS, "MPI_Cart_create: a dimension is not positive");
  CartTopology grid(std::move(d), std::move(p));
  if (grid.size() > size) fail(MPI_ERR_DIMS, "MPI_Cart_create: the grid has more processes than the communicator");
  return grid;
}

}  // namespace

extern "C" {

int MPI_Cart_create(MPI_Comm comm_old, int ndims, const int dims[], const int periods[], int reorder,
                    MPI_Comm* comm_cart) {
  (void)reorder;  // allowed to be ignored; every rank keeps its place
  return runtime_call([&](Rank& rank) {
    Communicator& parent = rank.comm(comm_old);
    MPI_Comm& out = out_arg(comm_cart);
    auto grid = std::make_shared<const CartTopology>(grid_of(ndims, dims, periods, parent.size()));
    const std::int64_t context = parent.next_child_context();  // every member advances, even one left out
    if (parent.rank >= grid->size()) {
      out = MPI_COMM_NULL;
      return;
    }
    Communicator c = parent.first_members(grid->size(), context);
    c.cart = std::move(grid);
    out = rank.add_comm(std::move(c));
  });
}

int MPI_Cartdim_get(MPI_Comm comm, int* ndims) {
  return runtime_call([&](Rank& rank) { out_arg(ndims) = cart_of(rank, comm).ndims(); });
}

int MPI_Cart_get(MPI_Comm comm, int maxdims, int dims[], int periods[], int coords[]) {
  return runtime_call([&](Rank& rank) {
    const CartTopology& g = cart_of(rank, comm);
    const std::vector<int> mine = g.coords(rank.comm(comm).rank);
    for (int d = 0; d < std::min(maxdims, g.ndims()); ++d) {
      if (dims) dims[d] = g.dims()[static_cast<std::size_t>(d)];
      if (periods) periods[d] = g.periodic(d) ? 1 : 0;
      if (coords) coords[d] = mine[static_cast<std::size_t>(d)];
    }
  });
}

int MPI_Cart_rank(MPI_Comm comm, const int coords[], int* rank_out) {
  return runtime_call([&](Rank& rank) {
    const CartTopology& g = cart_of(rank, comm);
    out_arg(rank_out) = g.rank(std::span(coords, static_cast<std::size_t>(g.ndims())));
  });
}

int MPI_Cart_coords(MPI_Comm comm, int rank_in, int maxdims, int coords[]) {
  return runtime_call([&](Rank& rank) {
    const std::vector<int> c = cart_of(rank, comm).coords(rank_in);
    std::copy_n(c.begin(), std::min<std::size_t>(c.size(), static_cast<std::size_t>(std::max(maxdims, 0))), coords);
  });
}

int MPI_Cart_shift(MPI_Comm comm, int direction, int disp, int* rank_source, int* rank_dest) {
  return runtime_call([&](Rank& rank) {
    const CartTopology& g = cart_of(rank, comm);
    if (direction < 0 || direction >= g.ndims()) fail(MPI_ERR_ARG, "MPI_Cart_shift: direction outside the grid's dimensions");
    const auto [source, dest] = g.shift(rank.comm(comm).rank, direction, disp);
    out_arg(rank_source) = source;
    out_arg(rank_dest) = dest;
  });
}

// A split of the grid by the coordinates dropped (the colour), ordered by those kept (the key), so
// each sub-grid's ranks are row-major in it as the standard asks.
int MPI_Cart_sub(MPI_Comm comm, const int remain_dims[], MPI_Comm* newcomm) {
  return runtime_call([&](Rank& rank) {
    cart_of(rank, comm);
    MPI_Comm& out = out_arg(newcomm);
    const std::shared_ptr<const CartTopology> grid = rank.comm(comm).cart;
    if (grid->ndims() > 0 && !remain_dims) fail(MPI_ERR_ARG, "MPI_Cart_sub: null remain_dims");
    std::vector<bool> remain;
    for (int d = 0; d < grid->ndims(); ++d) remain.push_back(remain_dims[d] != 0);
    auto sub = std::make_shared<const CartTopology>(grid->sub(remain));
    const int me = rank.comm(comm).rank;
    MPI_Comm part = MPI_COMM_NULL;
    if (const int code = MPI_Comm_split(comm, grid->sub_color(me, remain), grid->sub_rank(me, remain), &part); code != MPI_SUCCESS) {
      fail(code, "MPI_Cart_sub: its split failed");
    }
    rank.comm(part).cart = std::move(sub);
    out = part;
  });
}

int MPI_Cart_map(MPI_Comm comm, int ndims, const int dims[], const int periods[], int* newrank) {
  return runtime_call([&](Rank& rank) {
    const Communicator& c = rank.comm(comm);
    out_arg(newrank) = grid_of(ndims, dims, periods, c.size()).map(c.rank);
  });
}

int MPI_Topo_test(MPI_Comm comm, int* status) {
  return runtime_call([&](Rank& rank) {
    const Communicator& c = rank.comm(comm);
    out_arg(status) = c.cart ? MPI_CART : c.graph ? MPI_GRAPH : MPI_UNDEFINED;
  });
}

}  // extern "C"
