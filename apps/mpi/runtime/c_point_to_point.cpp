// The C entry points that start and finish point-to-point messages (MPI 3.1 chapter 3).
#include <string>
#include <vector>

#include "apps/mpi/c_call.hpp"
#include "apps/mpi/runtime/p2p_arguments.hpp"
#include "apps/mpi/runtime/operations_wait.hpp"
#include "apps/mpi/runtime/rank.hpp"
#include "apps/mpi/type_transfer.hpp"

using namespace gcsim::mpi_layer;
namespace parix = gcsim::parix;

namespace {

// MPI_PROC_NULL: complete at once, source MPI_PROC_NULL, tag MPI_ANY_TAG, no bytes.
MPI_Request done_request(Rank& rank, const char* call) { return rank.start_null(call); }

// What a send's request, or a deadlock report in its place, names: "MPI_Send(dest=1, tag=0, ...)".
CallText send_call(const char* call, int dest, int tag, MPI_Comm comm) {
  return CallText::point_to_point(call, "dest", dest, tag, comm);
}

// request_if_done: see Rank::start_send (false: an eager send returns MPI_REQUEST_NULL).
MPI_Request start_send(Rank& rank, const void* buf, int count, MPI_Datatype datatype, int dest, int tag, MPI_Comm comm,
                       SendMode mode, const char* call, bool request_if_done = true) {
  const Communicator& c = rank.comm(comm);
  check_message_count(count);
  check_peer(c, dest, false);
  check_tag(tag, false);
  const Datatype& type = datatype_arg(rank.registry(), datatype, true);
  check_message_buffer(buf, count, datatype);
  if (dest == MPI_PROC_NULL) return done_request(rank, call);
  // A contiguous buffer is the packed payload itself; any other is packed into the rank's scratch.
  std::span<const std::byte> payload = contiguous_bytes(buf, count, type);
  if (payload.data() == nullptr && pack_size(count, type) > 0) {
    parix::Bytes& packed = rank.send_scratch();
    packed.resize(static_cast<std::size_t>(pack_size(count, type)));
    MPI_Count position = 0;
    pack(buf, count, type, packed, position);
    payload = packed;
  }
  if (mode == SendMode::buffered && static_cast<MPI_Count>(payload.size()) > rank.attached_size) {
    fail(MPI_ERR_BUFFER, "MPI_Bsend: the attached buffer is too small for the message");
  }
  return rank.start_send(c, c.context, dest, tag, payload, mode, send_call(call, dest, tag, comm), request_if_done);
}

MPI_Request start_recv(Rank& rank, void* buf, int count, MPI_Datatype datatype, int source, int tag, MPI_Comm comm,
                       const char* call) {
  const Communicator& c = rank.comm(comm);
  check_message_count(count);
  check_peer(c, source, true);
  check_tag(tag, true);
  const Datatype& type = datatype_arg(rank.registry(), datatype, true);
  check_message_buffer(buf, count, datatype);
  if (source == MPI_PROC_NULL) return done_request(rank, call);
  return rank.start_recv(c, c.context, source, tag, buf, count, type, CallText::point_to_point(call, "source", source, tag, comm));
}

int wait_for(Rank& rank, MPI_Request& h, MPI_Status* status, const char* name) {
  const OperationsWait call(rank, "", h);
  rank.wait_until([&] { return rank.test(h); }, name, call);
  return rank.finish(h, status);
}

int blocking_send(const void* buf, int count, MPI_Datatype datatype, int dest, int tag, MPI_Comm comm, SendMode mode,
                  const char* call) {
  int error = MPI_SUCCESS;
  const int code = runtime_call_as(call, [&](Rank& rank) {
    MPI_Request h = start_send(rank, buf, count, datatype, dest, tag, comm, mode, call, false);
    if (h == MPI_REQUEST_NULL) {  // eager: complete; the wait's progress still answers what arrived
      rank.progress();
      return;
    }
    error = wait_for(rank, h, MPI_STATUS_IGNORE, call);
    fail_with(error);
  });
  return code != MPI_SUCCESS ? code : error;
}

int nonblocking_send(const void* buf, int count, MPI_Datatype datatype, int dest, int tag, MPI_Comm comm, SendMode mode,
                     const char* call, MPI_Request* request) {
  return runtime_call_as(call, [&](Rank& rank) {
    out_arg(request) = start_send(rank, buf, count, datatype, dest, tag, comm, mode, call);
  });
}

}  // namespace

extern "C" {

int MPI_Send(const void* buf, int count, MPI_Datatype datatype, int dest, int tag, MPI_Comm comm) {
  return blocking_send(buf, count, datatype, dest, tag, comm, SendMode::standard, "MPI_Send");
}
int MPI_Ssend(const void* buf, int count, MPI_Datatype datatype, int dest, int tag, MPI_Comm comm) {
  return blocking_send(buf, count, datatype, dest, tag, comm, SendMode::synchronous, "MPI_Ssend");
}
int MPI_Rsend(const void* buf, int count, MPI_Datatype datatype, int dest, int tag, MPI_Comm comm) {
  return blocking_send(buf, count, datatype, dest, tag, comm, SendMode::ready, "MPI_Rsend");
}
int MPI_Bsend(const void* buf, int count, MPI_Datatype datatype, int dest, int tag, MPI_Comm comm) {
  return blocking_send(buf, count, datatype, dest, tag, comm, SendMode::buffered, "MPI_Bsend");
}
int MPI_Isend(const void* buf, int count, MPI_Datatype datatype, int dest, int tag, MPI_Comm comm, MPI_Request* request) {
  return nonblocking_send(buf, count, datatype, dest, tag, comm, SendMode::standard, "MPI_Isend", request);
}
int MPI_Issend(const void* buf, int count, MPI_Datatype datatype, int dest, int tag, MPI_Comm comm, MPI_Request* request) {
  return nonblocking_send(buf, count, datatype, dest, tag, comm, SendMode::synchronous, "MPI_Issend", request);
}
int MPI_Ibsend(const void* buf, int count, MPI_Datatype datatype, int dest, int tag, MPI_Comm comm, MPI_Request* request) {
  return nonblocking_send(buf, count, datatype, dest, tag, comm, SendMode::buffered, "MPI_Ibsend", request);
}
int MPI_Irsend(const void* buf, int count, MPI_Datatype datatype, int dest, int tag, MPI_Comm comm, MPI_Request* request) {
  return nonblocking_send(buf, count, datatype, dest, tag, comm, SendMode::ready, "MPI_Irsend", request);
}

int MPI_Recv(void* buf, int count, MPI_Datatype datatype, int source, int tag, MPI_Comm comm, MPI_Status* status) {
  int error = MPI_SUCCESS;
  const int code = runtime_call([&](Rank& rank) {
    MPI_Request h = start_recv(rank, buf, count, datatype, source, tag, comm, "MPI_Recv");
    error = wait_for(rank, h, status, "MPI_Recv");
    fail_with(error);
  });
  return code != MPI_SUCCESS ? code : error;
}

int MPI_Irecv(void* buf, int count, MPI_Datatype datatype, int source, int tag, MPI_Comm comm, MPI_Request* request) {
  return runtime_call([&](Rank& rank) { out_arg(request) = start_recv(rank, buf, count, datatype, source, tag, comm, "MPI_Irecv"); });
}

int MPI_Sendrecv(const void* sendbuf, int sendcount, MPI_Datatype sendtype, int dest, int sendtag, void* recvbuf,
                 int recvcount, MPI_Datatype recvtype, int source, int recvtag, MPI_Comm comm, MPI_Status* status) {
  int error = MPI_SUCCESS;
  const int code = runtime_call([&](Rank& rank) {
    MPI_Request r = start_recv(rank, recvbuf, recvcount, recvtype, source, recvtag, comm, "MPI_Sendrecv");
    MPI_Request s = start_send(rank, sendbuf, sendcount, sendtype, dest, sendtag, comm, SendMode::standard, "MPI_Sendrecv", false);
    // An eager send has no request (complete): a deadlock report still names it.
    const CallText sent = send_call("MPI_Sendrecv", dest, sendtag, comm);
    const OperationsWait call(rank, "", r, s, s == MPI_REQUEST_NULL ? &sent : nullptr);
    rank.wait_until([&] { return (s == MPI_REQUEST_NULL || rank.test(s)) && rank.test(r); }, "MPI_Sendrecv", call);
    if (s != MPI_REQUEST_NULL) rank.finish(s, MPI_STATUS_IGNORE);
    error = rank.finish(r, status);
    fail_with(error);
  });
  return code != MPI_SUCCESS ? code : error;
}

int MPI_Sendrecv_replace(void* buf, int count, MPI_Datatype datatype, int dest, int sendtag, int source, int recvtag,
                         MPI_Comm comm, MPI_Status* status) {
  int error = MPI_SUCCESS;
  const int code = runtime_call([&](Rank& rank) {
    // The send packs buf before the receive may write it.
    MPI_Request s = start_send(rank, buf, count, datatype, dest, sendtag, comm, SendMode::standard, "MPI_Sendrecv_replace");
    MPI_Request r = start_recv(rank, buf, count, datatype, source, recvtag, comm, "MPI_Sendrecv_replace");
    const OperationsWait call(rank, "", r, s);
    rank.wait_until([&] { return rank.test(s) && rank.test(r); }, "MPI_Sendrecv_replace", call);
    rank.finish(s, MPI_STATUS_IGNORE);
    error = rank.finish(r, status);
    fail_with(error);
  });
  return code != MPI_SUCCESS ? code : error;
}

int MPI_Buffer_attach(void* buffer, int size) {
  return runtime_call([&](Rank& rank) {
    if (size < 0) fail(MPI_ERR_ARG, "negative buffer size");
    if (rank.attached_buffer) fail(MPI_ERR_BUFFER, "a buffer is attached already");
    rank.attached_buffer = buffer;
    rank.attached_size = size;
  });
}

int MPI_Buffer_detach(void* buffer_addr, int* size) {
  return runtime_call([&](Rank& rank) {
    if (!buffer_addr) fail(MPI_ERR_ARG, "null buffer address");
    *static_cast<void**>(buffer_addr) = rank.attached_buffer;
    out_arg(size) = rank.attached_size;
    rank.attached_buffer = nullptr;
    rank.attached_size = 0;
  });
}

}  // extern "C"
