#include "apps/raytrace/app/raytrace_experiment.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "apps/common/image.hpp"
#include "apps/pipeline/failure.hpp"
#include "apps/pipeline/sweep_table.hpp"
#include "apps/raytrace/algorithm.hpp"
#include "apps/raytrace/render.hpp"
#include "apps/raytrace/tile_prefetch.hpp"

namespace gcsim::raytrace::app {

RaytraceExperiment::RaytraceExperiment(const RaytraceFlags& flags)
    : flags_(flags),
      scene_(load_scene_or_fail(flags.render.scene)),
      bvh_(build_bvh_by_clustering(scene_)),
      settings_(settings_of(flags.render, scene_)),
      distribution_(*parse_distribution(flags.distribute)),
      job_(scene_, bvh_, settings_, distribution_) {}

std::unique_ptr<pipeline::Outcome> RaytraceExperiment::new_outcome(int nodes) const {
  auto out = std::make_unique<RaytraceOutcome>();
  out->render = job_.new_result(nodes);
  return out;
}

parix::Program RaytraceExperiment::program(pipeline::Outcome& out) const {
  RaytraceOutcome& o = pipeline::outcome_as<RaytraceOutcome>(out);
  ParallelRender* render = &o.render;
  if (flags_.progress && pipeline::progress_wanted()) {
    o.progress = std::make_unique<pipeline::ProgressLine>("raytrace", 0);
    render->on_tile = [line = o.progress.get()](int done, int total) {
      line->update_fraction(double(done) / total, fmt::format("{} of {} tiles rendered", done, total));
    };
  }
  // --host-threads: the tiles rendered ahead on the host (simulated backend; under MPI each rank renders its own).
  const std::shared_ptr<TilePrefetch> prefetch =
      o.options.backend == "simulated" ? job_.make_prefetch(o.options.simulation.config.nodes, o.options.host_threads) : nullptr;
  return [this, render, prefetch](parix::Processor& p) { job_.program(p, *render, prefetch.get()); };
}

void RaytraceExperiment::after_run(pipeline::Outcome& out) const {
  RaytraceOutcome& o = pipeline::outcome_as<RaytraceOutcome>(out);
  o.progress.reset();  // erases the line before the report
  job_.finish(o.render);
}

void RaytraceExperiment::report_interrupted(const pipeline::Outcome& out, nlohmann::json& reached) const {
  const ParallelRender& r = pipeline::outcome_as<RaytraceOutcome>(out).render;
  reached["tiles_rendered"] = r.tiles_rendered;  // rendered on a node; node 0 may not have received them all
  reached["tiles"] = r.tiles_total;
}

std::vector<pipeline::MemoryNeed> RaytraceExperiment::node_memory(int, int* processor) const {
  *processor = 0;  // node 0 also assembles the image
  return {{"scene", job_.scene_bytes()}, {"image", job_.image_bytes()}, {"image tile", job_.tile_bytes()}};
}

std::int64_t RaytraceExperiment::host_memory(int) const {
  // The float image, the hit ids (per node and merged), the 8-bit records and their messages.
  const std::int64_t pixels = std::int64_t(settings_.width) * settings_.height;
  return pixels * std::int64_t(sizeof(glm::vec3) + 2 * sizeof(std::int32_t) + 2 * 3);
}

void RaytraceExperiment::print_setup(int nodes) const {
  const RenderSettings& s = settings_;
  print_scene(scene_, bvh_);
  fmt::print("render    {}x{}, {} ({}), {}x{} subregions, {} shading, {} distribution over {} nodes\n", s.width, s.height,
             paper_name_of(s.algorithm), description_of(s.algorithm), s.tile, s.tile,
             s.shading == Shading::whitted ? "Whitted" : "local", name_of(distribution_), nodes);
}

void RaytraceExperiment::check_outputs() const { pipeline::check_writable(flags_.image, "--image"); }

pipeline::RunInputs RaytraceExperiment::run_inputs() const {
  pipeline::RunInputs in;
  in.scene = flags_.render.scene;
  if (!flags_.image.empty()) in.outputs.push_back(flags_.image);
  return in;
}

void RaytraceExperiment::report(const pipeline::Outcome& out, nlohmann::json& extra) const {
  const ParallelRender& r = pipeline::outcome_as<RaytraceOutcome>(out).render;
  print_counters(r.counters);
  int lo = 1 << 30, hi = 0;
  for (int t : r.tiles_per_node) lo = std::min(lo, t), hi = std::max(hi, t);
  fmt::print("tiles     {} in all, {}..{} per node\n", Tiling{settings_.width, settings_.height, settings_.tile}.count(), lo, hi);
  if (!flags_.image.empty()) {
    apps::write_png(flags_.image, r.image);
    fmt::print("image     {}\n", flags_.image);
  }
  extra["raytrace"] = counters_json(r.counters);
  extra["raytrace"]["scene"] = scene_.name;
  extra["raytrace"]["algorithm"] = std::string(paper_name_of(settings_.algorithm));
  extra["raytrace"]["tile"] = settings_.tile;
  extra["raytrace"]["size"] = settings_.width;
  extra["raytrace"]["distribution"] = std::string(name_of(distribution_));
  extra["raytrace"]["tiles_per_node"] = r.tiles_per_node;
  if (!flags_.image.empty()) extra["raytrace"]["image"] = flags_.image;  // gcsim report shows it
}

void RaytraceExperiment::print_sweep_setup() const {
  print_scene(scene_, bvh_);
  fmt::print("render    {}x{}, {}, {}x{} subregions, {} distribution\n\n", settings_.width, settings_.height,
             paper_name_of(settings_.algorithm), settings_.tile, settings_.tile, name_of(distribution_));
}

namespace {

// Speedup against the first count scaled to one node, parallel efficiency, compute and comm per node.
class EfficiencyTable : public pipeline::SweepTable {
 public:
  explicit EfficiencyTable(std::string scene) : scene_(std::move(scene)) {}
  pipeline::SpeedupBase speedup_base() const override { return pipeline::SpeedupBase::first_point_scaled; }
  void print_header() override {
    fmt::print("{:>6} {:>12} {:>8} {:>8} {:>12} {:>14} {:>12} {:>9}\n", "nodes", "simulated s", "speedup", "effic.",
               "busy s/node", "communic. s/nd", "waiting s/nd", "wall s");
  }
  // comm_s_mean: all the time blocked in calls, communicating_s_mean + waiting_s_mean (docs/run-records.md).
  std::string csv_header() const override {
    return "nodes,simulated_s,speedup,efficiency,comm_s_mean,communicating_s_mean,waiting_s_mean,compute_s_mean,wall_s";
  }
  void print_row(const pipeline::SweepRow& r) override {
    const parix::RunResult& run = r.outcome.run;
    fmt::print("{:>6} {:>12.4f} {:>8.2f} {:>7.0f}% {:>12.4f} {:>14.4f} {:>12.4f} {:>9.2f}\n", r.nodes, run.simulated_seconds(),
               r.speedup, 100.0 * r.speedup / r.nodes, run.mean_compute_seconds(), run.mean_communicating_seconds(),
               run.mean_waiting_seconds(), run.wall_seconds);
  }
  std::string csv_row(const pipeline::SweepRow& r) const override {
    const parix::RunResult& run = r.outcome.run;
    return fmt::format("{},{:.6f},{:.4f},{:.4f},{:.6f},{:.6f},{:.6f},{:.6f},{:.4f}", r.nodes, run.simulated_seconds(), r.speedup,
                       r.speedup / r.nodes, run.mean_comm_seconds(), run.mean_communicating_seconds(),
                       run.mean_waiting_seconds(), run.mean_compute_seconds(), run.wall_seconds);
  }
  void print_footer() override {
    fmt::print("busy: computing; communicating: moving bytes or setting up links; waiting: blocked before the peer sent "
               "or asked (docs/run-records.md)\n");
  }
  nlohmann::json json_document(nlohmann::json rows) const override { return {{"sweep", rows}, {"scene", scene_}}; }
  bool announce_files() const override { return false; }
  std::string scene() const override { return scene_; }

 private:
  std::string scene_;
};

}  // namespace

std::unique_ptr<pipeline::SweepTable> RaytraceExperiment::sweep_table() const {
  return std::make_unique<EfficiencyTable>(scene_.name);
}

}  // namespace gcsim::raytrace::app
