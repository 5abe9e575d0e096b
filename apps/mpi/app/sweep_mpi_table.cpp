#include "apps/mpi/app/sweep_mpi_table.hpp"

#include <fmt/format.h>

#include "apps/pipeline/experiment.hpp"

namespace gcsim::mpi_layer::app {
namespace {

class MpiSweepTable : public pipeline::SweepTable {
 public:
  explicit MpiSweepTable(std::string machine) : machine_(std::move(machine)) {}
  void print_header() override {
    fmt::print("{:>5} {:>12} {:>8} {:>10} {:>10} {:>15} {:>10} {:>9}\n", "nodes", "sim_s", "speedup", "efficiency",
               "busy_s", "communicating_s", "waiting_s", "wall_s");
  }
  std::string csv_header() const override {
    return "nodes,simulated_s,speedup,efficiency,comm_s,busy_s,communicating_s,waiting_s,wall_s,machine";
  }
  void print_row(const pipeline::SweepRow& r) override {
    if (r.first) first_nodes_ = r.nodes;
    const parix::RunResult& run = r.outcome.run;
    fmt::print("{:>5} {:>12.6f} {:>8.2f} {:>10.3f} {:>10.6f} {:>15.6f} {:>10.6f} {:>9.2f}\n", r.nodes, run.simulated_seconds(),
               r.speedup, efficiency(r), run.mean_compute_seconds(), run.mean_communicating_seconds(),
               run.mean_waiting_seconds(), run.wall_seconds);
  }
  std::string csv_row(const pipeline::SweepRow& r) const override {
    const parix::RunResult& run = r.outcome.run;
    return fmt::format("{},{:.9f},{:.6f},{:.6f},{:.9f},{:.9f},{:.9f},{:.9f},{:.6f},{}", r.nodes, run.simulated_seconds(),
                       r.speedup, efficiency(r), run.mean_comm_seconds(), run.mean_compute_seconds(),
                       run.mean_communicating_seconds(), run.mean_waiting_seconds(), run.wall_seconds, machine_);
  }
  nlohmann::json json_row(const pipeline::SweepRow& r) const override {
    nlohmann::json j = SweepTable::json_row(r);
    j["efficiency"] = efficiency(r);
    j["machine"] = machine_;
    return j;
  }
  void print_footer() override {
    fmt::print("efficiency: speedup x first count / count; busy: computing; communicating: moving bytes or setting up links; "
               "waiting: blocked before the peer sent or asked (means per processor; docs/run-records.md)\n");
  }
  bool announce_files() const override { return false; }  // the command names them once, after every machine

 private:
  double efficiency(const pipeline::SweepRow& r) const {
    const int first = r.first ? r.nodes : first_nodes_;
    return r.nodes > 0 ? r.speedup * first / r.nodes : 0.0;
  }
  std::string machine_;
  int first_nodes_ = 1;
};

}  // namespace

std::unique_ptr<pipeline::SweepTable> mpi_sweep_table(std::string machine) {
  return std::make_unique<MpiSweepTable>(std::move(machine));
}

}  // namespace gcsim::mpi_layer::app
