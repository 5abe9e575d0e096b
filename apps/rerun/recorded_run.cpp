#include "apps/rerun/recorded_run.hpp"

#include <fstream>
#include <set>
#include <system_error>

#include <fmt/format.h>

#include "apps/pipeline/content_hash.hpp"
#include "apps/pipeline/failure.hpp"
#include "apps/pipeline/version.hpp"

namespace gcsim::rerun {

namespace fs = std::filesystem;
using pipeline::FileError;

namespace {

const nlohmann::json& field(const nlohmann::json& j, const char* key, const std::string& file) {
  if (!j.is_object() || !j.contains(key))
    throw FileError(fmt::format("'{}': the provenance block has no \"{}\" (expected the JSON a run of this gcsim "
                                "wrote with --json)", file, key));
  return j.at(key);
}

// A recorded path as the recorded run saw it: relative paths are relative to its working directory.
fs::path resolved(const RecordedRun& run, const std::string& path) { return fs::path(path).is_absolute() ? fs::path(path) : run.cwd / path; }

std::string normal(const fs::path& p) {
  std::error_code ec;
  return fs::weakly_canonical(p, ec).lexically_normal().string();
}

}  // namespace

RecordedRun read_recorded_run(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw FileError(fmt::format("cannot read '{}' (does it exist?)", file));
  RecordedRun run;
  run.file = file;
  try {
    run.document = nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw FileError(fmt::format("'{}' is not JSON: {}", file, e.what()));
  }
  if (!run.document.is_object() || !run.document.contains("provenance"))
    throw FileError(fmt::format("'{}' has no \"provenance\" block: it is not a run's JSON, or an older gcsim wrote it "
                                "(run the command again to record one)", file));
  if (run.document.value("interrupted", false))
    throw FileError(fmt::format("'{}' records an interrupted run: its figures are partial, so a rerun cannot be "
                                "compared with them", file));
  const nlohmann::json& p = run.document.at("provenance");
  try {
    run.command_line = field(p, "command_line", file).get<std::vector<std::string>>();
    run.cwd = field(p, "cwd", file).get<std::string>();
    run.outputs = field(p, "outputs", file).get<std::vector<std::string>>();
    field(p, "machine", file);
  } catch (const nlohmann::json::type_error& e) {
    throw FileError(fmt::format("'{}': the provenance block has a value of the wrong type: {}", file, e.what()));
  }
  if (run.command_line.size() < 2) throw FileError(fmt::format("'{}': the recorded command line is empty", file));
  return run;
}

std::vector<std::string> changed_inputs(const RecordedRun& run) {
  std::vector<std::string> changed;
  const nlohmann::json& p = run.document.at("provenance");
  const nlohmann::json& m = p.at("machine");
  const std::string machine_file = m.value("file", "");
  const std::string recorded = m.value("hash", "");
  const std::string now = pipeline::machine_content_hash(machine_file.empty() ? "" : resolved(run, machine_file).string());
  if (now != recorded)
    changed.push_back(fmt::format("the machine {} resolves to {} now, the run recorded {}",
                                  machine_file.empty() ? "(built-in default)" : "file '" + machine_file + "'", now, recorded));
  const nlohmann::json scene = p.value("scene", nlohmann::json());
  if (scene.is_object() && scene.contains("path")) {
    const std::string path = scene.at("path").get<std::string>();
    const std::string scene_now = pipeline::file_content_hash(resolved(run, path));
    if (scene_now != scene.value("hash", ""))
      changed.push_back(fmt::format("the scene file '{}' hashes to {} now, the run recorded {}", path, scene_now,
                                    scene.value("hash", "")));
  }
  return changed;
}

std::vector<std::string> version_notes(const RecordedRun& run) {
  const nlohmann::json& p = run.document.at("provenance");
  const std::string version = p.value("version", ""), commit = p.value("commit", "");
  if (version == pipeline::version() && commit == pipeline::commit()) return {};
  return {fmt::format("recorded by gcsim {} (commit {}); this is {}", version, commit, pipeline::version_line())};
}

RerunPlan plan_rerun(const RecordedRun& run, const fs::path& out_dir, const std::string& json) {
  RerunPlan plan;
  std::set<std::string> recorded, names;
  for (const std::string& o : run.outputs) recorded.insert(normal(resolved(run, o)));
  auto move = [&](const std::string& path, bool is_json) {
    if (auto it = plan.moved.find(path); it != plan.moved.end()) return it->second;
    std::string name = fs::path(path).filename().string();
    for (int n = 2; names.count(name); ++n) name = fmt::format("{}-{}", n, fs::path(path).filename().string());
    names.insert(name);
    const std::string to = is_json && !json.empty() ? fs::absolute(json).string() : (out_dir / name).string();
    if (recorded.count(normal(to)))
      throw FileError(fmt::format("the rerun would write '{}', an output of the recorded run: give another --out-dir "
                                  "or --json (a rerun never overwrites the run it repeats)", to));
    plan.moved[path] = to;
    if (is_json) plan.json = to;
    return to;
  };
  const std::set<std::string> outputs(run.outputs.begin(), run.outputs.end());
  plan.argv.push_back(run.command_line.front());
  for (std::size_t i = 1; i < run.command_line.size(); ++i) {
    const std::string& arg = run.command_line[i];
    const bool after_json = run.command_line[i - 1] == "--json";
    const std::size_t eq = arg.find('=');
    if (outputs.count(arg)) {
      plan.argv.push_back(move(arg, after_json));
    } else if (arg.rfind("--", 0) == 0 && eq != std::string::npos && outputs.count(arg.substr(eq + 1))) {
      plan.argv.push_back(arg.substr(0, eq + 1) + move(arg.substr(eq + 1), arg.substr(0, eq) == "--json"));
    } else {
      plan.argv.push_back(arg);
    }
  }
  if (plan.json.empty()) throw FileError(fmt::format("'{}': the recorded command line has no --json among its outputs", run.file));
  return plan;
}

nlohmann::json with_recorded_paths(nlohmann::json rerun, const RerunPlan& plan) {
  std::map<std::string, std::string> back;
  for (const auto& [from, to] : plan.moved) back[to] = from;
  // Files written beside a moved one (a trace's .csv, a radiosity snapshot) keep its directory.
  auto restore = [&](const std::string& s) -> std::string {
    if (auto it = back.find(s); it != back.end()) return it->second;
    for (const auto& [to, from] : back) {
      const fs::path t(to), f(from), p(s);
      if (p.parent_path() == t.parent_path() && p.parent_path() != fs::path()) return (f.parent_path() / p.filename()).string();
    }
    return s;
  };
  auto walk = [&](auto& self, nlohmann::json& j) -> void {
    if (j.is_string()) j = restore(j.get<std::string>());
    else if (j.is_structured())
      for (auto& v : j) self(self, v);
  };
  walk(walk, rerun);
  return rerun;
}

}  // namespace gcsim::rerun
