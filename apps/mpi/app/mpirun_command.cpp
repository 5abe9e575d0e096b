// gcsim mpirun: runs an MPI program built with gcsim-mpicc on N simulated nodes, one rank per node,
// registered from the MPI layer's own folder (the gcsim command names no application).
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "apps/mpi/app/mpirun_options.hpp"
#include "apps/mpi/app/output_capture.hpp"
#include "apps/mpi/app/program_copies.hpp"
#include "apps/mpi/app/rank_deadlock_report.hpp"
#include "apps/mpi/runtime/collective_ledger.hpp"
#include "apps/mpi/runtime/error_routing.hpp"
#include "apps/mpi/runtime/rank.hpp"
#include "apps/pipeline/app_registry.hpp"
#include "apps/pipeline/command_groups.hpp"
#include "apps/pipeline/failure.hpp"
#include "apps/pipeline/machine_options.hpp"
#include "parix/sim/fiber_stack.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::mpi_layer::app {
namespace {

// What one rank does: its Rank installed, the program's main on its own copy, its exit status kept.
parix::Program rank_program(const MpirunOptions& o, const ProgramCopies& copies, OutputCapture& capture,
                            const machine::MachineConfig::Mpi& costs, std::vector<int>& statuses,
                            CollectiveLedger& ledger) {
  return [&o, &copies, &capture, costs, &statuses, &ledger](parix::Processor& p) {
    Rank rank(p, costs);
    rank.collective_ledger = &ledger;
    rank.counts_compute = o.compute == "annotated";
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
    statuses[static_cast<std::size_t>(id)] = copies.main_of(id)(static_cast<int>(args.size()), argv.data());
  };
}

void run_mpirun(const MpirunOptions& o) {
  parix::RunOptions run = pipeline::run_options(o.machine, o.np);
  run.simulation.config.fiber_stack_bytes = o.stack_bytes;
  const machine::MachineConfig::Mpi costs = run.simulation.config.mpi;
  pipeline::check_machine_outputs(o.machine);
  const ProgramCopies copies(o.program, o.np);
  std::vector<int> statuses(static_cast<std::size_t>(o.np), 0);
  CollectiveLedger ledger;  // the ranks' collective calls, compared as they are made
  parix::RunResult result;
  {
    OutputCapture capture(o.np, o.tag_output);
    try {
      result = pipeline::run_program(run, rank_program(o, copies, capture, costs, statuses, ledger), o.machine);
    } catch (const AbortRequested& a) {
      capture.finish();
      std::fprintf(stderr, "gcsim: rank %d called MPI_Abort with error code %d\n", a.rank, a.code);
      throw pipeline::ExitStatus{a.code == 0 ? 1 : a.code};
    } catch (const parix::DeadlockError& d) {
      throw parix::DeadlockError(rank_deadlock_report(d.what()));
    } catch (const FatalMpiError& e) {
      capture.finish();
      std::fprintf(stderr, "gcsim: %s\n", e.message.c_str());
      throw pipeline::ExitStatus{kMpiErrorExitCode};
    }
  }
  pipeline::report_run(result, o.machine, {{"mpi_ranks", o.np}, {"program", o.program}});
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
