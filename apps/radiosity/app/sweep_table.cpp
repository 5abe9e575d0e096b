// `gcsim sweep radiosity`'s table: per node count the simulated and communication seconds and the
// loops, next to the thesis's tables 4.3/4.5 (sequential broadcast) or 4.8 (tree broadcast).
#include <algorithm>
#include <vector>

#include <fmt/format.h>

#include "apps/pipeline/sweep_table.hpp"
#include "apps/radiosity/app/radiosity_experiment.hpp"
#include "apps/radiosity/thesis_tables.hpp"

namespace gcsim::radiosity::app {

namespace {

std::string cell(double v, const char* spec) { return v < 0 ? std::string("-") : fmt::format(fmt::runtime(spec), v); }

class ThesisSweepTable : public pipeline::SweepTable {
 public:
  ThesisSweepTable(const Scene& scene, bool tree, CommTimeOf comm_time, nlohmann::json program)
      : scene_name_(scene.name), tree_(tree), comm_time_(comm_time), program_(std::move(program)),
        fig_(thesis::figures_for(scene.name)) {}

  void print_header() override {
    fmt::print("{:>5} {:>10} {:>8} {:>10} {:>9} {:>9} {:>6} | {:>9} {:>8} {:>9}\n", "nodes", "sim_s", "speedup", "comm_s",
               "waiting_s", "wall_s", "loops", "thesis_s", "thesis_x", "thesis_c");
  }
  // comm_s: all the time blocked in calls, as the thesis timed it; waiting_s: the part of it before
  // the peer sent (docs/run-records.md); communicating_s the rest.
  std::string csv_header() const override {
    return "nodes,simulated_s,speedup,comm_s,wall_s,loops,thesis_s,thesis_speedup,thesis_comm_s,communicating_s,waiting_s";
  }
  void print_row(const pipeline::SweepRow& row) override;
  std::string csv_row(const pipeline::SweepRow& row) const override;
  nlohmann::json json_row(const pipeline::SweepRow& row) const override {
    nlohmann::json j = row.outcome.run.to_json();
    j["radiosity"] = {{"scene", scene_name_}, {"loops", result(row).steps.size()}, {"nodes", row.nodes}};
    j["radiosity"].update(program_);
    if (comm_time_ == CommTimeOf::root) j["radiosity"]["root_comm_s"] = comm_seconds(row.outcome.run, comm_time_);
    return j;
  }
  void print_footer() override;
  std::string scene() const override { return scene_name_; }

 private:
  struct Thesis {
    double seconds = -1, speedup = -1, comm = -1;
  };
  static const ParallelOutcome& result(const pipeline::SweepRow& row) {
    return pipeline::outcome_as<RadiosityOutcome>(row.outcome).result;
  }
  Thesis thesis_at(int nodes) const {
    Thesis t;
    const int i = thesis::node_index(nodes);
    if (!fig_ || i < 0) return t;
    const auto& times = tree_ ? fig_->time_tree_bcast : fig_->time_sequential_bcast;
    t.seconds = times[i];
    t.speedup = 100.0 * times[0] / t.seconds / 100.0;
    t.comm = tree_ ? -1 : fig_->comm_seconds[i];
    return t;
  }

  std::string scene_name_;
  bool tree_;
  CommTimeOf comm_time_;
  nlohmann::json program_;
  const thesis::SceneFigures* fig_;
  std::vector<Rgb> reference_;  // the first row's radiosities: every node count must give them
  int best_nodes_ = 0;
  double best_time_ = 0;
};

void ThesisSweepTable::print_row(const pipeline::SweepRow& row) {
  const ParallelOutcome& r = result(row);
  const double t = row.outcome.run.simulated_seconds();
  if (best_nodes_ == 0 || t < best_time_) best_nodes_ = row.nodes, best_time_ = t;
  if (reference_.empty()) reference_ = r.element_radiosity;
  else if (reference_ != r.element_radiosity) fmt::print("warning: radiosities on {} nodes differ from the first run\n", row.nodes);
  const Thesis th = thesis_at(row.nodes);
  fmt::print("{:>5} {:>10.2f} {:>8.2f} {:>10.2f} {:>9.2f} {:>9.2f} {:>6} | {:>9} {:>8} {:>9}\n", row.nodes, t, row.speedup,
             comm_seconds(row.outcome.run, comm_time_), waiting_seconds(row.outcome.run, comm_time_), row.outcome.run.wall_seconds,
             r.steps.size(), cell(th.seconds, "{:.0f}"),
             cell(th.speedup, "{:.2f}"), cell(th.comm, "{:.0f}"));
}

std::string ThesisSweepTable::csv_row(const pipeline::SweepRow& row) const {
  const Thesis th = thesis_at(row.nodes);
  const parix::RunResult& run = row.outcome.run;
  const double comm = comm_seconds(run, comm_time_), waiting = waiting_seconds(run, comm_time_);
  return fmt::format("{},{:.6f},{:.6f},{:.6f},{:.6f},{},{},{},{},{:.6f},{:.6f}", row.nodes, run.simulated_seconds(), row.speedup,
                     comm, run.wall_seconds, result(row).steps.size(),
                     th.seconds < 0 ? "" : fmt::format("{}", th.seconds), th.speedup < 0 ? "" : fmt::format("{:.4f}", th.speedup),
                     th.comm < 0 ? "" : fmt::format("{}", th.comm), comm - waiting, waiting);
}

void ThesisSweepTable::print_footer() {
  if (best_nodes_ > 0) {
    std::string theirs;
    if (fig_) {
      const auto& t = tree_ ? fig_->time_tree_bcast : fig_->time_sequential_bcast;
      const int bi = int(std::min_element(t.begin(), t.end()) - t.begin());
      theirs = fmt::format(" (thesis: {} nodes)", thesis::kNodes[bi]);
    }
    fmt::print("fastest on {} nodes{}\n", best_nodes_, theirs);
  }
  if (fig_) fmt::print("thesis_x: speedup over 1 node from the thesis's table {}; thesis_c: table 4.5\n", tree_ ? "4.8" : "4.3");
  fmt::print("comm_s: {}: time blocked in communication calls, as the thesis timed it; waiting_s: the part of it\n"
             "before the peer sent (docs/run-records.md)\n",
             comm_time_ == CommTimeOf::root ? "the root's (processor 0; --comm-time root)"
                                            : "the mean over the processors (--comm-time mean)");
}

}  // namespace

double comm_seconds(const parix::RunResult& run, CommTimeOf comm_time) {
  return comm_time == CommTimeOf::root ? machine::to_seconds(run.processors.at(0).comm) : run.mean_comm_seconds();
}

double waiting_seconds(const parix::RunResult& run, CommTimeOf comm_time) {
  return comm_time == CommTimeOf::root ? machine::to_seconds(run.processors.at(0).waiting) : run.mean_waiting_seconds();
}

std::unique_ptr<pipeline::SweepTable> thesis_sweep_table(const Scene& scene, const ParallelOptions& o, CommTimeOf comm_time,
                                                         nlohmann::json program) {
  return std::make_unique<ThesisSweepTable>(scene, o.bcast == parix::BcastAlgo::tree, comm_time, std::move(program));
}

}  // namespace gcsim::radiosity::app
