// Interim collectives: MPI_Barrier, MPI_Bcast, MPI_Reduce and MPI_Allreduce over the communicator's
// collective channel (runtime/rank_channel.hpp), the simplest correct schedules (a fan-in and
// fan-out through rank 0, a binomial broadcast tree, a reduction at the root in rank order so that
// non-commutative operations combine as the standard orders them). The collective algorithms
// (collective_algorithms.hpp) replace this file.
#include <string>
#include <vector>

#include "apps/mpi/c_call.hpp"
#include "apps/mpi/reduction.hpp"
#include "apps/mpi/runtime/rank_channel.hpp"
#include "apps/mpi/type_transfer.hpp"

using namespace gcsim::mpi_layer;

namespace {

enum Tag { kBarrier = 1, kBcast = 2, kReduce = 3 };
using Bytes = std::vector<std::byte>;

std::string named(const char* call, MPI_Comm comm) { return std::string(call) + "(comm=" + Rank::comm_name(comm) + ")"; }

void barrier_over(CollectiveChannel& ch) {
  std::vector<CollectiveChannel::Handle> hs;
  if (ch.rank() != 0) {
    hs.push_back(ch.start_send(0, kBarrier, {}));
    hs.push_back(ch.start_recv(0, kBarrier, {}));
    ch.wait_all(hs);
    return;
  }
  for (int r = 1; r < ch.size(); ++r) hs.push_back(ch.start_recv(r, kBarrier, {}));
  ch.wait_all(hs);
  hs.clear();
  for (int r = 1; r < ch.size(); ++r) hs.push_back(ch.start_send(r, kBarrier, {}));
  ch.wait_all(hs);
}

// Binomial tree from root over packed bytes (data must be sized alike on every rank).
void bcast_over(CollectiveChannel& ch, std::span<std::byte> data, int root) {
  const int n = ch.size();
  const int me = (ch.rank() - root + n) % n;
  int mask = 1;
  while (mask < n) {
    if (me & mask) {
      const CollectiveChannel::Handle h = ch.start_recv((me - mask + root) % n, kBcast, data);
      ch.wait_all(std::span(&h, 1));
      break;
    }
    mask <<= 1;
  }
  std::vector<CollectiveChannel::Handle> hs;
  for (mask >>= 1; mask > 0; mask >>= 1) {
    if (me + mask < n) hs.push_back(ch.start_send((me + mask + root) % n, kBcast, data));
  }
  ch.wait_all(hs);
}

Bytes packed(const void* buf, int count, const Datatype& type) {
  Bytes b(static_cast<std::size_t>(pack_size(count, type)));
  MPI_Count position = 0;
  pack(buf, count, type, b, position);
  return b;
}

void unpacked(const Bytes& b, void* buf, int count, const Datatype& type) {
  MPI_Count position = 0;
  unpack(b, position, buf, count, type);
}

// The bytes a typed buffer of count elements spans from its start (lb >= 0 assumed, checked).
std::size_t span_of(int count, const Datatype& type) {
  if (type.lb() < 0 || type.true_lb() < 0) fail(MPI_ERR_TYPE, "reductions over a datatype with a negative lower bound are not supported yet");
  if (count == 0) return 0;
  return static_cast<std::size_t>((count - 1) * type.extent() + type.true_lb() + type.true_extent());
}

// At the root: v_0 op (v_1 op (... op v_{n-1})), each v_i packed, into recvbuf.
void reduce_over(CollectiveChannel& ch, Registry& reg, const void* mine, void* recvbuf, int count, MPI_Datatype handle,
                 const Op& op, int root) {
  const Datatype& type = datatype_arg(reg, handle, true);
  Bytes own = packed(mine, count, type);
  if (ch.rank() != root) {
    const CollectiveChannel::Handle h = ch.start_send(root, kReduce, own);
    ch.wait_all(std::span(&h, 1));
    return;
  }
  std::vector<Bytes> values(static_cast<std::size_t>(ch.size()), Bytes(own.size()));
  std::vector<CollectiveChannel::Handle> hs;
  for (int r = 0; r < ch.size(); ++r) {
    if (r != root) hs.push_back(ch.start_recv(r, kReduce, values[static_cast<std::size_t>(r)]));
  }
  ch.wait_all(hs);
  values[static_cast<std::size_t>(root)] = std::move(own);
  std::vector<std::byte> acc(span_of(count, type)), next(acc.size());
  unpacked(values.back(), acc.data(), count, type);
  for (int r = ch.size() - 2; r >= 0; --r) {
    unpacked(values[static_cast<std::size_t>(r)], next.data(), count, type);
    apply_op(op, next.data(), acc.data(), count, type, handle);
    ch.charge_reduction(own.size());
  }
  unpacked(packed(acc.data(), count, type), recvbuf, count, type);
}

}  // namespace

extern "C" {

int MPI_Barrier(MPI_Comm comm) {
  return runtime_call([&](Rank& rank) {
    RankChannel ch(rank, comm, named("MPI_Barrier", comm));
    barrier_over(ch);
  });
}

int MPI_Bcast(void* buffer, int count, MPI_Datatype datatype, int root, MPI_Comm comm) {
  return runtime_call([&](Rank& rank) {
    RankChannel ch(rank, comm, "MPI_Bcast(root=" + std::to_string(root) + ", comm=" + Rank::comm_name(comm) + ")");
    check_count_arg(count);
    if (root < 0 || root >= ch.size()) fail(MPI_ERR_ROOT, "root outside the communicator");
    const Datatype& type = datatype_arg(rank.registry(), datatype, true);
    Bytes data = ch.rank() == root ? packed(buffer, count, type) : Bytes(static_cast<std::size_t>(pack_size(count, type)));
    bcast_over(ch, data, root);
    if (ch.rank() != root) unpacked(data, buffer, count, type);
  });
}

int MPI_Reduce(const void* sendbuf, void* recvbuf, int count, MPI_Datatype datatype, MPI_Op op, int root, MPI_Comm comm) {
  return runtime_call([&](Rank& rank) {
    RankChannel ch(rank, comm, "MPI_Reduce(root=" + std::to_string(root) + ", comm=" + Rank::comm_name(comm) + ")");
    check_count_arg(count);
    if (root < 0 || root >= ch.size()) fail(MPI_ERR_ROOT, "root outside the communicator");
    const Op& o = op_arg(rank.registry(), op);
    const void* mine = sendbuf == MPI_IN_PLACE && ch.rank() == root ? recvbuf : sendbuf;
    reduce_over(ch, rank.registry(), mine, recvbuf, count, datatype, o, root);
  });
}

int MPI_Allreduce(const void* sendbuf, void* recvbuf, int count, MPI_Datatype datatype, MPI_Op op, MPI_Comm comm) {
  return runtime_call([&](Rank& rank) {
    RankChannel ch(rank, comm, named("MPI_Allreduce", comm));
    check_count_arg(count);
    const Op& o = op_arg(rank.registry(), op);
    const Datatype& type = datatype_arg(rank.registry(), datatype, true);
    reduce_over(ch, rank.registry(), sendbuf == MPI_IN_PLACE ? recvbuf : sendbuf, recvbuf, count, datatype, o, 0);
    Bytes data = ch.rank() == 0 ? packed(recvbuf, count, type) : Bytes(static_cast<std::size_t>(pack_size(count, type)));
    bcast_over(ch, data, 0);
    if (ch.rank() != 0) unpacked(data, recvbuf, count, type);
  });
}

}  // extern "C"
