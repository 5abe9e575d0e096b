#include "apps/mpi/app/sweep_mpi_options.hpp"

#include <algorithm>
#include <filesystem>
#include <set>

#include <CLI/CLI.hpp>

#include "apps/pipeline/list_parsing.hpp"

namespace gcsim::mpi_layer::app {
namespace {

[[noreturn]] void refuse_sweep(const std::string& what) { throw CLI::ValidationError("gcsim sweep mpi", what); }

const std::set<std::string> kSweepOptions{"--nodes", "--config", "--csv", "--json"};
// mpirun's options that take a value, passed on to its parser.
const std::set<std::string> kRunValueOptions{"--model", "--stack-size", "--compute", "--host-speed", "--coll"};
const std::set<std::string> kNotForSweeps{"-np", "-n", "--np", "--shape", "--trace", "--tag-output"};

// Takes a sweep option and its value at words[i]; false when words[i] is none.
bool take_sweep_option(SweepMpiOptions& o, const std::vector<std::string>& words, std::size_t& i,
                       std::vector<std::string>& configs) {
  const std::string& w = words[i];
  if (!kSweepOptions.count(w)) return false;
  if (i + 1 >= words.size()) refuse_sweep(w + " expects a value");
  const std::string& v = words[++i];
  if (w == "--nodes") o.nodes = pipeline::parse_int_list(v, "--nodes");
  else if (w == "--config") configs.push_back(v);
  else if (w == "--csv") o.csv = v;
  else o.json = v;
  return true;
}

// The options that may end the program's arguments: the sweep's own and mpirun's that take a
// value (those a sweep refuses are recognized too, to be refused rather than handed on).
bool trailing_option(const std::string& w) {
  return kSweepOptions.count(w) || kRunValueOptions.count(w) || kNotForSweeps.count(w);
}

// The options ending the program's arguments (from the first such option after which every word
// is one with its value), removed from args: the sweep's go to o, mpirun's to run_words.
void take_trailing_options(SweepMpiOptions& o, std::vector<std::string>& args, std::vector<std::string>& configs,
                           std::vector<std::string>& run_words) {
  for (std::size_t k = 0; k < args.size(); ++k) {
    if (!trailing_option(args[k])) continue;
    bool all = true;
    for (std::size_t i = k; i < args.size() && all; i += 2) all = trailing_option(args[i]) && i + 1 < args.size();
    if (!all) continue;
    for (std::size_t i = k; i < args.size(); ++i) {
      if (kNotForSweeps.count(args[i])) refuse_sweep(args[i] + " is not an option of a sweep (trace one point with gcsim mpirun)");
      if (take_sweep_option(o, args, i, configs)) continue;
      run_words.push_back(args[i]);
      run_words.push_back(args[++i]);
    }
    args.resize(k);
    return;
  }
}

std::vector<SweepMachine> machines_of(const std::vector<std::string>& configs) {
  if (configs.empty()) return {{"calibrated", "", false}, {"published", "", true}};
  std::vector<SweepMachine> out;
  for (const std::string& f : configs) {
    if (!std::filesystem::is_regular_file(f)) refuse_sweep("--config " + f + ": no such machine file");
    out.push_back({std::filesystem::path(f).stem().string(), f, false});
  }
  return out;
}

}  // namespace

std::string sweep_mpi_summary() {
  return "Run an MPI program built with gcsim-mpicc on several node counts (one rank per node), on the calibrated and "
         "the published GC: simulated seconds, speedup, efficiency, busy, communicating and waiting seconds";
}

std::string sweep_mpi_usage() {
  return "usage: gcsim sweep mpi [options] PROGRAM [ARGS...] [--nodes LIST] [--config F ...] [--csv F] [--json F]\n"
         "  --nodes LIST         node counts, one run each (default 1,2,4,8,16,32,64)\n"
         "  --config FILE        a machine file; again for another (default: the built-in GC as measured,\n"
         "                       then as published: configs/gc-powerplus-calibrated.toml, configs/gc-powerplus.toml)\n"
         "  --model NAME         network model: analytic, flow or packet (default: each machine file's)\n"
         "  --csv FILE           the table as CSV (`gcsim plot --sweep FILE` draws it), one row per machine and count\n"
         "  --json FILE          every run's summary as JSON\n"
         "  --compute, --host-speed, --coll, --stack-size   as for gcsim mpirun\n"
         "gcsim's options go before PROGRAM; after it, the program's arguments, which the options above may\n"
         "follow. Words after `--` (before the arguments) are all the program's.\n"
         "Each point is one `gcsim mpirun -np N` of the program, its output kept back (a rank exiting non-zero\n"
         "ends the sweep with its stderr); the speedup is each machine's first count's time over this one's.\n";
}

SweepMpiOptions parse_sweep_mpi_options(const std::vector<std::string>& words) {
  SweepMpiOptions o;
  std::vector<std::string> configs;
  std::vector<std::string> run_words{"-np", "1"};
  std::size_t i = 0;
  for (; i < words.size(); ++i) {
    const std::string& w = words[i];
    if (w == "-h" || w == "--help") o.help = true;
    else if (kNotForSweeps.count(w)) refuse_sweep(w + " is not an option of a sweep (each point's node count comes from --nodes; trace one "
                                          "point with gcsim mpirun)");
    else if (take_sweep_option(o, words, i, configs)) continue;
    else if (kRunValueOptions.count(w)) {
      if (i + 1 >= words.size()) refuse_sweep(w + " expects a value");
      run_words.push_back(w);
      run_words.push_back(words[++i]);
    } else if (!w.empty() && w[0] == '-') refuse_sweep("unknown option '" + w + "'\n" + sweep_mpi_usage());
    else break;
  }
  if (o.help) return o;
  if (i >= words.size()) refuse_sweep("no program given: gcsim sweep mpi [options] PROGRAM [ARGS...]");
  std::vector<std::string> args(words.begin() + static_cast<std::ptrdiff_t>(i) + 1, words.end());
  if (!args.empty() && args.front() == "--") args.erase(args.begin());
  else take_trailing_options(o, args, configs, run_words);
  run_words.push_back(words[i]);
  o.run = parse_mpirun_options(run_words);
  o.run.args = args;
  o.machines = machines_of(configs);
  if (o.nodes.empty()) refuse_sweep("--nodes expects node counts such as 1,2,4");
  return o;
}

}  // namespace gcsim::mpi_layer::app
