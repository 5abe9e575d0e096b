#pragma once
// One outstanding non-blocking collective, progressing as an MPI library without a progress
// thread progresses it: its blocking form (the same schedule, the same checks) runs on a stack of
// its own, a coroutine driven by the rank's own fiber. Where the blocking form would wait for its
// messages (RankChannel::wait_all) the coroutine yields back to the rank instead, naming the
// requests it waits for; the rank resumes it at every MPI call that progresses (tests, waits,
// probes, sends and receives) once those requests are complete, and whenever a letter wakes the
// rank from a wait on anything else. Its sends and receives are the rank's own point-to-point
// messages on the communicator's collective context, so the machine model costs them as any
// others, on the rank's node CPU (o + G n per message, the reduction's cost) while the program
// computes in between.
//
// Why a coroutine and not a processor thread (Processor::spawn): the post office wakes one
// waiter per processor, so a second fiber of the rank waiting for letters would take the rank's
// wake-ups. Only the rank's fiber ever waits here; the coroutine never blocks on letters.
// Why not a state machine per algorithm: it would restate every schedule of
// collective_algorithms.hpp a second time; the coroutine runs exactly the blocking one.
#include <exception>
#include <functional>
#include <vector>

#include <boost/context/fiber.hpp>

#include "apps/mpi/include/mpi.h"

namespace gcsim::mpi_layer {

class Rank;

class CollectiveProgress {
 public:
  // run: the blocking form, returning its error code; it starts at the first resume().
  CollectiveProgress(Rank& rank, MPI_Request request, std::function<int()> run);
  ~CollectiveProgress();
  CollectiveProgress(const CollectiveProgress&) = delete;
  CollectiveProgress& operator=(const CollectiveProgress&) = delete;

  MPI_Request request() const { return request_; }
  bool finished() const { return finished_; }
  int code() const { return code_; }  // the blocking form's error code, once finished
  // Whether resuming would get further: every request it waits for is complete.
  bool ready() const;
  // From the rank's fiber: runs the schedule until it waits for a request not complete, or ends.
  // What the blocking form threw (an abandoned run, MPI_Abort) is rethrown here.
  void resume();
  // From inside the schedule: back to the rank until `waiting` are complete.
  void yield(const std::vector<MPI_Request>& waiting);

 private:
  // The nesting depths of the rank's MPI call (error scope, compute meter, trace span): the
  // schedule's frames are counted in them only while it runs.
  struct Depths {
    int call = 0, meter = 0, span = 0;
  };
  Depths depths() const;
  void set_depths(const Depths& d);
  void switch_in(int extra);  // the caller's depths plus the schedule's own, saved at its last yield
  void switch_out();

  Rank& rank_;
  MPI_Request request_;
  std::function<int()> run_;
  boost::context::fiber fiber_;   // the schedule, while it waits
  boost::context::fiber caller_;  // the rank's side, while the schedule runs
  std::vector<MPI_Request> waiting_;
  Depths outer_{}, own_{};  // the caller's depths at resume; the schedule's levels above them
  bool finished_ = false;
  int code_ = MPI_SUCCESS;
  std::exception_ptr thrown_;
};

}  // namespace gcsim::mpi_layer
