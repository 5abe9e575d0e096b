#include "apps/pipeline/bench_threads_command.hpp"

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "apps/pipeline/experiment.hpp"
#include "apps/pipeline/machine_options.hpp"
#include "apps/pipeline/failure.hpp"
#include "apps/pipeline/option_vocabulary.hpp"

namespace gcsim::pipeline {

namespace {

struct BenchFlags {
  MachineOptions machine;
  int threads = 2;
  int rounds = 3;
  int nodes = 0;
};

double median(std::vector<double> v) {
  std::ranges::sort(v);
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

void add_bench_threads_command(CLI::App& threads, const AppSpec& app) {
  auto f = std::make_shared<BenchFlags>();
  CLI::App* cmd = threads.add_subcommand(app.name, "What --host-threads buys for one " + app.name + " run on this host");
  add_machine_choice_options(cmd, f->machine);
  add_nodes_option(cmd, f->machine.nodes, fmt::format("the application's ({})", app.default_nodes));
  // Named apart from any application's own options (a test app has --rounds).
  cmd->add_option("--host-threads", f->threads, "Host threads compared with one")->check(CLI::Range(2, 256))->capture_default_str();
  cmd->add_option("--bench-rounds", f->rounds, "Rounds of one run on 1 host thread, then one on --host-threads")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  for (const char* name : {"--nodes", "--host-threads", "--bench-rounds"}) cmd->get_option(name)->group("Benchmark");
  ExperimentFactory prepare = app.options(*cmd, Verb::sweep);
  cmd->footer("Example:\n  gcsim bench threads " + app.name + " --nodes 64 --host-threads 2 --bench-rounds 3");
  const int default_nodes = app.default_nodes;
  cmd->callback([f, prepare, default_nodes] {
    if (f->machine.backend != "simulated") throw std::invalid_argument("bench threads: --host-threads is for the simulated backend");
    const std::unique_ptr<Experiment> e = prepare();
    parix::RunOptions options = run_options(f->machine, default_nodes);
    fmt::print("bench     {} nodes, wall time of one run on 1 host thread and on {}, {} rounds\n",
               options.simulation.config.nodes, f->threads, f->rounds);
    fmt::print("{:>5} {:>10} {:>10} {:>7}\n", "round", "1 thread", fmt::format("{} threads", f->threads), "ratio");
    std::vector<double> one, many, ratios;
    parix::RunResult anchor;
    for (int r = 1; r <= f->rounds; ++r) {
      double wall[2];
      for (int k = 0; k < 2; ++k) {
        options.host_threads = k == 0 ? 1 : f->threads;
        const std::unique_ptr<Outcome> out = run_experiment(*e, options, nullptr);
        if (r == 1 && k == 0) anchor = out->run;
        if (out->run.makespan != anchor.makespan || out->run.events != anchor.events)
          throw RunFailure(fmt::format("round {} on {} host threads: simulated time {} ps and {} events, against {} ps and {} "
                                       "events on one: --host-threads changed the run (a bug; please report it)",
                                       r, options.host_threads, out->run.makespan, out->run.events, anchor.makespan, anchor.events));
        wall[k] = out->run.wall_seconds;
      }
      one.push_back(wall[0]), many.push_back(wall[1]), ratios.push_back(wall[0] / wall[1]);
      fmt::print("{:>5} {:>9.3f}s {:>9.3f}s {:>7.2f}\n", r, wall[0], wall[1], ratios.back());
    }
    fmt::print("{:>5} {:>9.3f}s {:>9.3f}s {:>7.2f}\n", "median", median(one), median(many), median(ratios));
    fmt::print("simulated {:.6f} s in every run ({} events)\n", anchor.simulated_seconds(), anchor.events);
  });
}

}  // namespace gcsim::pipeline
