#pragma once
// What a trace says of the MPI call a rank is in: its name, the peer and the bytes, put on every
// record the call leaves on the rank's track (its CPU overheads and the time it is blocked), so a
// timeline names MPI_Send, MPI_Recv, MPI_Sendrecv, MPI_Allreduce, MPI_Wait ... The outermost C
// entry point opens the span (runtime_call); the first description the call hands the rank names
// it ("MPI_Wait on MPI_Irecv(source=1, ...)" is an MPI_Wait).
#include <cstdint>
#include <string>
#include <string_view>

namespace gcsim::mpi_layer {

// The identifier a call's description starts with: "MPI_Recv(source=1, ...)" -> "MPI_Recv".
std::string_view call_name(std::string_view description);

class CallSpan {
 public:
  CallSpan() = default;
  CallSpan(const CallSpan&) = delete;  // its name may point into its own storage
  CallSpan& operator=(const CallSpan&) = delete;
  // A C entry point begins or ends; only the outermost one opens and closes the span.
  void enter();
  void leave();
  // How many entry points are open; a non-blocking collective's schedule counts its own only
  // while it runs (collective_progress.hpp).
  int depth() const { return depth_; }
  void set_depth(int depth) { depth_ = depth; }
  // A description of what the call does names it, unless an earlier one did.
  void describe(std::string_view description);
  // The same with the call's name itself ("MPI_Recv"), not a description to take it from.
  void name(std::string_view call_name) {
    if (depth_ > 0 && name_.empty()) name_ = owned_.assign(call_name);
  }
  // The same with a name that lives for the run (a literal: kept as it is, not copied).
  void name_literal(const char* call_name) {
    if (depth_ > 0 && name_.empty()) name_ = call_name;
  }
  // An operation of the call with this peer (world rank; -1: any). The traced peer is the one the
  // call receives from (what it waits for), else the one it sends to; none when there are several.
  void involve(int peer, bool receives);
  void add_sent(std::int64_t bytes) { sent_ += bytes; }
  void add_received(std::int64_t bytes) { received_ += bytes; }  // a receive posted (its capacity)
  void note_received(std::int64_t bytes) { received_ = received_ > 0 ? received_ : bytes; }  // one completed

  // The call's name, or `fallback` outside a named call.
  std::string_view label(std::string_view fallback) const { return name_.empty() ? fallback : name_; }
  int peer() const { return receives_.any ? receives_.peer() : sends_.peer(); }
  // What the call sends, or (a receive) what it can receive, or received.
  std::int64_t bytes() const { return sent_ > 0 ? sent_ : received_; }

 private:
  int depth_ = 0;
  std::string_view name_;  // a literal, or owned_
  std::string owned_;
  struct Peers {
    bool any = false;
    int first = -1;
    bool several = false;
    void add(int p);
    int peer() const { return several ? -1 : first; }
  };
  Peers receives_, sends_;
  std::int64_t sent_ = 0;
  std::int64_t received_ = 0;
};

}  // namespace gcsim::mpi_layer
