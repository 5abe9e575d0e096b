// gcsim rerun RUN.json: repeats a run from the command line its JSON recorded, in the directory it
// ran in, with its outputs in a new place, and says whether the simulated figures are the same, and
// whether the trace files and images it wrote are (those of the recorded run still there).
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "apps/pipeline/app_registry.hpp"
#include "apps/pipeline/command_groups.hpp"
#include "apps/pipeline/failure.hpp"
#include "apps/rerun/figure_comparison.hpp"
#include "apps/rerun/output_comparison.hpp"
#include "apps/rerun/recorded_run.hpp"

namespace gcsim::rerun {

namespace {

namespace fs = std::filesystem;
using pipeline::FileError;

struct RerunFlags {
  std::string run_json, json, out_dir;
  bool force = false;
};

fs::path fresh_directory(const std::string& asked) {
  if (!asked.empty()) {
    std::error_code ec;
    fs::create_directories(asked, ec);
    if (ec) throw FileError(fmt::format("--out-dir '{}': cannot create it: {}", asked, ec.message()));
    return fs::absolute(asked);
  }
  std::string pattern = (fs::temp_directory_path() / "gcsim-rerun-XXXXXX").string();
  if (!::mkdtemp(pattern.data())) throw FileError(fmt::format("cannot create a directory '{}': {}", pattern, std::strerror(errno)));
  return pattern;
}

// This gcsim again, with argv, in directory cwd; returns its exit status.
int run_gcsim(const std::vector<std::string>& argv, const fs::path& cwd) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t child = ::fork();
  if (child < 0) throw std::runtime_error(fmt::format("cannot start the rerun: {}", std::strerror(errno)));
  if (child == 0) {
    if (::chdir(cwd.c_str()) != 0) {
      std::fprintf(stderr, "gcsim: error: cannot enter the recorded run's directory '%s': %s\n", cwd.c_str(), std::strerror(errno));
      ::_exit(pipeline::kExitFile);
    }
    ::execv("/proc/self/exe", args.data());
    std::fprintf(stderr, "gcsim: error: cannot start gcsim again: %s\n", std::strerror(errno));
    ::_exit(pipeline::kExitRunFailed);
  }
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw FileError(fmt::format("the rerun wrote no JSON at '{}'", path));
  return nlohmann::json::parse(in);
}

// The recorded trace files and images against the rerun's: a line for each kind of result.
void print_outputs(const OutputComparison& c) {
  if (!c.identical.empty())
    fmt::print("identical: {} file(s) the run wrote are the rerun's byte for byte: {}\n", c.identical.size(),
               fmt::join(c.identical, ", "));
  for (const std::string& m : c.missing) fmt::print("not compared: {}\n", m);
  if (c.differ.empty()) return;
  fmt::print("differ:   {} file(s) the run wrote differ from the rerun's:\n", c.differ.size());
  for (const std::string& d : c.differ) fmt::print("  {}\n", d);
}

void rerun(const RerunFlags& f) {
  const RecordedRun run = read_recorded_run(f.run_json);
  for (const std::string& note : version_notes(run)) fmt::print("note      {}\n", note);
  const std::vector<std::string> changed = changed_inputs(run);
  if (!changed.empty() && !f.force) {
    std::string why;
    for (const std::string& c : changed) why += "\n  " + c;
    throw FileError(fmt::format("'{}': its inputs changed since the run, so a rerun would not repeat it:{}\n"
                                "(--force reruns with the inputs as they are now)", f.run_json, why));
  }
  for (const std::string& c : changed) fmt::print("warning   --force: {}\n", c);
  const RerunPlan plan = plan_rerun(run, fresh_directory(f.out_dir), f.json);
  std::string shown;
  for (std::size_t i = 1; i < plan.argv.size(); ++i) shown += " " + plan.argv[i];
  fmt::print("rerun     gcsim{}\n          (in {})\n\n", shown, run.cwd.string());
  if (const int status = run_gcsim(plan.argv, run.cwd); status != 0) {
    pipeline::print_error(fmt::format("the rerun exited with status {} (its messages are above)", status));
    throw pipeline::ExitStatus{status};
  }
  const FigureComparison c = compare_figures(run.document, with_recorded_paths(read_json(plan.json), plan));
  const OutputComparison files = compare_outputs(run, plan);
  fmt::print("\n");
  if (c.differ.empty()) {
    fmt::print("identical: all {} simulated figures of the rerun ({}) equal {}'s\n", c.compared, plan.json, f.run_json);
  } else {
    fmt::print("differ:   {} of {} simulated figures of the rerun ({}) differ from {}'s (recorded -> rerun):\n",
               c.differ.size(), c.compared, plan.json, f.run_json);
    for (const std::string& d : c.differ) fmt::print("  {}\n", d);
  }
  print_outputs(files);
  if (!c.differ.empty())
    throw pipeline::RunFailure(fmt::format("the rerun's simulated figures differ from '{}' ({} of {})", f.run_json,
                                           c.differ.size(), c.compared));
  if (!files.differ.empty())
    throw pipeline::RunFailure(fmt::format("files the run wrote differ from the rerun's ({} of {})", files.differ.size(),
                                           files.differ.size() + files.identical.size()));
}

void add_rerun_command(pipeline::CommandGroups& g) {
  auto f = std::make_shared<RerunFlags>();
  CLI::App* cmd = g.app->add_subcommand(
      "rerun", "Repeat a run from its JSON (the command line, machine and scene it recorded) and compare the simulated figures");
  cmd->add_option("run", f->run_json, "A run's JSON, written with --json by gcsim run, render, sweep, bcast, ...")->required();
  cmd->add_option("--json", f->json, "Write the rerun's JSON here (default: in --out-dir, under the recorded name)");
  cmd->add_option("--out-dir", f->out_dir,
                  "Directory for the rerun's outputs (JSON, trace, images, CSVs; created if missing); default: a new "
                  "directory under $TMPDIR. The recorded run's files are never overwritten");
  cmd->add_flag("--force", f->force, "Rerun even if the machine file or the scene file changed since the run");
  cmd->footer(
      "\nThe rerun runs the recorded command line in the recorded working directory. It first checks the machine\n"
      "file (its content after inheritance) and the scene file against their recorded hashes and refuses when\n"
      "one changed (exit 3), unless --force. It then compares every figure of the two JSONs but the wall-clock\n"
      "ones and the provenance block, and the trace files (--trace's .json, .csv, .paje) and PNG images the run\n"
      "wrote, byte for byte, those still there (the others are named, not compared): exit 0 when all are\n"
      "identical; exit 1, listing each figure and file that differs; the rerun's own exit status when it failed.\n\n"
      "Example:\n"
      "  gcsim run radiosity --scene cornell --nodes 8 --json r.json && gcsim rerun r.json");
  cmd->callback([f] { rerun(*f); });
}

const pipeline::CommandFamilyRegistrar registrar{{.name = "rerun", .commands = add_rerun_command}};

}  // namespace
}  // namespace gcsim::rerun
