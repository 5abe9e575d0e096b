#include "apps/mpi/app/mpirun_options.hpp"

#include <limits>
#include <stdexcept>

#include <CLI/CLI.hpp>

namespace gcsim::mpi_layer::app {
namespace {

[[noreturn]] void bad(const std::string& what) { throw CLI::ValidationError("gcsim mpirun", what); }

long long integer_of(const std::string& option, const std::string& text) {
  try {
    std::size_t used = 0;
    const long long v = std::stoll(text, &used);
    if (used == text.size()) return v;
  } catch (const std::exception&) {
  }
  bad(option + " expects a whole number, got '" + text + "'");
}

// "8M", "512K", "1G" or bytes.
std::int64_t size_of(const std::string& text) {
  if (text.empty()) bad("--stack-size expects a size such as 8M");
  const char unit = static_cast<char>(std::toupper(static_cast<unsigned char>(text.back())));
  const int shift = unit == 'K' ? 10 : unit == 'M' ? 20 : unit == 'G' ? 30 : 0;
  const long long n = integer_of("--stack-size", shift ? text.substr(0, text.size() - 1) : text);
  if (n <= 0 || n > (1ll << 40) >> shift) bad("--stack-size expects a positive size such as 8M, got '" + text + "'");
  const std::int64_t bytes = static_cast<std::int64_t>(n) << shift;
  if (bytes < (64 << 10)) bad("--stack-size must be at least 64K");
  return bytes;
}

AlgorithmChoice algorithms_of_spec(const std::string& spec) {
  try {
    return parse_algorithm_spec(spec);
  } catch (const std::invalid_argument& e) {
    bad(std::string("--coll: ") + e.what());
  }
}

HostSpeedChoice host_speed_of(const std::string& text) {
  try {
    return parse_host_speed(text);
  } catch (const std::invalid_argument& e) {
    bad(std::string("--host-speed ") + e.what());
  }
}

}  // namespace

std::string mpirun_summary() {
  return "Run an MPI program built with gcsim-mpicc on N simulated nodes (one rank per node, or K with --ranks-per-node)";
}

std::string mpirun_usage() {
  return "usage: gcsim mpirun -np N [options] PROGRAM [ARGS...]\n"
         "  -np, -n, --np N      ranks, one per node of the machine unless --ranks-per-node (required)\n"
         "  --ranks-per-node K   K ranks per node (rank r on node r / K, ceil(N / K) nodes), sharing its\n"
         "                       CPUs and memory; their messages cost a node-local transfer (default 1)\n"
         "  --config FILE        machine file (default: the built-in calibrated GC-PowerPlus)\n"
         "  --model NAME         network model: analytic, flow or packet (default: the machine file's)\n"
         "  --shape WxH          the sub-mesh the N nodes occupy\n"
         "  --json FILE          the run's summary as JSON\n"
         "  --trace FILE         a trace of the run (.json, with .csv beside it)\n"
         "  --tag-output         prefix each line with [1,RANK]<stdout>: or <stderr>: as Open MPI does\n"
         "  --stack-size SIZE    stack reserved per rank, committed as used (default 8M)\n"
         "  --compute MODE       what computation between MPI calls costs on the rank's node:\n"
         "                       measured (default): the rank's host CPU time between calls times the\n"
         "                       host speed, plus what the program annotates (not byte-identical);\n"
         "                       annotated: only gcsim_mpi_compute(seconds), gcsim_mpi_compute_flops(n)\n"
         "                       and the GCSIM_SAMPLE macros of <gcsim/mpi_ext.h>; none: nothing.\n"
         "                       annotated and none runs are byte-identical unless they sample\n"
         "  --host-speed X       host seconds -> node seconds for measured and sampled time: auto\n"
         "                       (default: times a daxpy kernel once on this host and divides by the\n"
         "                       node's rate on it, clock / the machine file's [ops] daxpy_flop), a\n"
         "                       ratio (4: the host is 4x the node), or the host's rate (2Gf, 500Mf).\n"
         "                       Printed after the run and kept in --json\n"
         "  --coll SPEC          algorithms of collectives, e.g. bcast=binomial,allreduce=ring (default:\n"
         "                       MPICH's selection by size; apps/mpi/README.md lists the names)\n"
         "Output: each rank's stdout, then stderr, in rank order; then the simulated and wall time.\n"
         "Exit status: the program's (the first non-zero rank's), or gcsim's own (deadlock 5, ...).\n";
}

MpirunOptions parse_mpirun_options(const std::vector<std::string>& words) {
  MpirunOptions o;
  std::size_t i = 0;
  bool np_given = false;
  auto value = [&](const std::string& option) -> std::string {
    if (i + 1 >= words.size()) bad(option + " expects a value");
    return words[++i];
  };
  for (; i < words.size() && o.program.empty(); ++i) {
    const std::string& w = words[i];
    if (w == "-np" || w == "-n" || w == "--np") {
      const long long n = integer_of(w, value(w));
      if (n < 1 || n > std::numeric_limits<int>::max()) bad(w + " expects the number of ranks, 1 or more, got " + std::to_string(n));
      o.np = static_cast<int>(n), np_given = true;
    }
    else if (w == "--ranks-per-node") o.ranks_per_node = static_cast<int>(integer_of(w, value(w)));
    else if (w == "--config") o.machine.config = value(w);
    else if (w == "--model") o.machine.model = value(w);
    else if (w == "--shape") o.machine.shape = value(w);
    else if (w == "--json") o.machine.json = value(w);
    else if (w == "--trace") o.machine.trace = value(w);
    else if (w == "--tag-output") o.tag_output = true;
    else if (w == "--stack-size") o.stack_bytes = size_of(value(w));
    else if (w == "--compute") o.compute = value(w);
    else if (w == "--coll") o.collectives = algorithms_of_spec(o.collectives_spec = value(w));
    else if (w == "--host-speed") o.host_speed = host_speed_of(value(w));
    else if (w == "-h" || w == "--help") o.help = true;
    else if (!w.empty() && w[0] == '-') bad("unknown option '" + w + "'\n" + mpirun_usage());
    else o.program = w;
  }
  o.args.assign(words.begin() + static_cast<std::ptrdiff_t>(i), words.end());
  if (o.help) return o;
  if (o.compute != "none" && o.compute != "annotated" && o.compute != "measured")
    bad("--compute expects measured, annotated or none, got '" + o.compute + "'");
  if (!np_given) bad("-np N is required: the number of ranks, 1 or more");
  if (o.program.empty()) bad("no program given: gcsim mpirun -np N PROGRAM [ARGS...]");
  if (o.ranks_per_node < 1 || o.ranks_per_node > o.np) bad("--ranks-per-node expects 1..N (the ranks, -np)");
  o.machine.nodes = (o.np + o.ranks_per_node - 1) / o.ranks_per_node;
  return o;
}

}  // namespace gcsim::mpi_layer::app
