#pragma once
// One radiosity experiment: a scene and the solver's options, run by the pipeline on any number of
// nodes. Every node runs radiosity_program on its own replica of the scene; node 0's replica is
// the result.
#include <optional>
#include <string>
#include <vector>

#include "apps/pipeline/experiment.hpp"
#include "apps/pipeline/progress.hpp"
#include "apps/radiosity/app/solve_options.hpp"
#include "apps/radiosity/parallel_radiosity.hpp"
#include "apps/radiosity/program_preset.hpp"
#include "apps/radiosity/scene.hpp"
#include "apps/radiosity/thesis_workload.hpp"

namespace gcsim::radiosity::app {

// Options only `run radiosity` has: outputs and checks of the one run.
struct RunOutputs {
  std::string image, camera, steps_csv, radiosities;
  std::vector<std::string> snapshots;  // --snapshots: the loops, as CLI11 split them
  int width = 0, height = 0;
  double exposure = 0;
  bool gauss_seidel = false;
  bool progress = false;  // a progress line per loop on a terminal (gcsim run; a sweep has its own)
};

struct RadiosityOutcome : pipeline::Outcome {
  ParallelOutcome result;  // node 0's replica after the run
  std::unique_ptr<pipeline::ProgressLine> progress;  // while the run goes (RunOutputs::progress)
  int loops_done = 0;          // as processor 0 reported them (ParallelOptions::on_loop): what an
  double shot_fraction = 0.0;  // interrupted run reached
};

class RadiosityExperiment : public pipeline::Experiment {
 public:
  // Loads the scene and checks every option; throws with the reason.
  RadiosityExperiment(const SolveFlags& solve, const RunOutputs& outputs);

  std::unique_ptr<pipeline::Outcome> new_outcome(int nodes) const override;
  parix::Program program(pipeline::Outcome& out) const override;
  void report_interrupted(const pipeline::Outcome& out, nlohmann::json& reached) const override;
  void after_run(pipeline::Outcome& out) const override;
  void print_setup(int nodes) const override;
  std::vector<pipeline::MemoryNeed> node_memory(int nodes, int* processor) const override;
  std::int64_t host_memory(int nodes) const override;
  void report(const pipeline::Outcome& out, nlohmann::json& extra) const override;
  void check_outputs() const override;
  pipeline::RunInputs run_inputs() const override;
  // The energy threshold not reached (convergence.hpp says why).
  std::optional<std::string> goal_missed(const pipeline::Outcome& out) const override;
  void print_sweep_setup() const override;
  std::unique_ptr<pipeline::SweepTable> sweep_table() const override;

  const Scene& scene() const { return scene_; }

 private:
  void match_workload();
  nlohmann::json program_json() const;

  SolveFlags solve_;
  RunOutputs outputs_;
  Scene scene_;
  ParallelOptions options_;
  std::optional<Camera> camera_;
  Workload workload_ = Workload::as_built;
  CommTimeOf comm_time_ = CommTimeOf::mean;
  std::optional<LoopMatch> match_;  // the scene as matched to table 4.2 (--workload thesis-loops)
};

// Reports of one run (run_report.cpp).
void print_loops_table(const ParallelOutcome& r, const std::string& scene_name, int shooters);
void write_steps_csv(const std::string& path, const ParallelOutcome& r);
// Full-matrix Gauss-Seidel on the host: prints how far r is from it, returns the largest difference.
double compare_with_gauss_seidel(const Scene& scene, const HemicubeOptions& hemicube, const ParallelOutcome& r);
// Writes the final image and the snapshots; camera: the one asked for, or the scene's.
void write_images(const Scene& scene, const ParallelOutcome& r, const RunOutputs& o, const Camera& camera);
// The snapshot after `loop` of --image IMAGE: IMAGE_loopN.png beside it.
std::string snapshot_path(const std::string& image, int loop);

// The sweep's table with the thesis's tables 4.3/4.5/4.8 beside it (sweep_table.cpp); its
// communication column is the processors' mean or the root's (comm_time); each JSON row carries program.
std::unique_ptr<pipeline::SweepTable> thesis_sweep_table(const Scene& scene, const ParallelOptions& o, CommTimeOf comm_time,
                                                         nlohmann::json program);
// A run's communication seconds as comm_time reads them.
double comm_seconds(const parix::RunResult& run, CommTimeOf comm_time);
// Of that, the part before the peer sent (parix::ProcessorStats::waiting), for the same processors.
double waiting_seconds(const parix::RunResult& run, CommTimeOf comm_time);

}  // namespace gcsim::radiosity::app
