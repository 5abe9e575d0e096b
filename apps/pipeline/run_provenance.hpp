#pragma once
// The provenance block of a run's JSON: what is needed to run it again and to tell whether its
// inputs are still the ones it read. One place builds it; every command that writes a run JSON
// (report_run, the sweep, an interrupted run) puts it under "provenance", and `gcsim rerun RUN.json`
// reads it back:
//   command_line  the argv, exactly;  cwd  where it ran (relative paths are relative to it)
//   version, commit   gcsim's (as `gcsim --version` prints them)
//   machine   {file ("" : the built-in default), name, hash: content_hash.hpp, after inheritance}
//   scene     {path, hash} of a scene file, or {builtin: NAME}
//   seeds     {NAME: value} the run's random streams started from
//   outputs   every file the run wrote (its JSON, the trace and the files beside it, images, CSVs)
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gcsim::pipeline {

struct MachineOptions;

// What an application's run read and wrote beyond the machine options (Experiment::run_inputs).
struct RunInputs {
  std::string scene;                              // a scene file's path or a built-in scene's name; "" : none
  std::map<std::string, std::uint64_t> seeds;     // e.g. {"seed", 1}
  std::vector<std::string> outputs;               // files written besides --json and --trace
};

// Called once by main with the process's argv, before parsing.
void remember_command_line(int argc, const char* const* argv);
const std::vector<std::string>& command_line();

// The files a trace option writes: FILE.json, FILE.csv, FILE.paje (none for "").
std::vector<std::string> trace_files(const std::string& trace);

// The block described above: the machine file and the name it resolved to, what the application
// read and wrote, and the files the command itself wrote (outputs: its JSON, trace files, CSV).
nlohmann::json run_provenance(const std::string& machine_file, const std::string& machine_name,
                              const RunInputs& inputs, const std::vector<std::string>& outputs);
// The same for a run of machine options o: its --config, and its --json and --trace files.
nlohmann::json run_provenance(const MachineOptions& o, const std::string& machine_name, const RunInputs& inputs = {});

}  // namespace gcsim::pipeline
