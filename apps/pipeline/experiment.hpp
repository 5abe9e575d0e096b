#pragma once
// An experiment: one application with its options parsed and its scene loaded and checked, ready
// to run on any number of nodes. The pipeline runs it (run_experiment) on the backend the options
// name; the application only says what each processor does and what it reports.
//
// State rule (so that a distributed backend gives the same answers): a processor may write into
// the Outcome only (a) node 0, the results it assembled from what it received, or (b) its own
// per-node slot of check data that the program does not send (counters, primary-hit ids); no
// processor reads another's slot. A distributed backend gathers the slots after the run, outside
// the measured time, as the simulated one leaves them where they were written.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/pipeline/resource_check.hpp"
#include "apps/pipeline/run_provenance.hpp"
#include "apps/pipeline/sweep_table.hpp"
#include "parix/backend.hpp"

namespace gcsim::pipeline {

// What one run produced: the backend's figures, and the application's result beside them.
struct Outcome {
  virtual ~Outcome() = default;
  parix::RunResult run;
  parix::RunOptions options;  // what it ran on: the backend and the machine
};

class Experiment {
 public:
  virtual ~Experiment() = default;
  // An empty outcome for a run on `nodes` processors (per-node slots sized).
  virtual std::unique_ptr<Outcome> new_outcome(int nodes) const = 0;
  // The per-processor program of one run, writing its result into out (see the state rule above).
  virtual parix::Program program(Outcome& out) const = 0;
  // Host-side work after the run: merges per-node slots, sums counters.
  virtual void after_run(Outcome& out) const {}

  // Resources checked before new_outcome allocates anything (resource_check.hpp): what the
  // fullest node holds by kind (and which processor that is), and the host bytes of a run.
  virtual std::vector<MemoryNeed> node_memory(int nodes, int* processor) const { return {}; }
  virtual std::int64_t host_memory(int nodes) const { return 0; }

  // gcsim run APP: lines printed before the run, and the report after it (text on stdout,
  // JSON fields merged into --json's document).
  virtual void print_setup(int nodes) const {}
  virtual void report(const Outcome& out, nlohmann::json& extra) const {}
  // Checks, before any run, that the files the report will write can be written (throws FileError).
  virtual void check_outputs() const {}
  // The scene, seeds and files (images, CSVs) of a run, for its JSON's provenance block.
  virtual RunInputs run_inputs() const { return {}; }
  // Why a finished run did not do what was asked (e.g. a threshold not reached), or nothing: the
  // command then exits with kExitRunFailed after writing every output.
  virtual std::optional<std::string> goal_missed(const Outcome& out) const { return std::nullopt; }
  // What an interrupted run had finished (e.g. tiles rendered, loops done), as JSON fields; the
  // outcome holds only what the host saw so far.
  virtual void report_interrupted(const Outcome& out, nlohmann::json& reached) const {}

  // gcsim sweep APP: lines printed before the table, and the table's columns (default: nodes,
  // simulated seconds, speedup, communication, wall seconds; see sweep.hpp).
  virtual void print_sweep_setup() const {}
  virtual std::unique_ptr<SweepTable> sweep_table() const;
};

// Runs e once with the backend and simulation options of `options`.
// With `reached` given, an interruption first fills it by e.report_interrupted, then propagates.
std::unique_ptr<Outcome> run_experiment(const Experiment& e, const parix::RunOptions& options,
                                        nlohmann::json* reached = nullptr);

// The application's outcome type behind an Outcome the experiment made.
template <class T>
const T& outcome_as(const Outcome& o) {
  return static_cast<const T&>(o);
}
template <class T>
T& outcome_as(Outcome& o) {
  return static_cast<T&>(o);
}

}  // namespace gcsim::pipeline
