// The C entry points of graph topologies (MPI 3.1 section 7.5.3-7.5.5): MPI_Graph_create (no
// reordering: rank r of the old communicator is node r; ranks beyond the graph get MPI_COMM_NULL),
// the queries and MPI_Graph_map; the arithmetic is the core's (topology.hpp).
#include <algorithm>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "apps/mpi/c_call.hpp"
#include "apps/mpi/runtime/rank.hpp"

using namespace gcsim::mpi_layer;

namespace {

const GraphTopology& graph_of(Rank& rank, MPI_Comm comm) {
  const Communicator& c = rank.comm(comm);
  if (!c.graph) fail(MPI_ERR_TOPOLOGY, "the communicator has no graph topology");
  return *c.graph;
}

// The graph of (nnodes, index, edges) as MPI_Graph_create and MPI_Graph_map take it.
GraphTopology graph_from(const char* call, int nnodes, const int* index, const int* edges, int size) {
  if (nnodes < 0) fail(MPI_ERR_ARG, (std::string(call) + ": negative nnodes").c_str());
  if (nnodes > size) fail(MPI_ERR_ARG, (std::string(call) + ": the graph has more nodes than the communicator").c_str());
  if (nnodes > 0 && !index) fail(MPI_ERR_ARG, (std::string(call) + ": null index").c_str());
  const int nedges = nnodes > 0 ? index[nnodes - 1] : 0;
  if (nedges < 0) fail(MPI_ERR_ARG, (std::string(call) + ": negative number of edges").c_str());
  if (nedges > 0 && !edges) fail(MPI_ERR_ARG, (std::string(call) + ": null edges").c_str());
  return GraphTopology(std::vector<int>(index, index + nnodes), std::vector<int>(edges, edges + nedges));
}

template <class T>
void copy_out(std::span<const T> from, int max, T* to) {
  if (max <= 0) return;
  if (!to) fail(MPI_ERR_ARG, "null output array");
  std::copy_n(from.begin(), std::min(from.size(), static_cast<std::size_t>(max)), to);
}

}  // namespace

extern "C" {

int MPI_Graph_create(MPI_Comm comm_old, int nnodes, const int index[], const int edges[], int reorder,
                     MPI_Comm* comm_graph) {
  (void)reorder;  // allowed to be ignored; every rank keeps its place
  return runtime_call([&](Rank& rank) {
    Communicator& parent = rank.comm(comm_old);
    MPI_Comm& out = out_arg(comm_graph);
    auto graph = std::make_shared<const GraphTopology>(graph_from("MPI_Graph_create", nnodes, index, edges, parent.size()));
    const std::int64_t context = parent.next_child_context();  // every member advances, even one left out
    if (parent.rank >= graph->nnodes()) {
      out = MPI_COMM_NULL;
      return;
    }
    Communicator c = parent.first_members(graph->nnodes(), context);
    c.graph = std::move(graph);
    out = rank.add_comm(std::move(c));
  });
}

int MPI_Graphdims_get(MPI_Comm comm, int* nnodes, int* nedges) {
  return runtime_call([&](Rank& rank) {
    const GraphTopology& g = graph_of(rank, comm);
    out_arg(nnodes) = g.nnodes();
    out_arg(nedges) = g.nedges();
  });
}

int MPI_Graph_get(MPI_Comm comm, int maxindex, int maxedges, int index[], int edges[]) {
  return runtime_call([&](Rank& rank) {
    const GraphTopology& g = graph_of(rank, comm);
    copy_out(g.index(), maxindex, index);
    copy_out(g.edges(), maxedges, edges);
  });
}

int MPI_Graph_neighbors_count(MPI_Comm comm, int rank_in, int* nneighbors) {
  return runtime_call([&](Rank& rank) { out_arg(nneighbors) = graph_of(rank, comm).neighbors_count(rank_in); });
}

int MPI_Graph_neighbors(MPI_Comm comm, int rank_in, int maxneighbors, int neighbors[]) {
  return runtime_call([&](Rank& rank) { copy_out(graph_of(rank, comm).neighbors(rank_in), maxneighbors, neighbors); });
}

int MPI_Graph_map(MPI_Comm comm, int nnodes, const int index[], const int edges[], int* newrank) {
  return runtime_call([&](Rank& rank) {
    const Communicator& c = rank.comm(comm);
    out_arg(newrank) = graph_from("MPI_Graph_map", nnodes, index, edges, c.size()).map(c.rank);
  });
}

}  // extern "C"
