#pragma once
// One MPI rank of `gcsim mpirun`: its communicators, its requests and the matching of messages to
// receives, over the runtime's addressed messages (parix/mailbox.hpp). Protocol:
//  - eager: one letter with the data (standard sends up to [mpi] eager_limit_bytes, Bsend, Rsend);
//    the send is complete once handed over;
//  - rendezvous: a request-to-send letter (size, no data); the receiver answers clear-to-send when
//    a receive matches it; then the data letter, whose delivery completes the send (standard
//    sends above the limit, and every Ssend: complete only once matched).
// Receives match in posting order, arrivals in arrival order (which keeps each sender's order), by
// (source, tag, context) with MPI_ANY_SOURCE/MPI_ANY_TAG. A rank progresses only inside its own
// MPI calls, as an MPI library without a progress thread does. CPU overheads ([mpi] o and G) are
// charged per send call and per completed receive.
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <source_location>
#include <string_view>
#include <type_traits>
#include <span>
#include <string>
#include <vector>

#include "apps/mpi/collective_selection.hpp"
#include "apps/mpi/datatype.hpp"
#include "apps/mpi/error.hpp"
#include "apps/mpi/registry.hpp"
#include "apps/mpi/runtime/call_span.hpp"
#include "apps/mpi/runtime/collective_progress.hpp"
#include "apps/mpi/runtime/compute_meter.hpp"
#include "apps/mpi/runtime/communicator.hpp"
#include "apps/mpi/runtime/keyvals.hpp"
#include "apps/mpi/runtime/operation.hpp"
#include "apps/mpi/runtime/operation_table.hpp"
#include "machine/machine_config.hpp"
#include "parix/mailbox.hpp"
#include "parix/processor.hpp"

namespace gcsim::mpi_layer {

class CollectiveLedger;

// MPI_Abort: unwinds the rank's program; `gcsim mpirun` exits with the code.
struct AbortRequested {
  int rank;
  int code;
};

class Rank {
 public:
  // world: MPI_COMM_WORLD's members 0..N-1, one vector shared by every rank of a run (4096 ranks
  // would otherwise hold 64 MiB of copies); made here when not given.
  Rank(parix::Processor& processor, const machine::MachineConfig::Mpi& costs,
       std::shared_ptr<const std::vector<int>> world = nullptr);

  // The rank whose fiber runs now; MPI_ERR_OTHER outside `gcsim mpirun`.
  static Rank& current();
  // Makes this the current rank (and its registry the C calls' one); done as its fiber resumes.
  void install();
  // Called before the rank blocks or yields (the output capture attributes what it printed), once
  // per MPI call: only the program prints, and it runs only between MPI calls.
  std::function<void()> before_switch;

  int world_rank() const { return processor_.id(); }
  int world_size() const { return processor_.count(); }
  // The simulated node a rank runs on (gcsim mpirun --ranks-per-node K: world rank r on r / K).
  int node() const { return mailbox_.node_of(world_rank()); }
  int node_of(int world_rank) const { return mailbox_.node_of(world_rank); }
  double now_seconds() const { return processor_.now_seconds(); }
  Registry& registry() { return registry_; }
  RankCompute computing;  // --compute: its settings, CPU meter and sampled sites (compute_meter.hpp)
  AlgorithmChoice collective_algorithms;  // gcsim mpirun --coll; Auto: MPICH's selection
  CollectiveLedger* collective_ledger = nullptr;  // the run's, shared by its ranks; null: not checked
  bool initialized = false;
  bool finalized = false;
  CallSpan call_span;  // the MPI call in progress, as the trace names it

  Communicator& comm(MPI_Comm handle);  // MPI_ERR_COMM if it names none
  MPI_Comm add_comm(Communicator c);
  void free_comm(MPI_Comm handle);
  static std::string comm_name(MPI_Comm handle);

  // Point-to-point on comm's context (or its collective one). Return the request handle.
  // The payload is copied (posted, or kept until a rendezvous' clear-to-send). A send complete at
  // once (eager) gets no request when request_if_done is false (MPI_Send, MPI_Sendrecv, which
  // finish it in the same call): MPI_REQUEST_NULL, nothing to find, test or free.
  MPI_Request start_send(const Communicator& c, std::int64_t context, int dest, int tag,
                         std::span<const std::byte> payload, SendMode mode, CallText call, bool request_if_done = true);
  MPI_Request start_recv(const Communicator& c, std::int64_t context, int source, int tag, void* buffer, MPI_Count count,
                         const Datatype& type, CallText call);
  MPI_Request start_raw_recv(const Communicator& c, std::int64_t context, int source, int tag, std::span<std::byte> into);
  // A non-blocking collective on the collective context `context`: `run`, its blocking form,
  // starts now and progresses at the rank's later calls (rank_nonblocking_collectives.cpp).
  MPI_Request start_collective(std::string call, std::int64_t context, std::function<int()> run);
  // The non-blocking collective whose schedule runs now (its waits yield to the rank), or null.
  CollectiveProgress* running_schedule() const { return running_schedule_; }
  // A request complete at once, as a communication with MPI_PROC_NULL is.
  MPI_Request start_null(std::string call);
  Operation& operation(MPI_Request handle);  // MPI_ERR_REQUEST if it names none
  const Operation* find_operation(MPI_Request handle) const { return operations_.find(handle); }
  // A send's packed payload, reused from call to call (its bytes are copied by start_send).
  parix::Bytes& send_scratch() { return send_scratch_; }
  // Persistent requests, MPI_Request_free and MPI_Cancel (rank_persistent.cpp, rank_cancel.cpp).
  MPI_Request add_persistent(std::string call, std::function<MPI_Request(Rank&)> restart);
  void start_persistent(MPI_Request handle);  // MPI_ERR_REQUEST if not persistent or still active
  bool inactive(MPI_Request handle);          // a persistent request not started
  void free_request(MPI_Request handle);
  void cancel(MPI_Request handle);
  // Finishes handle (done): its status, its error; the handle is freed.
  int finish(MPI_Request& handle, MPI_Status* status);
  // Blocks until done(); `name` is the call the trace names ("MPI_Recv"), `call` describes the wait
  // in a deadlock report. done is any callable returning bool, called in place (no std::function).
  template <class Done>
  void wait_until(Done&& done, std::string_view name, const parix::WaitDescription& call) {
    wait_loop({[](void* f) { return static_cast<bool>((*static_cast<std::remove_reference_t<Done>*>(f))()); },
               const_cast<void*>(static_cast<const void*>(&done))},
              name, call);
  }
  // The same, with a fixed text naming the wait.
  template <class Done>
  void wait_until(Done&& done, const std::string& call) {
    const FixedWait text(call);
    wait_until(std::forward<Done>(done), call_name(call), text);
  }
  // Takes what arrived and answers it; completes rendezvous sends whose data was delivered. Does
  // nothing when nothing can have changed since the last one: the rank has not resumed from a
  // switch, entered a call, posted a receive or started an operation (tests call it often).
  void progress();
  bool test(MPI_Request handle);  // progress, then whether it is done (and its receive charged)
  // The first unexpected message matching (source, tag, context): status filled, nothing taken.
  bool probe(const Communicator& c, int source, int tag, MPI_Status* status);

  void charge(std::int64_t bytes);  // o + G * bytes, as communication
  void charge_reduction(std::size_t bytes);
  // Computation (rank_compute.cpp): annotated seconds or flops (nothing under --compute none), node
  // seconds charged as they are, and the marks of a call's entry and exit that --compute measured uses.
  void compute(double seconds);
  void compute_flops(double flops);
  void charge_compute(double node_seconds, const char* what);
  void start_computing();
  void enter_call();
  void leave_call();
  void finalize_checks();

  void* attached_buffer = nullptr;
  int attached_size = 0;
  Keyvals keyvals;  // attribute keys (c_attributes.cpp)

 private:
  struct Arrived {  // an eager message or a request-to-send, not matched yet
    int source = -1;
    std::int64_t context = 0;
    int tag = 0;
    bool rendezvous = false;
    std::int64_t size = 0;
    std::int64_t sender_op = 0;
    parix::Bytes data;
  };
  struct Predicate {
    bool (*test)(void*);
    void* object;
  };
  struct FixedWait final : parix::WaitDescription {
    const std::string& call;
    explicit FixedWait(const std::string& c) : call(c) {}
    std::string text() const override { return call; }
  };
  void wait_loop(Predicate done, std::string_view name, const parix::WaitDescription& call);
  void name_call_span(const CallText& call);  // the trace's name of the call it is part of
  void advance_collectives();  // resumes every schedule whose awaited requests are complete
  void run_schedule(CollectiveProgress& schedule);
  void drop_finished_schedules();
  void on_cancel_asked(const parix::Letter& l);
  void on_cancel_answered(const parix::Letter& l);
  void drop_freed();
  int finish_persistent(Operation& p, MPI_Status* status);
  void leave_cpu();  // before a switch: the program's output since the last MPI call is attributed
  void on_letter(parix::Letter& l);
  void on_message(Arrived&& m);
  void match(Operation& r, MPI_Request handle, Arrived&& m);
  void deliver(Operation& r, std::span<const std::byte> data);
  static bool matches(const Operation& r, const Arrived& m);
  MPI_Request add_operation(Operation op);

  parix::Processor& processor_;
  parix::Mailbox& mailbox_;
  std::string name_;  // "rank 3", for a stack overflow's message
  machine::MachineConfig::Mpi costs_;
  Registry registry_;
  std::map<MPI_Comm, Communicator> comms_;
  Communicator* world_ = nullptr;  // comms_'s MPI_COMM_WORLD (a map's entries never move)
  MPI_Comm next_comm_ = first_user_handle;
  OperationTable operations_;
  std::size_t freed_live_ = 0;  // operations MPI_Request_free left running (dropped once done)
  parix::Bytes send_scratch_;
  std::vector<MPI_Request> posted_;  // receives waiting for a message, in posting order
  std::vector<Arrived> unexpected_;  // messages waiting for a receive, in arrival order
  std::vector<parix::Letter> letters_;
  // Set as the program enters an MPI call (current()), cleared once its output is attributed: a
  // call's later switches have nothing new to attribute (the program has not run since).
  bool program_ran_ = true;
  bool progress_due_ = true;  // see progress()
  std::size_t sends_on_wire_ = 0;  // at least the rendezvous sends whose data letter is not delivered
  // Outstanding non-blocking collectives in start order; last, so they unwind while the rest lives.
  std::vector<std::unique_ptr<CollectiveProgress>> schedules_;
  CollectiveProgress* running_schedule_ = nullptr;
};

// A C entry point that may block: what the core throws (Error) goes through the error handler of
// the communicator it names (c_call.hpp), then is returned; anything else (the runtime unwinding an
// abandoned run, MPI_Abort, a fatal error) goes on up through the program.
template <class F>
int runtime_call_as(const char* call, F&& body) {
  CallScope scope(current_registry(), call);
  try {
    Rank& rank = Rank::current();
    struct InCall {  // the rank's CPU time since its last call is charged first (--compute measured)
      Rank& rank;
      explicit InCall(Rank& r) : rank(r) { rank.enter_call(); }
      ~InCall() { rank.leave_call(); }
    } in_call{rank};
    struct Span {  // closed also when the call fails or the run is abandoned
      CallSpan& span;
      explicit Span(CallSpan& s) : span(s) { span.enter(); }
      ~Span() { span.leave(); }
    } span(rank.call_span);
    body(rank);
    return MPI_SUCCESS;
  } catch (const Error& e) {
    return scope.raise(e);
  }
}
template <class F>
int runtime_call(F&& body, std::source_location where = std::source_location::current()) {
  return runtime_call_as(where.function_name(), std::forward<F>(body));
}
// A call that ends with an error code (a request's status) raises it as the core's errors are.
inline void fail_with(int code) {
  if (code == MPI_SUCCESS) return;
  const std::string_view text = error_text(code);
  fail(code, std::string(text.substr(text.find(": ") + 2)).c_str());
}

// The simulated node a world rank runs on (MPI_Comm_split_type's MPI_COMM_TYPE_SHARED): rank r on
// node r / K under --ranks-per-node K.
inline int node_of_world_rank(const Rank& rank, int world_rank) { return rank.node_of(world_rank); }

}  // namespace gcsim::mpi_layer
