// The C entry points that wait for or test requests, and probes (MPI 3.1 sections 3.7.3-3.7.5, 3.8).
#include <string>
#include <vector>

#include "apps/mpi/c_call.hpp"
#include "apps/mpi/runtime/p2p_arguments.hpp"
#include "apps/mpi/runtime/rank.hpp"
#include "apps/mpi/runtime/operations_wait.hpp"

using namespace gcsim::mpi_layer;

namespace {

// The requests' calls, for a deadlock report of a wait on several.
std::string calls_of(Rank& rank, const char* call, int count, const MPI_Request* rs) {
  std::string text = std::string(call) + " on";
  for (int i = 0; i < count; ++i) {
    if (rs[i] == MPI_REQUEST_NULL) continue;
    text += " ";
    rank.operation(rs[i]).call.append_to(text);
  }
  return text;
}

// Whether Waitany, Testany, Waitsome and Testsome look at a request: not null, and not an
// inactive persistent one (which they skip, as the standard says).
bool counted(Rank& rank, MPI_Request r) { return r != MPI_REQUEST_NULL && !rank.inactive(r); }

// Also refuses a negative count (MPI_ERR_COUNT): every call on an array of requests asks this first.
bool all_null(Rank& rank, int count, const MPI_Request* rs) {
  check_message_count(count);
  for (int i = 0; i < count; ++i) {
    if (counted(rank, rs[i])) return false;
  }
  return true;
}

void empty_status(MPI_Status* status) {
  if (!status) return;
  *status = MPI_Status{};
  status->MPI_SOURCE = MPI_ANY_SOURCE;
  status->MPI_TAG = MPI_ANY_TAG;
}

// Finishes every done request of rs (indices into `finished`); MPI_ERR_IN_STATUS if one failed.
int finish_done(Rank& rank, int count, MPI_Request* rs, MPI_Status* statuses, int* outcount, int* indices) {
  int error = MPI_SUCCESS;
  int n = 0;
  for (int i = 0; i < count; ++i) {
    if (rs[i] == MPI_REQUEST_NULL || (indices && rank.inactive(rs[i])) || !rank.test(rs[i])) continue;
    MPI_Status* st = statuses ? &statuses[indices ? n : i] : nullptr;
    const int e = rank.finish(rs[i], st);
    if (e != MPI_SUCCESS) error = MPI_ERR_IN_STATUS;
    if (indices) indices[n] = i;
    ++n;
  }
  if (outcount) *outcount = n;
  return error;
}

}  // namespace

extern "C" {

int MPI_Wait(MPI_Request* request, MPI_Status* status) {
  int error = MPI_SUCCESS;
  const int code = runtime_call([&](Rank& rank) {
    MPI_Request& h = out_arg(request);
    if (h == MPI_REQUEST_NULL) return empty_status(status);
    const OperationsWait call(rank, "MPI_Wait on ", h);
    rank.wait_until([&] { return rank.test(h); }, "MPI_Wait", call);
    error = rank.finish(h, status);
    fail_with(error);
  });
  return code != MPI_SUCCESS ? code : error;
}

int MPI_Test(MPI_Request* request, int* flag, MPI_Status* status) {
  int error = MPI_SUCCESS;
  const int code = runtime_call([&](Rank& rank) {
    MPI_Request& h = out_arg(request);
    int& done = out_arg(flag);
    done = 1;
    if (h == MPI_REQUEST_NULL) return empty_status(status);
    done = rank.test(h) ? 1 : 0;
    if (done) error = rank.finish(h, status);
    else rank.charge(0);  // a polling loop advances simulated time by o per try
    fail_with(error);
  });
  return code != MPI_SUCCESS ? code : error;
}

int MPI_Waitall(int count, MPI_Request array_of_requests[], MPI_Status array_of_statuses[]) {
  int error = MPI_SUCCESS;
  const int code = runtime_call([&](Rank& rank) {
    check_message_count(count);
    const std::string call = calls_of(rank, "MPI_Waitall", count, array_of_requests);
    rank.wait_until([&] {
      for (int i = 0; i < count; ++i) {
        if (array_of_requests[i] != MPI_REQUEST_NULL && !rank.test(array_of_requests[i])) return false;
      }
      return true;
    }, call);
    for (int i = 0; i < count; ++i) {
      if (array_of_requests[i] == MPI_REQUEST_NULL) {
        if (array_of_statuses) empty_status(&array_of_statuses[i]);
        continue;
      }
      const int e = rank.finish(array_of_requests[i], array_of_statuses ? &array_of_statuses[i] : nullptr);
      if (e != MPI_SUCCESS) error = MPI_ERR_IN_STATUS;
    }
    fail_with(error);
  });
  return code != MPI_SUCCESS ? code : error;
}

int MPI_Testall(int count, MPI_Request array_of_requests[], int* flag, MPI_Status array_of_statuses[]) {
  return runtime_call([&](Rank& rank) {
    int& all = out_arg(flag);
    check_message_count(count);
    all = 1;
    for (int i = 0; i < count; ++i) {
      if (array_of_requests[i] != MPI_REQUEST_NULL && !rank.test(array_of_requests[i])) all = 0;
    }
    if (all) fail_with(finish_done(rank, count, array_of_requests, array_of_statuses, nullptr, nullptr));
    else rank.charge(0);
  });
}

int MPI_Waitany(int count, MPI_Request array_of_requests[], int* index, MPI_Status* status) {
  int error = MPI_SUCCESS;
  const int code = runtime_call([&](Rank& rank) {
    int& which = out_arg(index);
    which = MPI_UNDEFINED;
    if (all_null(rank, count, array_of_requests)) return empty_status(status);
    const std::string call = calls_of(rank, "MPI_Waitany", count, array_of_requests);
    rank.wait_until([&] {
      for (int i = 0; i < count; ++i) {
        if (counted(rank, array_of_requests[i]) && rank.test(array_of_requests[i])) return (which = i), true;
      }
      return false;
    }, call);
    error = rank.finish(array_of_requests[which], status);
    fail_with(error);
  });
  return code != MPI_SUCCESS ? code : error;
}

int MPI_Testany(int count, MPI_Request array_of_requests[], int* index, int* flag, MPI_Status* status) {
  int error = MPI_SUCCESS;
  const int code = runtime_call([&](Rank& rank) {
    int& which = out_arg(index);
    int& found = out_arg(flag);
    which = MPI_UNDEFINED;
    found = all_null(rank, count, array_of_requests) ? 1 : 0;
    if (found) return empty_status(status);
    for (int i = 0; i < count && !found; ++i) {
      if (counted(rank, array_of_requests[i]) && rank.test(array_of_requests[i])) which = i, found = 1;
    }
    if (found) error = rank.finish(array_of_requests[which], status);
    else rank.charge(0);
    fail_with(error);
  });
  return code != MPI_SUCCESS ? code : error;
}

int MPI_Waitsome(int incount, MPI_Request array_of_requests[], int* outcount, int array_of_indices[],
                 MPI_Status array_of_statuses[]) {
  int error = MPI_SUCCESS;
  const int code = runtime_call([&](Rank& rank) {
    int& n = out_arg(outcount);
    if (all_null(rank, incount, array_of_requests)) return (void)(n = MPI_UNDEFINED);
    const std::string call = calls_of(rank, "MPI_Waitsome", incount, array_of_requests);
    rank.wait_until([&] {
      for (int i = 0; i < incount; ++i) {
        if (counted(rank, array_of_requests[i]) && rank.test(array_of_requests[i])) return true;
      }
      return false;
    }, call);
    error = finish_done(rank, incount, array_of_requests, array_of_statuses, &n, array_of_indices);
    fail_with(error);
  });
  return code != MPI_SUCCESS ? code : error;
}

int MPI_Testsome(int incount, MPI_Request array_of_requests[], int* outcount, int array_of_indices[],
                 MPI_Status array_of_statuses[]) {
  int error = MPI_SUCCESS;
  const int code = runtime_call([&](Rank& rank) {
    int& n = out_arg(outcount);
    if (all_null(rank, incount, array_of_requests)) return (void)(n = MPI_UNDEFINED);
    error = finish_done(rank, incount, array_of_requests, array_of_statuses, &n, array_of_indices);
    fail_with(error);
    if (n == 0) rank.charge(0);
  });
  return code != MPI_SUCCESS ? code : error;
}

int MPI_Probe(int source, int tag, MPI_Comm comm, MPI_Status* status) {
  return runtime_call([&](Rank& rank) {
    const Communicator& c = rank.comm(comm);
    check_peer(c, source, true);
    check_tag(tag, true);
    if (source == MPI_PROC_NULL) {
      empty_status(status);
      if (status) status->MPI_SOURCE = MPI_PROC_NULL;
      return;
    }
    const std::string call = "MPI_Probe(source=" + (source == MPI_ANY_SOURCE ? std::string("MPI_ANY_SOURCE") : std::to_string(source)) +
                             ", tag=" + (tag == MPI_ANY_TAG ? std::string("MPI_ANY_TAG") : std::to_string(tag)) +
                             ", comm=" + Rank::comm_name(comm) + ")";
    rank.wait_until([&] { return rank.probe(c, source, tag, status); }, call);
  });
}

int MPI_Iprobe(int source, int tag, MPI_Comm comm, int* flag, MPI_Status* status) {
  return runtime_call([&](Rank& rank) {
    const Communicator& c = rank.comm(comm);
    check_peer(c, source, true);
    check_tag(tag, true);
    int& found = out_arg(flag);
    if (source == MPI_PROC_NULL) {
      found = 1;
      empty_status(status);
      if (status) status->MPI_SOURCE = MPI_PROC_NULL;
      return;
    }
    found = rank.probe(c, source, tag, status) ? 1 : 0;
    if (!found) rank.charge(0);  // a polling loop advances simulated time by o per try
  });
}

}  // extern "C"
