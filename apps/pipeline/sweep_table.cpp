#include "apps/pipeline/sweep_table.hpp"

#include <fmt/format.h>

#include "apps/pipeline/experiment.hpp"

namespace gcsim::pipeline {

nlohmann::json SweepTable::json_row(const SweepRow& row) const {
  nlohmann::json j = row.outcome.run.to_json();
  j["speedup"] = row.speedup;
  return j;
}

namespace {

class StandardTable : public SweepTable {
 public:
  // Busy, communicating and waiting (docs/run-records.md), means per processor; the CSV keeps
  // comm_s (communicating + waiting: all the time blocked in calls) and adds its two parts.
  void print_header() override {
    fmt::print("{:>5} {:>12} {:>8} {:>10} {:>15} {:>10} {:>9}\n", "nodes", "sim_s", "speedup", "busy_s", "communicating_s",
               "waiting_s", "wall_s");
  }
  std::string csv_header() const override { return "nodes,simulated_s,speedup,comm_s,communicating_s,waiting_s,wall_s"; }
  void print_row(const SweepRow& r) override {
    const parix::RunResult& run = r.outcome.run;
    fmt::print("{:>5} {:>12.6f} {:>8.2f} {:>10.6f} {:>15.6f} {:>10.6f} {:>9.2f}\n", r.nodes, run.simulated_seconds(), r.speedup,
               run.mean_compute_seconds(), run.mean_communicating_seconds(), run.mean_waiting_seconds(), run.wall_seconds);
  }
  std::string csv_row(const SweepRow& r) const override {
    const parix::RunResult& run = r.outcome.run;
    return fmt::format("{},{:.9f},{:.6f},{:.9f},{:.9f},{:.9f},{:.6f}", r.nodes, run.simulated_seconds(), r.speedup,
                       run.mean_comm_seconds(), run.mean_communicating_seconds(), run.mean_waiting_seconds(), run.wall_seconds);
  }
  void print_footer() override {
    fmt::print("busy: computing; communicating: moving bytes or setting up links; waiting: blocked before the peer sent "
               "or asked (means per processor; docs/run-records.md)\n");
  }
};

}  // namespace

std::unique_ptr<SweepTable> standard_sweep_table() { return std::make_unique<StandardTable>(); }

std::unique_ptr<SweepTable> Experiment::sweep_table() const { return standard_sweep_table(); }

}  // namespace gcsim::pipeline
