// gcsim accuracy plan [--scenes A.toml,B.toml | --all] [--nodes 1,8,64] [--tolerance 0.1]: runs `gcsim plan`
// and `gcsim render` of every scene on every node count, each as its own process of this binary,
// and prints the plan's prediction against the render's figure per pass and for the memory, with
// the error in per cent; rows beyond the tolerance are marked, and the command fails if there are any.
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>

#include <fmt/format.h>

#include "apps/pipeline/failure.hpp"
#include "apps/render/app/render_commands.hpp"
#include "apps/render/plan_check.hpp"

extern char** environ;

namespace gcsim::render::app {

namespace {

namespace fs = std::filesystem;

struct PlanAccuracyFlags {
  std::vector<std::string> scenes;
  bool all = false;  // the default scenes include the long ones
  std::vector<int> nodes{1, 8, 64};
  double tolerance = 0.10;
};

struct HostCost {
  double wall_s = 0, cpu_s = 0;
};

double children_cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_CHILDREN, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// Runs this binary with `args`, its output to /dev/null; throws RunFailure when it fails.
HostCost run_self(const std::vector<std::string>& args) {
  std::vector<char*> argv{const_cast<char*>("gcsim")};
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  const double cpu0 = children_cpu_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int err = posix_spawn(&pid, "/proc/self/exe", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  if (err != 0 || waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw pipeline::RunFailure(fmt::format("gcsim {} failed (exit status {})", fmt::join(args, " "), WEXITSTATUS(status)));
  return {std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), children_cpu_seconds() - cpu0};
}

nlohmann::json read_json(const fs::path& p) {
  std::ifstream in(p);
  if (!in) throw pipeline::FileError(fmt::format("cannot read '{}'", p.string()));
  return nlohmann::json::parse(in);
}

// A row's figure in its unit: MiB for the memory, seconds for a stage.
std::string figure(const PlanCheckRow& r, double value) {
  if (r.stage == "memory") return fmt::format("{:.3f} MiB", value / (1 << 20));
  return fmt::format("{:.4g} s", value);
}

// One scene on one node count: plan, render, the rows; returns the rows beyond the tolerance.
int check_one(const std::string& scene, int nodes, const PlanAccuracyFlags& f, const fs::path& dir) {
  const fs::path plan_json = dir / "plan.json", render_json = dir / "render.json";
  const std::string n = std::to_string(nodes);
  const HostCost plan = run_self({"plan", scene, "--nodes", n, "--json", plan_json.string()});
  const HostCost render = run_self({"render", scene, "--nodes", n, "--json", render_json.string()});
  int misses = 0;
  for (const PlanCheckRow& r : compare_plan_render(read_json(plan_json), read_json(render_json))) {
    const bool miss = std::abs(r.error()) > f.tolerance;
    misses += miss;
    fmt::print("{:<28} {:>5}  {:<14} {:>12} ± {:>2.0f} % {:>12} {:>+8.1f} %{}\n", fs::path(scene).filename().string(), nodes,
               r.stage, figure(r, r.predicted), std::max(1.0, 100 * r.uncertainty), figure(r, r.measured), 100 * r.error(), miss ? "  EXCEEDS" : "");
  }
  fmt::print("{:<28} {:>5}  {:<14} plan {:.2f} s wall, {:.2f} s CPU; render {:.2f} s wall, {:.2f} s CPU ({:.1f} % of its CPU)\n",
             fs::path(scene).filename().string(), nodes, "host", plan.wall_s, plan.cpu_s, render.wall_s, render.cpu_s,
             render.cpu_s > 0 ? 100 * plan.cpu_s / render.cpu_s : 0.0);
  std::fflush(stdout);
  return misses;
}

// Scene files whose renders take minutes each (media-exp1: 640 x 480 through fog and a thick
// sphere, about 160 s of host CPU a render): left out of the default unless --all.
bool long_scene(const fs::path& p) { return p.filename() == "media-exp1.toml"; }

std::vector<std::string> scene_files(bool all) {
  std::vector<std::string> out;
  if (fs::is_directory("scenes"))
    for (const auto& e : fs::directory_iterator("scenes"))
      if (e.path().extension() == ".toml" && (all || !long_scene(e.path()))) out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  if (out.empty()) throw pipeline::FileError("no scenes/*.toml here: give --scenes");
  return out;
}

void run(const PlanAccuracyFlags& f) {
  const std::vector<std::string> scenes = f.scenes.empty() ? scene_files(f.all) : f.scenes;
  const fs::path dir = fs::temp_directory_path() / fmt::format("gcsim-plan-accuracy-{}", ::getpid());
  fs::create_directories(dir);
  fmt::print("{:<28} {:>5}  {:<14} {:>17} {:>12} {:>10}\n", "scene", "nodes", "stage", "plan", "render", "error");
  int misses = 0;
  try {
    for (const std::string& scene : scenes)
      for (int nodes : f.nodes) misses += check_one(scene, nodes, f, dir);
  } catch (...) {
    fs::remove_all(dir);
    throw;
  }
  fs::remove_all(dir);
  if (misses > 0)
    throw pipeline::RunFailure(fmt::format("{} row(s) beyond {:.0f} % (marked EXCEEDS)", misses, 100 * f.tolerance));
  fmt::print("every row within {:.0f} %\n", 100 * f.tolerance);
}

}  // namespace

void add_plan_accuracy_command(pipeline::CommandGroups& g) {
  auto f = std::make_shared<PlanAccuracyFlags>();
  CLI::App* cmd = g.accuracy->add_subcommand(
      "plan",
      "How well `gcsim plan` predicts `gcsim render`: runs both on every scene and node count and prints\n"
      "each pass's predicted simulated time and the peak memory per node against the render's, with the\n"
      "error in per cent and the host time of each; fails if a row is beyond the tolerance.");
  cmd->footer(
      "\nBy default every scenes/*.toml here but media-exp1.toml, on 1, 8 and 64 nodes: about a minute of\n"
      "host CPU in all. --all adds media-exp1.toml (640 x 480 through fog: about 3 minutes of CPU for\n"
      "each node count), as does naming it in --scenes.");
  cmd->add_option("--scenes", f->scenes, "scene files (default: every scenes/*.toml here but media-exp1.toml)")->delimiter(',');
  cmd->add_flag("--all", f->all, "with the default scenes, include media-exp1.toml (renders of minutes each)");
  cmd->add_option("--nodes", f->nodes, "node counts")->delimiter(',')->capture_default_str()->check(CLI::Range(1, 4096));
  cmd->add_option("--tolerance", f->tolerance, "largest relative error a row may have")->capture_default_str()->check(CLI::Range(0.0, 10.0));
  cmd->callback([f] { run(*f); });
}

}  // namespace gcsim::render::app
