// The C entry points of the reduce-scatter and prefix reductions (MPI 3.1 sections 5.10, 5.11):
// Reduce_scatter, Reduce_scatter_block, Scan, Exscan. MPI_IN_PLACE as sendbuf on every rank:
// the operands are then recvbuf's (for reduce-scatter, the whole vector in recvbuf).
#include <numeric>
#include <string>

#include "apps/mpi/runtime/collective_site.hpp"

using namespace gcsim::mpi_layer;

namespace {

struct Operands {
  const Datatype& type;
  Reduction reduction;
};

Operands operands_of(CollectiveSite& s, MPI_Datatype datatype, MPI_Op op) {
  const Datatype& type = s.datatype(datatype);
  return {type, reduction_for(s.op(op), type, datatype)};
}

void reduce_scatter_any(const char* name, const void* sendbuf, void* recvbuf, const int* recvcounts, int recvcount,
                        MPI_Datatype datatype, MPI_Op op, MPI_Comm comm) {
  CollectiveSite s(Rank::current(), name, comm);
  const bool block = recvcounts == nullptr;
  std::vector<int> uniform(static_cast<std::size_t>(s.size()), recvcount);
  if (block) {
    s.check_count(recvcount, "recvcount");
    recvcounts = uniform.data();
  } else {
    s.check_counts(recvcounts, "recvcounts");
  }
  const Operands o = operands_of(s, datatype, op);
  if (block) s.agree_on_data(recvcount, o.type, datatype);
  const long long total = std::accumulate(recvcounts, recvcounts + s.size(), 0ll);
  const int mine = recvcounts[s.rank()];
  s.check_buffer(sendbuf, total, true, "sendbuf");
  s.check_buffer(recvbuf, sendbuf == MPI_IN_PLACE ? total : mine, false, "recvbuf");
  const Bytes send = pack_of(sendbuf == MPI_IN_PLACE ? recvbuf : sendbuf, total, o.type);
  Bytes result(packed_bytes(mine, o.type));
  const CollectiveCall call = s.call();
  if (block) {
    reduce_scatter_block(call, send, result, static_cast<std::size_t>(recvcount), o.reduction,
                         s.algorithm(Collective::ReduceScatterBlock));
  } else {
    std::vector<std::size_t> counts(recvcounts, recvcounts + s.size());
    reduce_scatter(call, send, result, counts, o.reduction, s.algorithm(Collective::ReduceScatter));
  }
  unpack_into(result, recvbuf, mine, o.type);
}

void prefix(const char* name, const void* sendbuf, void* recvbuf, int count, MPI_Datatype datatype, MPI_Op op,
            MPI_Comm comm, bool exclusive) {
  CollectiveSite s(Rank::current(), name, comm);
  s.check_count(count);
  s.check_buffer(sendbuf, count, true, "sendbuf");
  s.check_buffer(recvbuf, count, false, "recvbuf");
  const Operands o = operands_of(s, datatype, op);
  s.agree_on_data(count, o.type, datatype);
  const Bytes send = pack_of(sendbuf == MPI_IN_PLACE ? recvbuf : sendbuf, count, o.type);
  Bytes result(send.size());
  const CollectiveCall call = s.call();
  if (exclusive) exscan(call, send, result, static_cast<std::size_t>(count), o.reduction, s.algorithm(Collective::Exscan));
  else scan(call, send, result, static_cast<std::size_t>(count), o.reduction, s.algorithm(Collective::Scan));
  if (!exclusive || s.rank() != 0) unpack_into(result, recvbuf, count, o.type);  // rank 0's exscan: undefined, untouched
}

}  // namespace

extern "C" {

int MPI_Reduce_scatter(const void* sendbuf, void* recvbuf, const int recvcounts[], MPI_Datatype datatype, MPI_Op op,
                       MPI_Comm comm) {
  return runtime_call([&](Rank&) {
    if (!recvcounts) fail_in("MPI_Reduce_scatter", MPI_ERR_ARG, "null recvcounts");
    reduce_scatter_any("MPI_Reduce_scatter", sendbuf, recvbuf, recvcounts, 0, datatype, op, comm);
  });
}

int MPI_Reduce_scatter_block(const void* sendbuf, void* recvbuf, int recvcount, MPI_Datatype datatype, MPI_Op op,
                             MPI_Comm comm) {
  return runtime_call([&](Rank&) {
    reduce_scatter_any("MPI_Reduce_scatter_block", sendbuf, recvbuf, nullptr, recvcount, datatype, op, comm);
  });
}

int MPI_Scan(const void* sendbuf, void* recvbuf, int count, MPI_Datatype datatype, MPI_Op op, MPI_Comm comm) {
  return runtime_call([&](Rank&) { prefix("MPI_Scan", sendbuf, recvbuf, count, datatype, op, comm, false); });
}

int MPI_Exscan(const void* sendbuf, void* recvbuf, int count, MPI_Datatype datatype, MPI_Op op, MPI_Comm comm) {
  return runtime_call([&](Rank&) { prefix("MPI_Exscan", sendbuf, recvbuf, count, datatype, op, comm, true); });
}

}  // extern "C"
