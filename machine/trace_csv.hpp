#pragma once
// Reads back a trace CSV written by TraceWriter (FILE.csv beside FILE.json). The Paje export is
// made from it at the end of a run (Paje needs its events sorted by time, which the run does not
// produce them in), and `gcsim paje` converts the CSV of an interrupted run the same way.
#include <cstdint>
#include <string>
#include <vector>

#include "machine/trace.hpp"

namespace gcsim::machine {

struct StoredTraceRecord {
  TraceKind kind;
  int proc;
  int peer;
  SimTime start;
  SimTime end;
  std::int64_t bytes;
  std::int64_t id;
  std::int32_t label;  // index into TraceCsv::labels
  int thread;          // node-local thread; 0 = the processor itself
};

struct TraceCsv {
  std::string level;  // summary, messages or full
  int processors = 0;
  int mesh_width = 0;   // the grid of nodes ("mesh WxH" in the header)
  int mesh_height = 0;
  std::string interconnect = "mesh";  // "; interconnect NAME" after it, when not the GC's mesh
  std::vector<std::string> labels;  // distinct labels, in order of first use
  std::vector<StoredTraceRecord> records;
};

// Throws std::runtime_error naming the file and the line when it is not a gcsim trace CSV.
TraceCsv read_trace_csv(const std::string& path);

// FILE.json -> FILE.csv, FILE.paje: the files written beside the Chrome trace.
std::string trace_sibling_path(const std::string& path, std::string_view extension);

}  // namespace gcsim::machine
