#include "apps/rerun/output_comparison.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>

#include <fmt/format.h>

#include "apps/pipeline/run_provenance.hpp"

namespace gcsim::rerun {

namespace fs = std::filesystem;

namespace {

// The recorded command line's --trace value ("" : none).
std::string recorded_trace(const RecordedRun& run) {
  const std::vector<std::string>& argv = run.command_line;
  for (std::size_t i = 1; i < argv.size(); ++i) {
    if (argv[i] == "--trace" && i + 1 < argv.size()) return argv[i + 1];
    if (argv[i].rfind("--trace=", 0) == 0) return argv[i].substr(8);
  }
  return "";
}

std::optional<std::string> contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Where the rerun wrote what the recorded run wrote at `recorded`.
std::string rerun_path(const std::string& recorded, const std::string& trace, const RerunPlan& plan) {
  if (auto it = plan.moved.find(recorded); it != plan.moved.end()) return it->second;
  const auto moved_trace = plan.moved.find(trace);
  if (moved_trace == plan.moved.end()) return "";
  const std::vector<std::string> from = pipeline::trace_files(trace), to = pipeline::trace_files(moved_trace->second);
  const auto at = std::find(from.begin(), from.end(), recorded);
  return at == from.end() ? "" : to[std::size_t(at - from.begin())];
}

}  // namespace

std::vector<std::string> repeatable_outputs(const RecordedRun& run) {
  const std::vector<std::string> traces = pipeline::trace_files(recorded_trace(run));
  std::vector<std::string> out;
  for (const std::string& o : run.outputs)
    if (std::find(traces.begin(), traces.end(), o) != traces.end() || fs::path(o).extension() == ".png") out.push_back(o);
  return out;
}

OutputComparison compare_outputs(const RecordedRun& run, const RerunPlan& plan) {
  OutputComparison c;
  const std::string trace = recorded_trace(run);
  for (const std::string& recorded : repeatable_outputs(run)) {
    const std::string redone = rerun_path(recorded, trace, plan);
    const fs::path original = fs::path(recorded).is_absolute() ? fs::path(recorded) : run.cwd / recorded;
    const std::optional<std::string> before = contents(original);
    const std::optional<std::string> after = redone.empty() ? std::nullopt : contents(redone);
    if (!before || !after) {
      c.missing.push_back(!before ? fmt::format("{} (no longer there)", recorded)
                                  : fmt::format("{} (the rerun wrote no file in its place)", recorded));
    } else if (*before == *after) {
      c.identical.push_back(recorded);
    } else {
      c.differ.push_back(fmt::format("{} (the rerun's: {})", recorded, redone));
    }
  }
  return c;
}

}  // namespace gcsim::rerun
