#include "apps/pipeline/run_provenance.hpp"

#include <filesystem>
#include <system_error>

#include "apps/pipeline/content_hash.hpp"
#include "apps/pipeline/machine_options.hpp"
#include "apps/pipeline/version.hpp"
#include "machine/trace_csv.hpp"

namespace gcsim::pipeline {

namespace {

std::vector<std::string>& recorded_argv() {
  static std::vector<std::string> argv;  // the one process-wide fact: how this process was started
  return argv;
}

nlohmann::json scene_record(const std::string& scene) {
  if (scene.empty()) return nullptr;
  std::error_code ec;
  // A name that is no file is a built-in scene (the catalogue, or the media app's own scenes).
  if (!std::filesystem::is_regular_file(scene, ec)) return {{"builtin", scene}};
  return {{"path", scene}, {"hash", file_content_hash(scene)}};
}

}  // namespace

void remember_command_line(int argc, const char* const* argv) {
  recorded_argv().assign(argv, argv + argc);
}

const std::vector<std::string>& command_line() { return recorded_argv(); }

std::vector<std::string> trace_files(const std::string& trace) {
  if (trace.empty()) return {};
  return {trace, machine::trace_sibling_path(trace, ".csv"), machine::trace_sibling_path(trace, ".paje")};
}

nlohmann::json run_provenance(const std::string& machine_file, const std::string& machine_name,
                              const RunInputs& inputs, const std::vector<std::string>& outputs) {
  std::error_code ec;
  const std::filesystem::path cwd = std::filesystem::current_path(ec);
  nlohmann::json seeds = nlohmann::json::object();
  for (const auto& [name, value] : inputs.seeds) seeds[name] = value;
  std::vector<std::string> written = outputs;
  written.insert(written.end(), inputs.outputs.begin(), inputs.outputs.end());
  return {{"command_line", command_line()},
          {"cwd", cwd.string()},
          {"version", version()},
          {"commit", commit()},
          {"machine", {{"file", machine_file}, {"name", machine_name}, {"hash", machine_content_hash(machine_file)}}},
          {"scene", scene_record(inputs.scene)},
          {"seeds", seeds},
          {"outputs", written}};
}

nlohmann::json run_provenance(const MachineOptions& o, const std::string& machine_name, const RunInputs& inputs) {
  std::vector<std::string> outputs;
  if (!o.json.empty()) outputs.push_back(o.json);
  for (const std::string& f : trace_files(o.trace)) outputs.push_back(f);
  return run_provenance(o.config, machine_name, inputs, outputs);
}

}  // namespace gcsim::pipeline
