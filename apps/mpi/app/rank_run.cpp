#include "apps/mpi/app/rank_run.hpp"

#include <cstdio>
#include <memory>
#include <vector>

#include "apps/mpi/app/output_capture.hpp"
#include "apps/mpi/app/program_copies.hpp"
#include "apps/mpi/app/rank_deadlock_report.hpp"
#include "apps/mpi/runtime/collective_ledger.hpp"
#include "apps/mpi/runtime/error_routing.hpp"
#include "apps/mpi/runtime/rank.hpp"
#include "apps/pipeline/command_groups.hpp"
#include "parix/sim/fiber_stack.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::mpi_layer::app {
namespace {

// What one rank does: its Rank installed, the program's main on its own copy, its exit status kept.
parix::Program rank_program(const MpirunOptions& o, const ProgramCopies& copies, OutputCapture& capture,
                            const machine::MachineConfig::Mpi& costs, const ComputeSettings& computing,
                            std::vector<int>& statuses, CollectiveLedger& ledger) {
  std::vector<int> members(static_cast<std::size_t>(o.np));
  for (int r = 0; r < o.np; ++r) members[static_cast<std::size_t>(r)] = r;
  auto world = std::make_shared<const std::vector<int>>(std::move(members));  // one for all ranks
  return [&o, &copies, &capture, costs, computing, &statuses, world, &ledger](parix::Processor& p) {
    Rank rank(p, costs, world);
    rank.collective_ledger = &ledger;
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

}  // namespace

RankRun run_ranks(const MpirunOptions& o, const parix::RunOptions& run, const ComputeSettings& computing, bool silent,
                  CopiesAtEnd at_end) {
  const machine::MachineConfig::Mpi costs = run.simulation.config.mpi;
  const ProgramCopies copies(o.program, o.np, at_end);
  RankRun out;
  out.statuses.assign(static_cast<std::size_t>(o.np), 0);
  OutputCapture capture(o.np, o.tag_output);
  if (silent) capture.keep_silent();
  CollectiveLedger ledger;  // the ranks' collective calls, compared as they are made
  try {
    out.result = parix::run(run, rank_program(o, copies, capture, costs, computing, out.statuses, ledger));
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
  capture.finish();
  for (std::size_t r = 0; r < out.statuses.size() && out.failed_rank < 0; ++r) {
    if (out.statuses[r] == 0) continue;
    out.failed_rank = static_cast<int>(r);
    if (silent) out.failed_stderr = capture.stderr_of(out.failed_rank);
  }
  return out;
}

}  // namespace gcsim::mpi_layer::app
