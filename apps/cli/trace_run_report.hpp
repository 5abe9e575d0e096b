#pragma once
// `gcsim report RUN.json --out DIR`: one HTML page (DIR/index.html) with the run's configuration,
// its simulated times next to the wall-clock times, the image of a rendering run and the trace
// plots. DIR holds copies of everything the page shows, so it can be moved or archived whole.
#include <string>

namespace gcsim::cli {

struct ReportOptions {
  std::string run_json;  // written by --json
  std::string out_dir;
  std::string trace;     // "" : the trace the JSON names, if any
};

// Writes DIR/index.html and returns its path. Throws std::runtime_error naming the file on bad input.
std::string write_run_report(const ReportOptions& o);

}  // namespace gcsim::cli
