#pragma once
// Trace of a simulated run: compute intervals, sends, receives, waits, connections and link use,
// with simulated timestamps only, so a rerun writes byte-identical files. Written incrementally:
// Chrome trace-event JSON (array form, whose closing bracket is optional, so an interrupted run
// still loads in Perfetto) and CSV, flushed as the run goes in whole records. Paje (for ViTE)
// needs its events in time order, so it is written from the CSV when the trace is closed.
// traces/README.md describes the three formats.
#include <cstdint>
#include <cstdio>
#include <memory>
#include <set>
#include <string>
#include <string_view>

#include "machine/interconnect.hpp"
#include "machine/output_file.hpp"
#include "machine/sim_time.hpp"

namespace gcsim::machine {

enum class TraceLevel {
  summary,   // no per-event records, totals only
  messages,  // compute, send, receive, wait and connection intervals, message arrows
  full,      // and every link occupancy
};
TraceLevel parse_trace_level(std::string_view s);  // throws std::invalid_argument
std::string_view to_string(TraceLevel l);

struct TraceOptions {
  std::string path;                // FILE.json (Chrome) with FILE.csv and FILE.paje beside it; "" = no trace
  TraceLevel level = TraceLevel::full;
  std::string machine;             // machine and network model, for the plots' subtitles (JSON metadata only)
};

enum class TraceKind { compute, send, recv, wait, connect, link, message };
std::string_view to_string(TraceKind k);

struct TraceRecord {
  TraceKind kind;
  int proc = -1;           // processor (or, for link records, the link's source node)
  int peer = -1;           // other processor (or the link's destination node)
  SimTime start = 0;
  SimTime end = 0;
  std::int64_t bytes = 0;
  std::int64_t id = -1;    // message id, for arrows from send to receive
  std::string_view label;  // operation or call name
  int thread = 0;          // node-local thread (Processor::spawn) the interval belongs to; 0 = the processor itself
};

class TraceWriter {
 public:
  // Nodes are labelled by the interconnect's coordinates, link records by its channel labels; it
  // must outlive the writer.
  TraceWriter(const TraceOptions& options, int processors, const Interconnect& interconnect);
  ~TraceWriter();
  TraceWriter(const TraceWriter&) = delete;
  TraceWriter& operator=(const TraceWriter&) = delete;

  // Whether records are kept: a trace file is open and the level is above summary.
  bool enabled() const { return json_.is_open() && level_ != TraceLevel::summary; }
  TraceLevel level() const { return level_; }
  void record(const TraceRecord& r);
  void close();  // writes the closing bracket, then the Paje file

 private:
  void flush_buffers();
  TraceLevel level_;
  std::string json_path_, csv_path_, paje_path_;
  CheckedFile json_, csv_;  // a failed write is reported by close()
  void name_thread_track(int proc, int thread);
  int thread_track(int proc, int thread) const;  // Chrome tid
  static std::int64_t sort_index(int proc, int thread) { return std::int64_t(proc) * 65536 + thread; }
  int processors_;
  std::int64_t link_records_ = 0;  // ids of the channels' async begin/end pairs
  std::set<std::pair<int, int>> named_threads_;  // (processor, thread) tracks already named in the JSON
  std::string json_buffer_;  // whole records only, so the files always end on a record boundary
  std::string csv_buffer_;
  const Interconnect& net_;
};

}  // namespace gcsim::machine
