#pragma once
// One ray-tracing experiment: a scene, its tree and the render settings, run by the pipeline on any
// number of nodes (the per-processor program is ParallelRenderJob's).
#include <memory>

#include "apps/pipeline/experiment.hpp"
#include "apps/pipeline/progress.hpp"
#include "apps/raytrace/app/render_options.hpp"
#include "apps/raytrace/parallel_render.hpp"

namespace gcsim::raytrace::app {

struct RaytraceFlags {
  RenderOptions render;
  std::string distribute = "dynamic";
  std::string image;  // run only
  bool progress = false;  // run only: tiles rendered as a line on a terminal (a sweep has its own)
};

struct RaytraceOutcome : pipeline::Outcome {
  ParallelRender render;  // its `run` is unused: the pipeline's is in Outcome::run
  std::unique_ptr<pipeline::ProgressLine> progress;
};

class RaytraceExperiment : public pipeline::Experiment {
 public:
  explicit RaytraceExperiment(const RaytraceFlags& flags);

  std::unique_ptr<pipeline::Outcome> new_outcome(int nodes) const override;
  parix::Program program(pipeline::Outcome& out) const override;
  void after_run(pipeline::Outcome& out) const override;
  void report_interrupted(const pipeline::Outcome& out, nlohmann::json& reached) const override;
  std::vector<pipeline::MemoryNeed> node_memory(int nodes, int* processor) const override;
  std::int64_t host_memory(int nodes) const override;
  void print_setup(int nodes) const override;
  void report(const pipeline::Outcome& out, nlohmann::json& extra) const override;
  void check_outputs() const override;
  pipeline::RunInputs run_inputs() const override;
  void print_sweep_setup() const override;
  std::unique_ptr<pipeline::SweepTable> sweep_table() const override;

 private:
  RaytraceFlags flags_;
  Scene scene_;
  Bvh bvh_;
  RenderSettings settings_;
  Distribution distribution_;
  ParallelRenderJob job_;
};

}  // namespace gcsim::raytrace::app
