// The trace family: gcsim plot (PNGs of a trace or a sweep), gcsim report (an HTML page of a run)
// and gcsim paje (the Paje export of a trace CSV, e.g. of an interrupted run).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "apps/cli/commands.hpp"
#include "apps/cli/trace_plot_runner.hpp"
#include "apps/cli/trace_run_report.hpp"
#include "apps/pipeline/failure.hpp"
#include "machine/input_file.hpp"
#include "machine/paje_writer.hpp"
#include "machine/trace_csv.hpp"

namespace gcsim::cli {

namespace {

struct PlotOptions {
  std::string trace;
  std::string out = "plots";
  std::optional<double> from_ms;
  std::optional<double> to_ms;
  std::string procs;
  std::string sweep;
  std::string calibration;
  std::string accuracy;
  std::string title;
  std::string only;
};

// The CSV a trace argument names, as traces/gcsim_plots/trace_data.py finds it.
std::string trace_csv_of(const std::string& trace) {
  const std::string ext = std::filesystem::path(trace).extension().string();
  if (ext == ".csv") return trace;
  if (ext == ".json" || ext == ".paje") return machine::trace_sibling_path(trace, ".csv");
  return std::filesystem::exists(trace) ? trace : trace + ".csv";
}

// Inputs that exist but are not regular files (a directory, /dev/zero, a FIFO) are refused here:
// the script would block or read without end. Missing files are the script's to report.
void check_plot_inputs(const PlotOptions& o) {
  const std::pair<const char*, std::string> inputs[] = {
      {"trace", o.trace.empty() ? "" : trace_csv_of(o.trace)}, {"--sweep", o.sweep},
      {"--calibration", o.calibration}, {"--accuracy", o.accuracy}};
  for (const auto& [option, path] : inputs) {
    if (path.empty() || !std::filesystem::exists(path)) continue;
    if (auto why = machine::why_not_regular_file(path))
      throw pipeline::FileError(fmt::format("{} {}: {}", option, path, *why));
  }
}

// The script's statuses: 2 usage, 3 an input or output file, 4 memory; anything else is a failure (1).
int plot_status(int script_status) {
  return script_status == pipeline::kExitUsage || script_status == pipeline::kExitFile ||
                 script_status == pipeline::kExitResource
             ? script_status
             : pipeline::kExitRunFailed;
}

void add_plot_command(CLI::App* app) {
  auto o = std::make_shared<PlotOptions>();
  CLI::App* cmd = app->add_subcommand("plot", "PNG plots of a trace (timeline, mesh heat map, message matrix, utilization) or of a sweep");
  cmd->add_option("trace", o->trace, "Trace written by --trace: FILE.json (with FILE.csv beside it) or FILE.csv");
  cmd->add_option("--out", o->out, "Directory for the PNGs (created if needed)")->capture_default_str();
  cmd->add_option("--from-ms", o->from_ms, "Start of the time window, in simulated milliseconds");
  cmd->add_option("--to-ms", o->to_ms, "End of the time window, in simulated milliseconds");
  cmd->add_option("--procs", o->procs, "Processors to show, e.g. 0-7,12 (default: all)");
  cmd->add_option("--sweep", o->sweep, "Plot a node-count sweep CSV (nodes, simulated_s, comm_s, ...) instead of a trace");
  cmd->add_option("--calibration", o->calibration,
                  "Plot measured against predicted from a CSV of `gcsim calibrate/validate --csv` instead of a trace");
  cmd->add_option("--accuracy", o->accuracy,
                  "Plot error against host time per network model from a CSV of `gcsim accuracy network --csv`");
  cmd->add_option("--title", o->title, "Title line of every plot (default: the trace's name and shape)");
  cmd->add_option("--only", o->only, "Some of: gantt, mesh_heatmap, message_matrix, utilization");
  cmd->footer(
      "\nWrites DIR/gantt.png, DIR/mesh_heatmap.png, DIR/message_matrix.png and DIR/utilization.png\n"
      "(or DIR/sweep_NAME.png for --sweep). Uses Debian's python3 with python3-matplotlib\n"
      "(GCSIM_PYTHON overrides it). traces/README.md describes the plots and the sweep columns.\n\n"
      "Examples:\n"
      "  gcsim bcast --nodes 16 --size 4096 --algo tree --trace t.json && gcsim plot t.json --out plots/\n"
      "  gcsim plot t.json --out zoom/ --from-ms 2 --to-ms 6 --procs 0-7,12\n"
      "  gcsim plot --sweep sweep.csv --out plots/\n"
      "  gcsim validate --config configs/gc-powerplus-calibrated.toml --csv v.csv && gcsim plot --calibration v.csv");
  cmd->callback([o] {
    check_plot_inputs(*o);
    std::vector<std::string> args;
    if (!o->trace.empty()) args.push_back(o->trace);
    args.insert(args.end(), {"--out", o->out});
    if (o->from_ms) args.insert(args.end(), {"--from-ms", fmt::format("{}", *o->from_ms)});
    if (o->to_ms) args.insert(args.end(), {"--to-ms", fmt::format("{}", *o->to_ms)});
    if (!o->procs.empty()) args.insert(args.end(), {"--procs", o->procs});
    if (!o->sweep.empty()) args.insert(args.end(), {"--sweep", o->sweep});
    if (!o->calibration.empty()) args.insert(args.end(), {"--calibration", o->calibration});
    if (!o->accuracy.empty()) args.insert(args.end(), {"--accuracy", o->accuracy});
    if (!o->title.empty()) args.insert(args.end(), {"--title", o->title});
    if (!o->only.empty()) args.insert(args.end(), {"--only", o->only});
    const int status = run_plot_script(args);
    if (status != 0) throw ExitStatus{plot_status(status)};
  });
}

void add_report_command(CLI::App* app) {
  auto o = std::make_shared<ReportOptions>();
  o->out_dir = "report";
  CLI::App* cmd = app->add_subcommand("report", "An HTML page of a run: configuration, simulated and wall times, image, trace plots");
  cmd->add_option("run", o->run_json, "Run JSON written by --json")->required();
  cmd->add_option("--out", o->out_dir, "Directory for index.html and the files it shows")->capture_default_str();
  cmd->add_option("--trace", o->trace, "Trace to plot (default: the one the run JSON names, if any)");
  cmd->footer(
      "\nExample:\n"
      "  gcsim bcast --nodes 16 --size 4096 --algo tree --trace t.json --json run.json\n"
      "  gcsim report run.json --out report/      # then open report/index.html");
  cmd->callback([o] { fmt::print("wrote {}\n", write_run_report(*o)); });
}

void add_paje_command(CLI::App* app) {
  auto csv = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  CLI::App* cmd = app->add_subcommand("paje", "Write the Paje file (for ViTE) of a trace CSV, e.g. of an interrupted run");
  cmd->add_option("csv", *csv, "Trace CSV (FILE.csv beside FILE.json)")->required();
  cmd->add_option("--out", *out, "Paje file to write (default: FILE.paje beside the CSV)");
  cmd->callback([csv, out] {
    const std::string source = machine::trace_sibling_path(*csv, ".csv");
    const std::string target = out->empty() ? machine::trace_sibling_path(*csv, ".paje") : *out;
    machine::write_paje(machine::read_trace_csv(source), target);
    fmt::print("wrote {}\n", target);
  });
}

}  // namespace

void add_trace_commands(CommandGroups& g) {
  add_plot_command(g.app);
  add_report_command(g.app);
  add_paje_command(g.app);
}

}  // namespace gcsim::cli
