#pragma once
// A run as its JSON recorded it (the provenance block, apps/pipeline/run_provenance.hpp), and the
// command line that repeats it with every output moved to a new place.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gcsim::rerun {

struct RecordedRun {
  std::string file;                       // the RUN.json read
  nlohmann::json document;                // all of it
  std::vector<std::string> command_line;  // argv as recorded
  std::filesystem::path cwd;              // where it ran
  std::vector<std::string> outputs;       // the files it wrote, as recorded
};

// Reads RUN.json; throws FileError naming the file and what is missing (no provenance: the JSON
// of an older gcsim, or not a run's).
RecordedRun read_recorded_run(const std::string& file);

// The inputs whose content hash no longer matches the record, one sentence each (the machine file
// as resolved after inheritance, the scene file); empty when they all match.
std::vector<std::string> changed_inputs(const RecordedRun& run);

// Lines saying how this gcsim differs from the one that recorded the run (version, commit).
std::vector<std::string> version_notes(const RecordedRun& run);

struct RerunPlan {
  std::vector<std::string> argv;              // the recorded command line, outputs moved
  std::map<std::string, std::string> moved;   // recorded output path -> the rerun's
  std::string json;                           // where the rerun's JSON goes
};

// The recorded command line with each output path (an argument equal to a recorded output, also as
// --opt=PATH) replaced by one in out_dir, and --json's by json when given. Throws FileError if a
// new path would be one of the recorded outputs (a rerun never overwrites them).
RerunPlan plan_rerun(const RecordedRun& run, const std::filesystem::path& out_dir, const std::string& json);

// The rerun's JSON with each moved output path put back to the recorded one, so paths compare equal.
nlohmann::json with_recorded_paths(nlohmann::json rerun, const RerunPlan& plan);

}  // namespace gcsim::rerun
