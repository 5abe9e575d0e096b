// gcsim mpirun: runs an MPI program built with gcsim-mpicc on N simulated nodes, one rank per node,
// registered from the MPI layer's own folder (the gcsim command names no application).
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "apps/mpi/app/mpirun_options.hpp"
#include "apps/mpi/app/output_capture.hpp"
#include "apps/mpi/app/program_copies.hpp"
#include "apps/mpi/runtime/host_speed.hpp"
#include "apps/mpi/runtime/rank.hpp"
#include "apps/pipeline/app_registry.hpp"
#include "apps/pipeline/command_groups.hpp"
#include "apps/pipeline/failure.hpp"
#include "apps/pipeline/machine_options.hpp"
#include "parix/sim/fiber_stack.hpp"

namespace gcsim::mpi_layer::app {
namespace {

// What one rank does: its Rank installed, the program's main on its own copy, its exit status kept.
parix::Program rank_program(const MpirunOptions& o, const ProgramCopies& copies, OutputCapture& capture,
                            const machine::MachineConfig::Mpi& costs, const ComputeSettings& computing,
                            std::vector<int>& statuses) {
  return [&o, &copies, &capture, costs, computing, &statuses](parix::Processor& p) {
    Rank rank(p, costs);
    rank.computing.settings = computing;
    rank.collective_algorithms = o.collectives;
    const int id = p.id();
    rank.before_switch = [&capture, id] { capture.attribute(id); };
    std::vector<std::string> args{o.program};
    args.insert(args.end(), o.args.begin(), o.args.end());
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    rank.install();
    struct Leave {  // also when the run is abandoned: nothing may use this rank's state any more
      Rank& rank;
      OutputCapture& capture;
      int id;
      ~Leave() {
        capture.attribute(id);
        install_registry(nullptr);
        parix::describe_running_stack(nullptr, nullptr);
      }
    } leave{rank, capture, id};
    rank.start_computing();  // from here the rank's CPU time is its own until it calls MPI
    statuses[static_cast<std::size_t>(id)] = copies.main_of(id)(static_cast<int>(args.size()), argv.data());
    rank.enter_call();  // what it computed after its last call (usually MPI_Finalize)
    rank.leave_call();
  };
}

// Cycles of the first of ops the machine file's [ops] gives; NaN when it gives none (then the
// calls that need it fail, naming it).
double cycles_of(const machine::MachineConfig& config, std::initializer_list<const char*> ops) {
  for (const char* op : ops) {
    if (const auto it = config.cycles_per_op.find(op); it != config.cycles_per_op.end()) return it->second;
  }
  return NAN;
}

// The run's computation settings: the mode, the node's time per flop, the host speed (timed now
// under measured, so the figure is the run's from its start) and the tables the ranks share.
struct RunComputing {
  HostSpeed host_speed;
  SampleSites global_samples;
  ComputeTotals totals;
  ComputeSettings settings;

  RunComputing(const MpirunOptions& o, const machine::MachineConfig& config)
      : host_speed(o.host_speed, "daxpy", config.clock_hz / cycles_of(config, {"daxpy_flop", "flop"})) {
    settings.mode = *compute_mode_of(o.compute);
    settings.seconds_per_flop = cycles_of(config, {"flop"}) / config.clock_hz;
    settings.host_speed = &host_speed;
    settings.global_samples = &global_samples;
    settings.totals = &totals;
    if (o.host_speed.kind != HostSpeedChoice::Kind::ratio && !std::isfinite(host_speed.node_flops())) {
      std::fprintf(stderr, "gcsim mpirun: --host-speed %s needs the node's rate: %s's [ops] gives neither daxpy_flop nor flop\n",
                   o.host_speed.text.c_str(), config.source.c_str());
      throw pipeline::ExitStatus{2};
    }
    if (settings.mode == ComputeMode::measured) host_speed.ratio();
  }

  nlohmann::json report() const {
    std::printf("compute   %s: %.6f s measured, %.6f s sampled (%lld bodies run, %lld skipped); %s\n",
                compute_mode_name(settings.mode), totals.measured_seconds, totals.sampled_seconds, totals.bodies_run,
                totals.bodies_skipped, host_speed.summary().c_str());
    return {{"mode", compute_mode_name(settings.mode)},
            {"host_speed", host_speed.to_json()},
            {"measured_seconds", totals.measured_seconds},
            {"sampled_seconds", totals.sampled_seconds},
            {"sampled_bodies_run", totals.bodies_run},
            {"sampled_bodies_skipped", totals.bodies_skipped}};
  }
};

void run_mpirun(const MpirunOptions& o) {
  parix::RunOptions run = pipeline::run_options(o.machine, o.np);
  run.simulation.config.fiber_stack_bytes = o.stack_bytes;
  const machine::MachineConfig::Mpi costs = run.simulation.config.mpi;
  pipeline::check_machine_outputs(o.machine);
  RunComputing computing(o, run.simulation.config);
  const ProgramCopies copies(o.program, o.np);
  std::vector<int> statuses(static_cast<std::size_t>(o.np), 0);
  parix::RunResult result;
  {
    OutputCapture capture(o.np, o.tag_output);
    try {
      result = pipeline::run_program(run, rank_program(o, copies, capture, costs, computing.settings, statuses), o.machine);
    } catch (const AbortRequested& a) {
      capture.finish();
      std::fprintf(stderr, "gcsim: rank %d called MPI_Abort with error code %d\n", a.rank, a.code);
      throw pipeline::ExitStatus{a.code == 0 ? 1 : a.code};
    }
  }
  const nlohmann::json compute = computing.report();
  pipeline::report_run(result, o.machine, {{"mpi_ranks", o.np}, {"program", o.program}, {"compute", compute}});
  for (int s : statuses) {
    if (s != 0) throw pipeline::ExitStatus{s};
  }
}

const pipeline::CommandFamilyRegistrar registrar{{.name = "mpi", .commands = [](pipeline::CommandGroups& g) {
                                                    CLI::App* cmd = g.app->add_subcommand("mpirun", mpirun_summary());
                                                    cmd->prefix_command();
                                                    cmd->allow_extras();
                                                    cmd->footer(mpirun_usage());
                                                    cmd->callback([cmd] {
                                                      const MpirunOptions o = parse_mpirun_options(cmd->remaining());
                                                      if (o.help) {
                                                        std::printf("%s", mpirun_usage().c_str());
                                                        return;
                                                      }
                                                      run_mpirun(o);
                                                    });
                                                  }}};

}  // namespace
}  // namespace gcsim::mpi_layer::app
