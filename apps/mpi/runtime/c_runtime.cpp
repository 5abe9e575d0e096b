// The C entry points of the environment (MPI 3.1 chapter 8): start, end, abort, clocks, names,
// and the communicators' sizes and ranks.
#include <cstdio>
#include <cstring>
#include <string>

#include "apps/mpi/c_call.hpp"
#include "apps/mpi/runtime/attributes.hpp"
#include "apps/mpi/runtime/rank.hpp"

using namespace gcsim::mpi_layer;

extern "C" {

int MPI_Init(int* argc, char*** argv) {
  (void)argc;
  (void)argv;
  return runtime_call([](Rank& rank) {
    if (rank.initialized) fail(MPI_ERR_OTHER, "MPI_Init called twice");
    rank.initialized = true;
  });
}

int MPI_Init_thread(int* argc, char*** argv, int required, int* provided) {
  (void)required;
  const int code = MPI_Init(argc, argv);
  if (code == MPI_SUCCESS && provided) *provided = MPI_THREAD_SINGLE;  // one fiber per rank
  return code;
}

int MPI_Query_thread(int* provided) {
  return runtime_call([&](Rank&) { out_arg(provided) = MPI_THREAD_SINGLE; });
}

int MPI_Is_thread_main(int* flag) {
  return runtime_call([&](Rank&) { out_arg(flag) = 1; });
}

int MPI_Finalize(void) {
  return runtime_call([](Rank& rank) {
    if (!rank.initialized || rank.finalized) fail(MPI_ERR_OTHER, "MPI_Finalize without MPI_Init, or twice");
    delete_attributes(rank, MPI_COMM_SELF);  // first, as the standard says (its callbacks may still communicate)
    // As MPI implementations do: no rank leaves while others may still talk to it.
    if (const int code = MPI_Barrier(MPI_COMM_WORLD); code != MPI_SUCCESS) fail(code, "MPI_Finalize: its barrier failed");
    rank.finalize_checks();
    rank.finalized = true;
  });
}

int MPI_Initialized(int* flag) {
  return runtime_call([&](Rank& rank) { out_arg(flag) = rank.initialized ? 1 : 0; });
}

int MPI_Finalized(int* flag) {
  return runtime_call([&](Rank& rank) { out_arg(flag) = rank.finalized ? 1 : 0; });
}

int MPI_Abort(MPI_Comm comm, int errorcode) {
  return runtime_call([&](Rank& rank) {
    (void)comm;  // every rank ends, as Open MPI does for any communicator
    std::fflush(stdout);
    throw AbortRequested{rank.world_rank(), errorcode};
  });
}

double MPI_Wtime(void) {
  double t = 0;
  runtime_call([&](Rank& rank) { t = rank.now_seconds(); });
  return t;
}

double MPI_Wtick(void) { return 1e-12; }  // the simulated clock counts picoseconds

int MPI_Get_processor_name(char* name, int* resultlen) {
  return runtime_call([&](Rank& rank) {
    if (!name) fail(MPI_ERR_ARG, "null name");
    const std::string text = "gc-node-" + std::to_string(rank.node());  // ranks of one node share it
    std::memcpy(name, text.c_str(), text.size() + 1);
    out_arg(resultlen) = static_cast<int>(text.size());
  });
}

int MPI_Comm_size(MPI_Comm comm, int* size) {
  return runtime_call([&](Rank& rank) { out_arg(size) = rank.comm(comm).size(); });
}

int MPI_Comm_rank(MPI_Comm comm, int* rank_out) {
  return runtime_call([&](Rank& rank) { out_arg(rank_out) = rank.comm(comm).rank; });
}

int MPI_Comm_test_inter(MPI_Comm comm, int* flag) {
  return runtime_call([&](Rank& rank) {
    rank.comm(comm);
    out_arg(flag) = 0;  // no intercommunicators
  });
}

}  // extern "C"
