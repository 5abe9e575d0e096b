// The C entry points of the collectives every rank receives from (MPI 3.1 sections 5.7, 5.8,
// 5.9.6): Allreduce, Allgather(v), Alltoall(v, w). MPI_IN_PLACE as sendbuf on every rank, as
// the standard allows: the data is then taken from recvbuf.
#include <algorithm>
#include <string>

#include "apps/mpi/runtime/collective_site.hpp"

using namespace gcsim::mpi_layer;

namespace {

void copy_into(Bytes& all, std::size_t at, const Bytes& block) {
  std::copy(block.begin(), block.end(), all.begin() + static_cast<std::ptrdiff_t>(at));
}

void check_own_block(const CollectiveSite& s, std::size_t sent, std::size_t expected) {
  if (sent != expected) {
    s.fail(MPI_ERR_TRUNCATE, "this rank sends " + std::to_string(sent) + " bytes but its block holds " + std::to_string(expected));
  }
}

void allgather_v(const void* sendbuf, int sendcount, MPI_Datatype sendtype, void* recvbuf, const int* recvcounts,
                 const int* displs, int recvcount, MPI_Datatype recvtype, MPI_Comm comm, bool varying) {
  CollectiveSite s(Rank::current(), varying ? "MPI_Allgatherv" : "MPI_Allgather", comm);
  const bool in_place = sendbuf == MPI_IN_PLACE;
  const Datatype& recv_type = s.datatype(recvtype);
  const CollectiveSite::Blocks layout = s.blocks(recvcounts, displs, recvcount, varying);
  recvcounts = layout.counts.data();
  displs = layout.displs.data();
  std::vector<std::size_t> sizes(layout.counts.size());
  for (int r = 0; r < s.size(); ++r) sizes[static_cast<std::size_t>(r)] = packed_bytes(recvcounts[r], recv_type);
  const std::vector<std::size_t> at = end_to_end(sizes);
  Bytes all(at.back() + sizes.back());
  const std::size_t me = static_cast<std::size_t>(s.rank());
  Bytes own;
  if (in_place) {
    own = pack_of(element_at(recvbuf, displs[me], recv_type), recvcounts[me], recv_type);
  } else {
    s.check_count(sendcount, "sendcount");
    s.check_buffer(sendbuf, sendcount, false, "sendbuf");
    own = pack_of(sendbuf, sendcount, s.datatype(sendtype));
  }
  check_own_block(s, own.size(), sizes[me]);
  copy_into(all, at[me], own);
  if (!varying) s.agree_on_data(recvcount, recv_type, recvtype);
  const CollectiveCall call = s.call();
  if (varying) allgatherv(call, all, sizes, at, s.algorithm(Collective::Allgatherv));
  else allgather(call, all, sizes[0], s.algorithm(Collective::Allgather));
  for (int r = 0; r < s.size(); ++r) {
    const std::size_t i = static_cast<std::size_t>(r);
    unpack_into(std::span(all).subspan(at[i], sizes[i]), element_at(recvbuf, displs[r], recv_type), recvcounts[r], recv_type);
  }
}

// One side of an all-to-all: per peer a count, a displacement in bytes and a datatype.
struct Side {
  const int* counts;
  std::vector<MPI_Aint> byte_displs;
  std::vector<const Datatype*> types;
};

Side side_of(const CollectiveSite& s, const int* counts, const int* displs, const MPI_Aint* byte_displs,
             const MPI_Datatype* types, MPI_Datatype one_type, const char* which) {
  s.check_counts(counts, which);
  if (!displs && !byte_displs) s.fail(MPI_ERR_ARG, std::string("null displacements of ") + which);
  if (!types && one_type == MPI_DATATYPE_NULL) s.fail(MPI_ERR_ARG, std::string("null datatypes of ") + which);
  Side side{counts, {}, {}};
  for (int r = 0; r < s.size(); ++r) {
    const Datatype& t = s.datatype(types ? types[r] : one_type);
    side.types.push_back(&t);
    side.byte_displs.push_back(byte_displs ? byte_displs[r] : static_cast<MPI_Aint>(displs[r]) * t.extent());
  }
  return side;
}

// uniform: MPI_Alltoall, run by the alltoall algorithms (every block the same size).
void alltoall_sides(CollectiveSite& s, const void* sendbuf, const Side& send, void* recvbuf, const Side& recv, bool uniform) {
  std::vector<std::size_t> send_sizes, recv_sizes;
  for (int r = 0; r < s.size(); ++r) {
    const std::size_t i = static_cast<std::size_t>(r);
    send_sizes.push_back(packed_bytes(send.counts[r], *send.types[i]));
    recv_sizes.push_back(packed_bytes(recv.counts[r], *recv.types[i]));
  }
  const std::vector<std::size_t> send_at = end_to_end(send_sizes), recv_at = end_to_end(recv_sizes);
  Bytes out(send_at.back() + send_sizes.back()), in(recv_at.back() + recv_sizes.back());
  for (int r = 0; r < s.size(); ++r) {
    const std::size_t i = static_cast<std::size_t>(r);
    copy_into(out, send_at[i], pack_of(static_cast<const char*>(sendbuf) + send.byte_displs[i], send.counts[r], *send.types[i]));
  }
  const std::size_t me = static_cast<std::size_t>(s.rank());
  if (send_sizes[me] != recv_sizes[me]) check_own_block(s, send_sizes[me], recv_sizes[me]);
  if (uniform) alltoall(s.call(), out, in, recv_sizes[0], s.algorithm(Collective::Alltoall));
  else alltoallv(s.call(), out, {send_sizes, send_at}, in, {recv_sizes, recv_at}, s.algorithm(Collective::Alltoallv));
  for (int r = 0; r < s.size(); ++r) {
    const std::size_t i = static_cast<std::size_t>(r);
    unpack_into(std::span(in).subspan(recv_at[i], recv_sizes[i]), static_cast<char*>(recvbuf) + recv.byte_displs[i],
                recv.counts[r], *recv.types[i]);
  }
}

// Alltoall(v, w) in place: the send side is the receive side's layout over a copy of recvbuf.
Bytes copy_of_receive_side(const CollectiveSite& s, const void* recvbuf, const Side& recv) {
  MPI_Aint end = 0;
  for (int r = 0; r < s.size(); ++r) {
    const std::size_t i = static_cast<std::size_t>(r);
    if (recv.counts[r] > 0) end = std::max(end, recv.byte_displs[i] + recv.counts[r] * recv.types[i]->extent());
  }
  const auto* from = static_cast<const std::byte*>(recvbuf);
  return Bytes(from, from + end);
}

void alltoall_any(const char* name, const void* sendbuf, const int* sendcounts, const int* sdispls, const MPI_Aint* sbytes,
                  const MPI_Datatype* sendtypes, MPI_Datatype sendtype, void* recvbuf, const int* recvcounts,
                  const int* rdispls, const MPI_Aint* rbytes, const MPI_Datatype* recvtypes, MPI_Datatype recvtype,
                  MPI_Comm comm) {
  CollectiveSite s(Rank::current(), name, comm);
  const bool uniform = std::string_view(name) == "MPI_Alltoall";
  const Side recv = side_of(s, recvcounts, rdispls, rbytes, recvtypes, recvtype, "recvcounts");
  if (sendbuf == MPI_IN_PLACE) {
    const Bytes copy = copy_of_receive_side(s, recvbuf, recv);  // lb >= 0 assumed of in-place types
    alltoall_sides(s, copy.data(), recv, recvbuf, recv, uniform);
    return;
  }
  const Side send = side_of(s, sendcounts, sdispls, sbytes, sendtypes, sendtype, "sendcounts");
  alltoall_sides(s, sendbuf, send, recvbuf, recv, uniform);
}

}  // namespace

extern "C" {

int MPI_Allreduce(const void* sendbuf, void* recvbuf, int count, MPI_Datatype datatype, MPI_Op op, MPI_Comm comm) {
  return runtime_call([&](Rank& rank) {
    CollectiveSite s(rank, "MPI_Allreduce", comm);
    s.check_count(count);
    s.check_buffer(sendbuf, count, true, "sendbuf");
    s.check_buffer(recvbuf, count, false, "recvbuf");
    const Datatype& type = s.datatype(datatype);
    s.agree_on_data(count, type, datatype);
    const Reduction reduction = reduction_for(s.op(op), type, datatype);
    const Bytes send = pack_of(sendbuf == MPI_IN_PLACE ? recvbuf : sendbuf, count, type);
    Bytes result(send.size());
    allreduce(s.call(), send, result, static_cast<std::size_t>(count), reduction, s.algorithm(Collective::Allreduce));
    unpack_into(result, recvbuf, count, type);
  });
}

int MPI_Allgather(const void* sendbuf, int sendcount, MPI_Datatype sendtype, void* recvbuf, int recvcount,
                  MPI_Datatype recvtype, MPI_Comm comm) {
  return runtime_call([&](Rank&) {
    allgather_v(sendbuf, sendcount, sendtype, recvbuf, nullptr, nullptr, recvcount, recvtype, comm, false);
  });
}

int MPI_Allgatherv(const void* sendbuf, int sendcount, MPI_Datatype sendtype, void* recvbuf, const int recvcounts[],
                   const int displs[], MPI_Datatype recvtype, MPI_Comm comm) {
  return runtime_call([&](Rank&) {
    allgather_v(sendbuf, sendcount, sendtype, recvbuf, recvcounts, displs, 0, recvtype, comm, true);
  });
}

int MPI_Alltoall(const void* sendbuf, int sendcount, MPI_Datatype sendtype, void* recvbuf, int recvcount,
                 MPI_Datatype recvtype, MPI_Comm comm) {
  return runtime_call([&](Rank& rank) {
    const int n = rank.comm(comm).size();
    std::vector<int> sc(static_cast<std::size_t>(n), sendcount), rc(sc.size(), recvcount), sd(sc.size()), rd(sc.size());
    for (int r = 0; r < n; ++r) {
      sd[static_cast<std::size_t>(r)] = r * sendcount;
      rd[static_cast<std::size_t>(r)] = r * recvcount;
    }
    alltoall_any("MPI_Alltoall", sendbuf, sc.data(), sd.data(), nullptr, nullptr, sendtype, recvbuf, rc.data(), rd.data(),
                 nullptr, nullptr, recvtype, comm);
  });
}

int MPI_Alltoallv(const void* sendbuf, const int sendcounts[], const int sdispls[], MPI_Datatype sendtype, void* recvbuf,
                  const int recvcounts[], const int rdispls[], MPI_Datatype recvtype, MPI_Comm comm) {
  return runtime_call([&](Rank&) {
    alltoall_any("MPI_Alltoallv", sendbuf, sendcounts, sdispls, nullptr, nullptr, sendtype, recvbuf, recvcounts, rdispls,
                 nullptr, nullptr, recvtype, comm);
  });
}

int MPI_Alltoallw(const void* sendbuf, const int sendcounts[], const int sdispls[], const MPI_Datatype sendtypes[],
                  void* recvbuf, const int recvcounts[], const int rdispls[], const MPI_Datatype recvtypes[],
                  MPI_Comm comm) {
  return runtime_call([&](Rank&) {
    std::vector<MPI_Aint> sb, rb;
    const int n = Rank::current().comm(comm).size();
    for (int r = 0; r < n; ++r) {
      if (sdispls && sendbuf != MPI_IN_PLACE) sb.push_back(sdispls[r]);
      if (rdispls) rb.push_back(rdispls[r]);
    }
    alltoall_any("MPI_Alltoallw", sendbuf, sendcounts, nullptr, sb.empty() ? nullptr : sb.data(), sendtypes,
                 MPI_DATATYPE_NULL, recvbuf, recvcounts, nullptr, rb.empty() ? nullptr : rb.data(), recvtypes,
                 MPI_DATATYPE_NULL, comm);
  });
}

}  // extern "C"
