#pragma once
// What the simulated machine predicts for the cells of a measured table: each table names its
// experiment (4.6/4.7: the thesis's all-node broadcast; 4.3/4.4/4.5/4.8: radiosity of ROOM,
// PICROOM and CORNELL to 99.9% of the energy), and each cell is one simulated run of it.
#include <exception>
#include <functional>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "apps/calibration/measured_table.hpp"
#include "apps/radiosity/radiosity.hpp"
#include "machine/machine_config.hpp"

namespace gcsim::calibration {

// Whose communication time a measured table of it (4.5) reports: radiosity::CommTimeOf.
using radiosity::CommTimeOf;
using radiosity::parse_comm_time_of;

// How the radiosity tables' runs are simulated. Defaults: the thesis's program
// (radiosity::thesis_program(), the preset `gcsim run radiosity --preset thesis` runs).
struct PredictionSettings {
  PredictionSettings() : PredictionSettings(radiosity::thesis_program()) {}
  explicit PredictionSettings(const radiosity::ProgramPreset& p)
      : hemicube(p.hemicube), shooters(p.shooters), energy(p.energy), cell_assignment(p.cell_assignment),
        side_faces(p.side_faces), merge(p.merge), ff_exchange(p.ff_exchange),
        match_thesis_loops(p.workload == radiosity::Workload::thesis_loops), comm_time_of(p.comm_time) {}
  std::string model;     // network model; "": the machine file's
  int hemicube;          // radiosity runs: hemicube resolution
  int shooters;          //                 patches shot per loop (the thesis: 2)
  double energy;         //                 shot fraction at which a run stops (the thesis: 99.9%)
  radiosity::CellAssignment cell_assignment;
  radiosity::SideFaces side_faces;
  radiosity::FormFactorMerge merge;
  radiosity::FormFactorExchange ff_exchange;
  int jobs = 1;          // simulations run side by side on this many host threads
  // Each built-in scene's reflectances scaled so that it takes table 4.2's loops at `energy`
  // (apps/radiosity/thesis_workload.hpp); false: the scenes as built.
  bool match_thesis_loops;
  CommTimeOf comm_time_of;
};

// Predictions in the layout of a table: kNotMeasured where the table has no figure.
using Grid = std::vector<std::vector<double>>;

class Predictor {
 public:
  explicit Predictor(PredictionSettings settings) : settings_(std::move(settings)) {}

  // Predicts every measured cell of every table on machine c. Runs shared by several tables
  // (4.3, 4.4 and 4.5 use the same runs) are simulated once.
  // With `interruption` given, a SIGINT/SIGTERM (parix::host::Interrupted) does not propagate: the grids
  // hold the cells whose runs finished (kNotMeasured for the rest) and *interruption the exception,
  // for the caller to rethrow once it has written them.
  std::vector<Grid> predict(const std::vector<MeasuredTable>& tables, const machine::MachineConfig& c,
                            std::exception_ptr* interruption = nullptr);

  // Called after each simulated run of a predict() with the runs done and the runs it needs
  // (from the host thread that ran it, one call at a time): a progress line.
  void on_run(std::function<void(int done, int total)> f) { on_run_ = std::move(f); }

  // Simulated runs so far (each cell of a broadcast table, each distinct radiosity run).
  int runs() const { return runs_; }

  // Loads (and matches to table 4.2) the scenes the tables' runs need, ahead of predict(), so a
  // caller timing predictions can leave that out; share_scenes takes another predictor's, which
  // must have the same scene settings (energy, hemicube, shooters, workload).
  void prepare(const std::vector<MeasuredTable>& tables);
  void share_scenes(const Predictor& from);

  // The scenes whose workload was matched to table 4.2 so far (lower-case names), and how.
  const std::map<std::string, radiosity::LoopMatch>& loop_matches() const { return matches_; }

 private:
  struct RadiosityRun {
    double seconds = 0;
    double comm_seconds = 0;
  };
  using RunKey = std::tuple<std::string, int, bool>;  // scene, nodes, tree broadcast
  void run_radiosity(const std::vector<RunKey>& keys, const machine::MachineConfig& c,
                     std::map<RunKey, RadiosityRun>& out);
  static std::vector<RunKey> radiosity_keys(const std::vector<MeasuredTable>& tables);
  radiosity::SolverOptions solver_options() const;
  void load_scenes(const std::vector<RunKey>& keys);
  RadiosityRun one_node_from_counts(const std::string& scene, const machine::MachineConfig& c);
  void predict_broadcast(const MeasuredTable& t, const machine::MachineConfig& c, Grid& g);
  void run_done();

  PredictionSettings settings_;
  // One-node radiosity runs charge only counted operations, and the counts do not depend on the
  // machine: they are kept, and a new machine's time is recomputed from them.
  std::map<std::string, std::map<std::string, std::int64_t, std::less<>>> one_node_ops_;
  // The scenes the runs read (matched to table 4.2 once, on first use), by lower-case name.
  std::map<std::string, radiosity::Scene> scenes_;
  std::map<std::string, radiosity::LoopMatch> matches_;
  int runs_ = 0;
  std::function<void(int, int)> on_run_;
  int predict_done_ = 0, predict_total_ = 0;  // the current predict()'s runs, for on_run_
};

}  // namespace gcsim::calibration
