// The C entry points of persistent requests, MPI_Request_free and MPI_Cancel (MPI 3.1 sections
// 3.7.3, 3.8.4, 3.9); the rank does the work (rank_persistent.cpp, rank_cancel.cpp).
#include <algorithm>
#include <string>

#include "apps/mpi/c_call.hpp"
#include "apps/mpi/runtime/rank.hpp"

using namespace gcsim::mpi_layer;

namespace {

using Starter = int (*)(void*, int, MPI_Datatype, int, int, MPI_Comm, MPI_Request*);

// A persistent request whose MPI_Start calls `start` (MPI_Isend ... MPI_Irecv) with these
// arguments; the arguments that need no peer are checked now, the rest at each start.
int make_persistent(const char* call, Starter start, const void* buf, int count, MPI_Datatype datatype, int peer,
                    int tag, MPI_Comm comm, MPI_Request* request) {
  return runtime_call([&](Rank& rank) {
    MPI_Request& out = out_arg(request);
    rank.comm(comm);
    check_count_arg(count);
    datatype_arg(rank.registry(), datatype, true);
    void* buffer = const_cast<void*>(buf);  // a send's start only reads it
    const std::string name = call;
    auto restart = [=](Rank& r) {
      MPI_Request started = MPI_REQUEST_NULL;
      if (const int code = start(buffer, count, datatype, peer, tag, comm, &started); code != MPI_SUCCESS) {
        fail(code, ("MPI_Start: starting " + name + " failed").c_str());
      }
      CallText& described = r.operation(started).call;  // "MPI_Isend(dest=...)": name the init call
      if (described.form == CallText::Form::point_to_point) {
        described.name = call;  // a literal, as the entry point's own name
      } else {
        const std::string was = described.str();
        described = CallText::of(name + was.substr(std::min(was.find('('), was.size())));
      }
      return started;
    };
    out = rank.add_persistent(name, std::move(restart));
  });
}

int send_isend(void* b, int n, MPI_Datatype t, int p, int tag, MPI_Comm c, MPI_Request* r) { return MPI_Isend(b, n, t, p, tag, c, r); }
int send_ibsend(void* b, int n, MPI_Datatype t, int p, int tag, MPI_Comm c, MPI_Request* r) { return MPI_Ibsend(b, n, t, p, tag, c, r); }
int send_issend(void* b, int n, MPI_Datatype t, int p, int tag, MPI_Comm c, MPI_Request* r) { return MPI_Issend(b, n, t, p, tag, c, r); }
int send_irsend(void* b, int n, MPI_Datatype t, int p, int tag, MPI_Comm c, MPI_Request* r) { return MPI_Irsend(b, n, t, p, tag, c, r); }

}  // namespace

extern "C" {

int MPI_Send_init(const void* buf, int count, MPI_Datatype datatype, int dest, int tag, MPI_Comm comm, MPI_Request* request) {
  return make_persistent("MPI_Send_init", send_isend, buf, count, datatype, dest, tag, comm, request);
}
int MPI_Bsend_init(const void* buf, int count, MPI_Datatype datatype, int dest, int tag, MPI_Comm comm, MPI_Request* request) {
  return make_persistent("MPI_Bsend_init", send_ibsend, buf, count, datatype, dest, tag, comm, request);
}
int MPI_Ssend_init(const void* buf, int count, MPI_Datatype datatype, int dest, int tag, MPI_Comm comm, MPI_Request* request) {
  return make_persistent("MPI_Ssend_init", send_issend, buf, count, datatype, dest, tag, comm, request);
}
int MPI_Rsend_init(const void* buf, int count, MPI_Datatype datatype, int dest, int tag, MPI_Comm comm, MPI_Request* request) {
  return make_persistent("MPI_Rsend_init", send_irsend, buf, count, datatype, dest, tag, comm, request);
}
int MPI_Recv_init(void* buf, int count, MPI_Datatype datatype, int source, int tag, MPI_Comm comm, MPI_Request* request) {
  return make_persistent("MPI_Recv_init", MPI_Irecv, buf, count, datatype, source, tag, comm, request);
}

int MPI_Start(MPI_Request* request) {
  return runtime_call([&](Rank& rank) { rank.start_persistent(out_arg(request)); });
}

int MPI_Startall(int count, MPI_Request array_of_requests[]) {
  return runtime_call([&](Rank& rank) {
    if (count < 0) fail(MPI_ERR_COUNT, "MPI_Startall: negative count");
    if (count > 0 && !array_of_requests) fail(MPI_ERR_ARG, "MPI_Startall: null array of requests");
    for (int i = 0; i < count; ++i) rank.start_persistent(array_of_requests[i]);
  });
}

int MPI_Request_free(MPI_Request* request) {
  return runtime_call([&](Rank& rank) {
    MPI_Request& h = out_arg(request);
    if (h == MPI_REQUEST_NULL) fail(MPI_ERR_REQUEST, "MPI_Request_free: a null request");
    rank.free_request(h);
    h = MPI_REQUEST_NULL;
  });
}

int MPI_Cancel(MPI_Request* request) {
  return runtime_call([&](Rank& rank) {
    const MPI_Request h = out_arg(request);
    if (h == MPI_REQUEST_NULL) fail(MPI_ERR_REQUEST, "MPI_Cancel: a null request");
    rank.cancel(h);
  });
}

}  // extern "C"
