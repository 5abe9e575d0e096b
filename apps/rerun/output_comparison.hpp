#pragma once
// Whether the files a recorded run wrote that must repeat bit for bit (its trace: FILE.json,
// FILE.csv, FILE.paje; its PNG images) are the rerun's, byte for byte. A recorded file that is no
// longer there is named, not compared. JSONs and CSVs are left to the figure comparison: they hold
// wall-clock times.
#include <string>
#include <vector>

#include "apps/rerun/recorded_run.hpp"

namespace gcsim::rerun {

struct OutputComparison {
  std::vector<std::string> identical;  // recorded paths whose rerun is the same bytes
  std::vector<std::string> differ;     // "PATH (the rerun's: PATH)"
  std::vector<std::string> missing;    // recorded paths no longer there (or the rerun did not write)
};

// The recorded files of those kinds: the trace files of the recorded --trace and every .png output.
std::vector<std::string> repeatable_outputs(const RecordedRun& run);

// Each of them against the file the rerun wrote in its place (plan.moved, or beside the moved trace).
OutputComparison compare_outputs(const RecordedRun& run, const RerunPlan& plan);

}  // namespace gcsim::rerun
