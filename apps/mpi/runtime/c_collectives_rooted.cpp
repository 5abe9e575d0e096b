// The C entry points of the rooted collectives and the barrier (MPI 3.1 sections 5.3-5.6, 5.9):
// arguments checked, buffers packed, the algorithm run (collective_algorithms.hpp), results
// unpacked. MPI_IN_PLACE as the standard allows it: the root's sendbuf of Reduce and Gather(v),
// the root's recvbuf of Scatter(v).
#include <string>

#include "apps/mpi/runtime/collective_site.hpp"

using namespace gcsim::mpi_layer;

namespace {

std::string root_text(int root) { return "root=" + std::to_string(root); }

std::vector<std::size_t> packed_sizes(CollectiveSite& s, const int* counts, const Datatype& type) {
  std::vector<std::size_t> sizes(static_cast<std::size_t>(s.size()));
  for (int r = 0; r < s.size(); ++r) sizes[static_cast<std::size_t>(r)] = packed_bytes(counts[r], type);
  return sizes;
}

// The root's receive side of gather(v): checked, its packed blocks laid end to end.
struct RootBlocks {
  std::vector<std::size_t> sizes, displacements;
  Bytes all;
};
RootBlocks root_blocks(CollectiveSite& s, std::vector<std::size_t> sizes) {
  RootBlocks b{std::move(sizes), {}, {}};
  b.displacements = end_to_end(b.sizes);
  b.all.resize(b.displacements.empty() ? 0 : b.displacements.back() + b.sizes.back());
  return b;
}

void gather_v(const void* sendbuf, int sendcount, MPI_Datatype sendtype, void* recvbuf, const int* recvcounts,
              const int* displs, int recvcount, MPI_Datatype recvtype, int root, MPI_Comm comm, bool varying) {
  const char* name = varying ? "MPI_Gatherv" : "MPI_Gather";
  CollectiveSite s(Rank::current(), name, comm, root_text(root));
  s.check_root(root);
  const bool at_root = s.rank() == root;
  const bool in_place = at_root && sendbuf == MPI_IN_PLACE;
  if (!in_place) {
    s.check_count(sendcount, "sendcount");
    s.check_buffer(sendbuf, sendcount, false, "sendbuf");
  }
  const Datatype* send_type = in_place ? nullptr : &s.datatype(sendtype);
  Bytes send;
  if (!at_root) {
    send = pack_of(sendbuf, sendcount, *send_type);
    if (!varying) s.agree_on_data(sendcount, *send_type, sendtype);
    const CollectiveCall call = s.call();
    if (varying) gatherv(call, send, {}, {}, {}, root, s.algorithm(Collective::Gatherv));
    else gather(call, send, {}, root, s.algorithm(Collective::Gather));
    return;
  }
  const Datatype& recv_type = s.datatype(recvtype);
  const CollectiveSite::Blocks layout = s.blocks(recvcounts, displs, recvcount, varying);
  recvcounts = layout.counts.data();
  displs = layout.displs.data();
  RootBlocks blocks = root_blocks(s, packed_sizes(s, recvcounts, recv_type));
  send = in_place ? pack_of(element_at(recvbuf, displs[root], recv_type), recvcounts[root], recv_type)
                  : pack_of(sendbuf, sendcount, *send_type);
  if (send.size() != blocks.sizes[static_cast<std::size_t>(root)]) {
    s.fail(MPI_ERR_TRUNCATE, "the root sends " + std::to_string(send.size()) + " bytes but receives " +
                                 std::to_string(blocks.sizes[static_cast<std::size_t>(root)]) + " from itself");
  }
  if (!varying) s.agree_on_data(recvcount, recv_type, recvtype);
  const CollectiveCall call = s.call();
  if (varying) gatherv(call, send, blocks.all, blocks.sizes, blocks.displacements, root, s.algorithm(Collective::Gatherv));
  else gather(call, send, blocks.all, root, s.algorithm(Collective::Gather));
  for (int r = 0; r < s.size(); ++r) {
    if (in_place && r == root) continue;
    const std::size_t i = static_cast<std::size_t>(r);
    unpack_into(std::span(blocks.all).subspan(blocks.displacements[i], blocks.sizes[i]),
                element_at(recvbuf, displs[r], recv_type), recvcounts[r], recv_type);
  }
}

void scatter_v(const void* sendbuf, const int* sendcounts, const int* displs, int sendcount, MPI_Datatype sendtype,
               void* recvbuf, int recvcount, MPI_Datatype recvtype, int root, MPI_Comm comm, bool varying) {
  const char* name = varying ? "MPI_Scatterv" : "MPI_Scatter";
  CollectiveSite s(Rank::current(), name, comm, root_text(root));
  s.check_root(root);
  const bool at_root = s.rank() == root;
  const bool in_place = at_root && recvbuf == MPI_IN_PLACE;
  const Datatype* recv_type = nullptr;
  if (!in_place) {
    s.check_count(recvcount, "recvcount");
    s.check_buffer(recvbuf, recvcount, false, "recvbuf");
    recv_type = &s.datatype(recvtype);
  }
  Bytes mine(in_place ? 0 : packed_bytes(recvcount, *recv_type));
  if (!at_root) {
    if (!varying) s.agree_on_data(recvcount, *recv_type, recvtype);
    const CollectiveCall call = s.call();
    if (varying) scatterv(call, {}, {}, {}, mine, root, s.algorithm(Collective::Scatterv));
    else scatter(call, {}, mine, root, s.algorithm(Collective::Scatter));
    unpack_into(mine, recvbuf, recvcount, *recv_type);
    return;
  }
  const Datatype& send_type = s.datatype(sendtype);
  const CollectiveSite::Blocks send_layout = s.blocks(sendcounts, displs, sendcount, varying, "send");
  sendcounts = send_layout.counts.data();
  displs = send_layout.displs.data();
  RootBlocks blocks = root_blocks(s, packed_sizes(s, sendcounts, send_type));
  for (int r = 0; r < s.size(); ++r) {
    const Bytes b = pack_of(element_at(sendbuf, displs[r], send_type), sendcounts[r], send_type);
    std::copy(b.begin(), b.end(), blocks.all.begin() + static_cast<std::ptrdiff_t>(blocks.displacements[static_cast<std::size_t>(r)]));
  }
  if (in_place) mine.resize(blocks.sizes[static_cast<std::size_t>(root)]);
  if (mine.size() != blocks.sizes[static_cast<std::size_t>(root)]) {
    s.fail(MPI_ERR_TRUNCATE, "the root receives " + std::to_string(mine.size()) + " bytes but sends itself " +
                                 std::to_string(blocks.sizes[static_cast<std::size_t>(root)]));
  }
  if (!varying) s.agree_on_data(sendcount, send_type, sendtype);
  const CollectiveCall call = s.call();
  if (varying) scatterv(call, blocks.all, blocks.sizes, blocks.displacements, mine, root, s.algorithm(Collective::Scatterv));
  else scatter(call, blocks.all, mine, root, s.algorithm(Collective::Scatter));
  if (!in_place) unpack_into(mine, recvbuf, recvcount, *recv_type);
}

}  // namespace

extern "C" {

int MPI_Barrier(MPI_Comm comm) {
  return runtime_call([&](Rank& rank) {
    CollectiveSite s(rank, "MPI_Barrier", comm);
    barrier(s.call(), s.algorithm(Collective::Barrier));
  });
}

int MPI_Bcast(void* buffer, int count, MPI_Datatype datatype, int root, MPI_Comm comm) {
  return runtime_call([&](Rank& rank) {
    CollectiveSite s(rank, "MPI_Bcast", comm, root_text(root));
    s.check_count(count);
    s.check_root(root);
    s.check_buffer(buffer, count, false, "buffer");
    const Datatype& type = s.datatype(datatype);
    s.agree_on_data(count, type, datatype);
    Bytes data = s.rank() == root ? pack_of(buffer, count, type) : Bytes(packed_bytes(count, type));
    bcast(s.call(), data, root, s.algorithm(Collective::Bcast));
    if (s.rank() != root) unpack_into(data, buffer, count, type);
  });
}

int MPI_Reduce(const void* sendbuf, void* recvbuf, int count, MPI_Datatype datatype, MPI_Op op, int root, MPI_Comm comm) {
  return runtime_call([&](Rank& rank) {
    CollectiveSite s(rank, "MPI_Reduce", comm, root_text(root));
    s.check_count(count);
    s.check_root(root);
    const bool at_root = s.rank() == root;
    s.check_buffer(sendbuf, count, at_root, "sendbuf");
    if (at_root) s.check_buffer(recvbuf, count, false, "recvbuf");
    const Datatype& type = s.datatype(datatype);
    s.agree_on_data(count, type, datatype);
    const Reduction reduction = reduction_for(s.op(op), type, datatype);
    const Bytes send = pack_of(sendbuf == MPI_IN_PLACE ? recvbuf : sendbuf, count, type);
    Bytes result(at_root ? send.size() : 0);
    reduce(s.call(), send, result, static_cast<std::size_t>(count), reduction, root, s.algorithm(Collective::Reduce));
    if (at_root) unpack_into(result, recvbuf, count, type);
  });
}

int MPI_Gather(const void* sendbuf, int sendcount, MPI_Datatype sendtype, void* recvbuf, int recvcount,
               MPI_Datatype recvtype, int root, MPI_Comm comm) {
  return runtime_call([&](Rank&) {
    gather_v(sendbuf, sendcount, sendtype, recvbuf, nullptr, nullptr, recvcount, recvtype, root, comm, false);
  });
}

int MPI_Gatherv(const void* sendbuf, int sendcount, MPI_Datatype sendtype, void* recvbuf, const int recvcounts[],
                const int displs[], MPI_Datatype recvtype, int root, MPI_Comm comm) {
  return runtime_call([&](Rank&) {
    gather_v(sendbuf, sendcount, sendtype, recvbuf, recvcounts, displs, 0, recvtype, root, comm, true);
  });
}

int MPI_Scatter(const void* sendbuf, int sendcount, MPI_Datatype sendtype, void* recvbuf, int recvcount,
                MPI_Datatype recvtype, int root, MPI_Comm comm) {
  return runtime_call([&](Rank&) {
    scatter_v(sendbuf, nullptr, nullptr, sendcount, sendtype, recvbuf, recvcount, recvtype, root, comm, false);
  });
}

int MPI_Scatterv(const void* sendbuf, const int sendcounts[], const int displs[], MPI_Datatype sendtype, void* recvbuf,
                 int recvcount, MPI_Datatype recvtype, int root, MPI_Comm comm) {
  return runtime_call([&](Rank&) {
    scatter_v(sendbuf, sendcounts, displs, 0, sendtype, recvbuf, recvcount, recvtype, root, comm, true);
  });
}

}  // extern "C"
