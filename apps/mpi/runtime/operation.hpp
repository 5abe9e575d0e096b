#pragma once
// What stands behind one MPI_Request: an operation's state, and the call that made it as a deadlock
// report or a warning names it. The call is kept as its arguments and formatted only when a text
// is asked for: a rank blocks on nearly every call, but a report is rare.
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "apps/mpi/datatype.hpp"
#include "apps/mpi/include/mpi.h"
#include "parix/processor.hpp"

namespace gcsim::mpi_layer {

class Rank;

// "MPI_Irecv(source=1, tag=0, comm=MPI_COMM_WORLD)", "a collective's receive from rank 3", or a
// text given whole.
struct CallText {
  enum class Form { text, point_to_point, collective_receive };
  Form form = Form::text;
  const char* name = "";             // point_to_point: the entry point's name (a literal: never freed)
  const char* peer_label = "";       // point_to_point: "dest" or "source"
  int peer = 0;                      // a communicator rank, MPI_ANY_SOURCE
  int tag = 0;                       // MPI_ANY_TAG
  MPI_Comm comm = MPI_COMM_WORLD;
  // Form::text; shared, so that a call text is cheap to carry (a collective's sends name one call).
  std::shared_ptr<const std::string> text;

  static CallText of(std::string text) { return shared(std::make_shared<const std::string>(std::move(text))); }
  static CallText shared(std::shared_ptr<const std::string> text) {
    CallText c;
    c.text = std::move(text);
    return c;
  }
  static CallText point_to_point(const char* name, const char* peer_label, int peer, int tag, MPI_Comm comm) {
    CallText c;
    c.form = Form::point_to_point;
    c.name = name;
    c.peer_label = peer_label;
    c.peer = peer;
    c.tag = tag;
    c.comm = comm;
    return c;
  }
  static CallText collective_receive(int peer) {
    CallText c;
    c.form = Form::collective_receive;
    c.peer = peer;
    return c;
  }
  std::string str() const;  // call_text.cpp
  void append_to(std::string& out) const;
};

enum class SendMode { standard, synchronous, buffered, ready };

struct Operation {  // behind one MPI_Request
  bool is_send = false;
  bool done = false;
  bool charged = false;  // a receive's CPU overhead was paid
  MPI_Status status{};
  CallText call;
  std::shared_ptr<const std::vector<int>> members;  // of its communicator: status source ranks
  std::int64_t context = 0;
  int tag = 0;
  int peer_world = -1;  // destination, or source (-1: MPI_ANY_SOURCE)
  MPI_Comm comm = MPI_COMM_WORLD;  // whose error handler its errors go to
  // send
  parix::Bytes payload;   // rendezvous: kept until clear-to-send
  parix::Request wire;    // rendezvous: the data letter, delivered = complete
  // receive: into (buffer, count, *type), or raw into exactly `raw` bytes (collectives). A
  // predefined type is pointed to (it lives for the run); a user's is copied into owned_type, as
  // the program may free it while the receive is pending.
  void* buffer = nullptr;
  MPI_Count count = 0;
  const Datatype* type = nullptr;
  std::unique_ptr<const Datatype> owned_type;  // behind a pointer: most receives have none
  std::span<std::byte> raw;
  bool is_raw = false;
  // A non-blocking collective's request: done when its schedule (collective_progress.hpp) ends.
  bool collective = false;
  // MPI_Request_free of an active one: it runs on unseen and is dropped once done (rank_cancel.cpp).
  bool freed = false;
  bool cancel_asked = false;  // MPI_Cancel of a rendezvous send: the receiver's answer awaited
  // A persistent request (MPI_Send_init ...): each MPI_Start calls `restart`, whose operation is
  // `started` until finished; inactive (MPI_REQUEST_NULL) it completes at once, status empty.
  // Null for every other request; apart, so that a request is quick to make and to reset.
  struct Persistent {
    std::function<MPI_Request(Rank&)> restart;
    MPI_Request started = MPI_REQUEST_NULL;
  };
  std::unique_ptr<Persistent> persistent;
};

}  // namespace gcsim::mpi_layer
