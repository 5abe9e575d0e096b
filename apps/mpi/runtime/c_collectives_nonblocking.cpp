// The C entry points of the non-blocking collectives (MPI 3.1 section 5.12): each checks its
// communicator and request argument, takes the communicator's sequence number now (so blocking
// and non-blocking collectives interleave in the order the program starts them), and starts its
// blocking form's schedule, which progresses at the rank's later calls
// (rank_nonblocking_collectives.cpp). The arguments' other checks run at once, inside the start;
// their error is the request's, raised by its wait or test.
#include <string>

#include "apps/mpi/runtime/collective_site.hpp"

using namespace gcsim::mpi_layer;

namespace {

template <class Blocking>
int start_nonblocking(const char* name, MPI_Comm comm, MPI_Request* request, Blocking blocking) {
  return runtime_call_as(name, [&](Rank& rank) {
    MPI_Request& out = out_arg(request);
    Communicator& c = communicator_of(rank, name, comm);
    const std::uint32_t sequence = c.collectives++;
    const std::string call = std::string(name) + "(comm=" + Rank::comm_name(comm) + ")";
    out = rank.start_collective(call, c.collective_context(), [blocking, sequence] {
      const ReservedSequence reserved(sequence);
      return blocking();
    });
  });
}

}  // namespace

extern "C" {

int MPI_Ibarrier(MPI_Comm comm, MPI_Request* request) {
  return start_nonblocking("MPI_Ibarrier", comm, request, [=] { return MPI_Barrier(comm); });
}

int MPI_Ibcast(void* buffer, int count, MPI_Datatype datatype, int root, MPI_Comm comm, MPI_Request* request) {
  return start_nonblocking("MPI_Ibcast", comm, request, [=] { return MPI_Bcast(buffer, count, datatype, root, comm); });
}

int MPI_Ireduce(const void* sendbuf, void* recvbuf, int count, MPI_Datatype datatype, MPI_Op op, int root,
                MPI_Comm comm, MPI_Request* request) {
  return start_nonblocking("MPI_Ireduce", comm, request,
                           [=] { return MPI_Reduce(sendbuf, recvbuf, count, datatype, op, root, comm); });
}

int MPI_Iallreduce(const void* sendbuf, void* recvbuf, int count, MPI_Datatype datatype, MPI_Op op, MPI_Comm comm,
                   MPI_Request* request) {
  return start_nonblocking("MPI_Iallreduce", comm, request,
                           [=] { return MPI_Allreduce(sendbuf, recvbuf, count, datatype, op, comm); });
}

int MPI_Igather(const void* sendbuf, int sendcount, MPI_Datatype sendtype, void* recvbuf, int recvcount,
                MPI_Datatype recvtype, int root, MPI_Comm comm, MPI_Request* request) {
  return start_nonblocking("MPI_Igather", comm, request, [=] {
    return MPI_Gather(sendbuf, sendcount, sendtype, recvbuf, recvcount, recvtype, root, comm);
  });
}

int MPI_Igatherv(const void* sendbuf, int sendcount, MPI_Datatype sendtype, void* recvbuf, const int recvcounts[],
                 const int displs[], MPI_Datatype recvtype, int root, MPI_Comm comm, MPI_Request* request) {
  return start_nonblocking("MPI_Igatherv", comm, request, [=] {
    return MPI_Gatherv(sendbuf, sendcount, sendtype, recvbuf, recvcounts, displs, recvtype, root, comm);
  });
}

int MPI_Iscatter(const void* sendbuf, int sendcount, MPI_Datatype sendtype, void* recvbuf, int recvcount,
                 MPI_Datatype recvtype, int root, MPI_Comm comm, MPI_Request* request) {
  return start_nonblocking("MPI_Iscatter", comm, request, [=] {
    return MPI_Scatter(sendbuf, sendcount, sendtype, recvbuf, recvcount, recvtype, root, comm);
  });
}

int MPI_Iscatterv(const void* sendbuf, const int sendcounts[], const int displs[], MPI_Datatype sendtype,
                  void* recvbuf, int recvcount, MPI_Datatype recvtype, int root, MPI_Comm comm,
                  MPI_Request* request) {
  return start_nonblocking("MPI_Iscatterv", comm, request, [=] {
    return MPI_Scatterv(sendbuf, sendcounts, displs, sendtype, recvbuf, recvcount, recvtype, root, comm);
  });
}

int MPI_Iallgather(const void* sendbuf, int sendcount, MPI_Datatype sendtype, void* recvbuf, int recvcount,
                   MPI_Datatype recvtype, MPI_Comm comm, MPI_Request* request) {
  return start_nonblocking("MPI_Iallgather", comm, request, [=] {
    return MPI_Allgather(sendbuf, sendcount, sendtype, recvbuf, recvcount, recvtype, comm);
  });
}

int MPI_Iallgatherv(const void* sendbuf, int sendcount, MPI_Datatype sendtype, void* recvbuf,
                    const int recvcounts[], const int displs[], MPI_Datatype recvtype, MPI_Comm comm,
                    MPI_Request* request) {
  return start_nonblocking("MPI_Iallgatherv", comm, request, [=] {
    return MPI_Allgatherv(sendbuf, sendcount, sendtype, recvbuf, recvcounts, displs, recvtype, comm);
  });
}

int MPI_Ialltoall(const void* sendbuf, int sendcount, MPI_Datatype sendtype, void* recvbuf, int recvcount,
                  MPI_Datatype recvtype, MPI_Comm comm, MPI_Request* request) {
  return start_nonblocking("MPI_Ialltoall", comm, request, [=] {
    return MPI_Alltoall(sendbuf, sendcount, sendtype, recvbuf, recvcount, recvtype, comm);
  });
}

int MPI_Ialltoallv(const void* sendbuf, const int sendcounts[], const int sdispls[], MPI_Datatype sendtype,
                   void* recvbuf, const int recvcounts[], const int rdispls[], MPI_Datatype recvtype,
                   MPI_Comm comm, MPI_Request* request) {
  return start_nonblocking("MPI_Ialltoallv", comm, request, [=] {
    return MPI_Alltoallv(sendbuf, sendcounts, sdispls, sendtype, recvbuf, recvcounts, rdispls, recvtype, comm);
  });
}

int MPI_Ialltoallw(const void* sendbuf, const int sendcounts[], const int sdispls[], const MPI_Datatype sendtypes[],
                   void* recvbuf, const int recvcounts[], const int rdispls[], const MPI_Datatype recvtypes[],
                   MPI_Comm comm, MPI_Request* request) {
  return start_nonblocking("MPI_Ialltoallw", comm, request, [=] {
    return MPI_Alltoallw(sendbuf, sendcounts, sdispls, sendtypes, recvbuf, recvcounts, rdispls, recvtypes, comm);
  });
}

int MPI_Ireduce_scatter(const void* sendbuf, void* recvbuf, const int recvcounts[], MPI_Datatype datatype,
                        MPI_Op op, MPI_Comm comm, MPI_Request* request) {
  return start_nonblocking("MPI_Ireduce_scatter", comm, request,
                           [=] { return MPI_Reduce_scatter(sendbuf, recvbuf, recvcounts, datatype, op, comm); });
}

int MPI_Ireduce_scatter_block(const void* sendbuf, void* recvbuf, int recvcount, MPI_Datatype datatype,
                              MPI_Op op, MPI_Comm comm, MPI_Request* request) {
  return start_nonblocking("MPI_Ireduce_scatter_block", comm, request,
                           [=] { return MPI_Reduce_scatter_block(sendbuf, recvbuf, recvcount, datatype, op, comm); });
}

int MPI_Iscan(const void* sendbuf, void* recvbuf, int count, MPI_Datatype datatype, MPI_Op op, MPI_Comm comm,
              MPI_Request* request) {
  return start_nonblocking("MPI_Iscan", comm, request,
                           [=] { return MPI_Scan(sendbuf, recvbuf, count, datatype, op, comm); });
}

int MPI_Iexscan(const void* sendbuf, void* recvbuf, int count, MPI_Datatype datatype, MPI_Op op, MPI_Comm comm,
                MPI_Request* request) {
  return start_nonblocking("MPI_Iexscan", comm, request,
                           [=] { return MPI_Exscan(sendbuf, recvbuf, count, datatype, op, comm); });
}

}  // extern "C"
