#include "machine/trace.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

#include "machine/paje_writer.hpp"
#include "machine/trace_csv.hpp"

namespace gcsim::machine {

TraceLevel parse_trace_level(std::string_view s) {
  if (s == "summary") return TraceLevel::summary;
  if (s == "messages") return TraceLevel::messages;
  if (s == "full") return TraceLevel::full;
  throw std::invalid_argument("unknown trace level '" + std::string(s) + "' (expected summary, messages or full)");
}

std::string_view to_string(TraceLevel l) {
  switch (l) {
    case TraceLevel::summary: return "summary";
    case TraceLevel::messages: return "messages";
    case TraceLevel::full: return "full";
  }
  return "?";
}

std::string_view to_string(TraceKind k) {
  switch (k) {
    case TraceKind::compute: return "compute";
    case TraceKind::send: return "send";
    case TraceKind::recv: return "recv";
    case TraceKind::wait: return "wait";
    case TraceKind::connect: return "connect";
    case TraceKind::link: return "link";
    case TraceKind::message: return "message";
  }
  return "?";
}

namespace {

constexpr std::size_t kFlushBytes = 1 << 16;

// Chrome timestamps are microseconds; six decimals keep every picosecond.
std::string us(SimTime t) { return fmt::format("{}.{:06d}", t / kMicrosecond, t % kMicrosecond); }

// Labels are operation names chosen by applications; anything that would need quoting in CSV or
// escaping in JSON becomes '_', so both files stay trivially parseable.
std::string_view clean_label(std::string_view label, std::string& scratch) {
  auto needs_cleaning = [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == ',' || c == '"' || c == '\\'; };
  if (std::none_of(label.begin(), label.end(), needs_cleaning)) return label;
  scratch.assign(label);
  std::replace_if(scratch.begin(), scratch.end(), needs_cleaning, '_');
  return scratch;
}

}  // namespace

TraceWriter::TraceWriter(const TraceOptions& options, int processors, const Interconnect& interconnect)
    : level_(options.level), processors_(processors), net_(interconnect) {
  if (options.path.empty()) return;
  json_path_ = options.path;
  csv_path_ = trace_sibling_path(options.path, ".csv");
  paje_path_ = trace_sibling_path(options.path, ".paje");
  if (csv_path_ == json_path_ || paje_path_ == json_path_) {
    throw std::runtime_error("trace file '" + json_path_ + "': name the Chrome JSON (FILE.json); FILE.csv and FILE.paje go beside it");
  }
  json_.open(json_path_, "trace file");
  csv_.open(csv_path_, "trace file");
  // Array form of the Chrome trace-event format: the closing bracket is optional, so the file
  // is readable at every record boundary. pid 0 holds one track (tid) per processor.
  json_buffer_ += "[\n";
  json_buffer_ += R"js({"ph":"M","pid":0,"name":"process_name","args":{"name":"processors"}})js";
  json_buffer_ += R"js(,
{"ph":"M","pid":0,"name":"process_sort_index","args":{"sort_index":0}})js";
  if (!options.machine.empty()) {
    // Perfetto shows process_labels beside the track group's name; gcsim plot reads it for its subtitles.
    std::string machine = options.machine;
    for (char& c : machine) {
      if (c == '"' || c == '\\' || static_cast<unsigned char>(c) < 0x20) c = '_';
    }
    json_buffer_ += fmt::format(",\n{{\"ph\":\"M\",\"pid\":0,\"name\":\"process_labels\",\"args\":{{\"labels\":\"{}\"}}}}", machine);
  }
  for (int p = 0; p < processors; ++p) {
    if (processors > net_.nodes()) {  // several per node (a packed placement): processors only
      json_buffer_ += fmt::format(",\n{{\"ph\":\"M\",\"pid\":0,\"tid\":{},\"name\":\"thread_name\",\"args\":{{\"name\":\"P{}\"}}}}", p, p);
    } else {
      const NodeCoordinates at = net_.coordinates(p);
      json_buffer_ += fmt::format(
          ",\n{{\"ph\":\"M\",\"pid\":0,\"tid\":{},\"name\":\"thread_name\",\"args\":{{\"name\":\"P{} node ({},{})\"}}}}", p,
          p, at.x, at.y);
    }
    json_buffer_ += fmt::format(
        ",\n{{\"ph\":\"M\",\"pid\":0,\"tid\":{},\"name\":\"thread_sort_index\",\"args\":{{\"sort_index\":{}}}}}", p,
        sort_index(p, 0));
  }
  if (level_ == TraceLevel::full) {
    // pid 1 holds the interconnect's channels' occupancy (see record()).
    json_buffer_ += fmt::format(
        ",\n{{\"ph\":\"M\",\"pid\":1,\"name\":\"process_name\",\"args\":{{\"name\":\"{} channels ({}x{})\"}}}}",
        net_.name(), net_.width(), net_.height());
    json_buffer_ += R"js(,
{"ph":"M","pid":1,"name":"process_sort_index","args":{"sort_index":1}})js";
  }
  // "mesh WxH" is the grid of nodes whatever wires it; another interconnect than the GC's mesh is
  // named after it, so that the Paje export (and `gcsim paje`) rebuilds the same one.
  const std::string wiring = net_.name() == "mesh" ? "" : fmt::format("; interconnect {}", net_.name());
  csv_buffer_ += fmt::format("# gcsim trace; level {}; {} processors; mesh {}x{}{}; times in picoseconds\n",
                             to_string(level_), processors, net_.width(), net_.height(), wiring);
  csv_buffer_ += "kind,proc,peer,start_ps,end_ps,bytes,id,label,thread\n";
  flush_buffers();
}

TraceWriter::~TraceWriter() {
  try {
    close();
  } catch (...) {
    // A destructor must not throw; close() is called explicitly on the normal path.
  }
}

void TraceWriter::record(const TraceRecord& r) {
  if (!enabled()) return;
  if (r.kind == TraceKind::link && level_ != TraceLevel::full) return;
  std::string scratch;
  const std::string_view label = clean_label(r.label.empty() ? to_string(r.kind) : r.label, scratch);
  csv_buffer_ += fmt::format("{},{},{},{},{},{},{},{},{}\n", to_string(r.kind), r.proc, r.peer, r.start, r.end, r.bytes,
                             r.id, label, r.thread);
  switch (r.kind) {
    case TraceKind::message:
      // An arrow from the send on the source's track to the arrival on the destination's. Flow
      // events of version 2 (bind_id, flow_out/flow_in) bind to the zero-length slice they sit on,
      // so the arrow exists even when no send or receive interval covers that instant.
      json_buffer_ += fmt::format(
          ",\n{{\"ph\":\"X\",\"pid\":0,\"tid\":{},\"ts\":{},\"dur\":0,\"cat\":\"message\",\"name\":\"to P{}\","
          "\"bind_id\":{},\"flow_out\":true,\"args\":{{\"message\":{},\"peer\":{},\"bytes\":{}}}}}",
          r.proc, us(r.start), r.peer, r.id, r.id, r.peer, r.bytes);
      json_buffer_ += fmt::format(
          ",\n{{\"ph\":\"X\",\"pid\":0,\"tid\":{},\"ts\":{},\"dur\":0,\"cat\":\"message\",\"name\":\"from P{}\","
          "\"bind_id\":{},\"flow_in\":true,\"args\":{{\"message\":{},\"peer\":{},\"bytes\":{}}}}}",
          r.peer, us(r.end), r.proc, r.id, r.id, r.proc, r.bytes);
      break;
    case TraceKind::link: {
      // Messages sharing a channel overlap without nesting, which slices of one track may not do:
      // async begin/end pairs (one track per channel name, laid out in lanes) may.
      const std::string name = fmt::format("ch {} P{}->P{} {}", r.id, r.proc, r.peer, net_.channel_label(static_cast<int>(r.id)));
      const std::int64_t occupancy = link_records_++;
      json_buffer_ += fmt::format(
          ",\n{{\"ph\":\"b\",\"pid\":1,\"tid\":{},\"ts\":{},\"cat\":\"link\",\"name\":\"{}\",\"id\":{},\"args\":{{\"bytes\":{}}}}}",
          r.id, us(r.start), name, occupancy, r.bytes);
      json_buffer_ += fmt::format(
          ",\n{{\"ph\":\"e\",\"pid\":1,\"tid\":{},\"ts\":{},\"cat\":\"link\",\"name\":\"{}\",\"id\":{}}}",
          r.id, us(r.end), name, occupancy);
      break;
    }
    default:
      if (r.thread > 0) name_thread_track(r.proc, r.thread);
      json_buffer_ += fmt::format(
          ",\n{{\"ph\":\"X\",\"pid\":0,\"tid\":{},\"ts\":{},\"dur\":{},\"cat\":\"{}\",\"name\":\"{}\",\"args\":{{\"peer\":{},\"bytes\":{}}}}}",
          thread_track(r.proc, r.thread), us(r.start), us(r.end - r.start), to_string(r.kind), label, r.peer, r.bytes);
      break;
  }
  if (json_buffer_.size() > kFlushBytes || csv_buffer_.size() > kFlushBytes) flush_buffers();
}

// Threads a processor spawns overlap it in time, and Perfetto wants the slices of one track
// nested: each thread gets its own track, sorted right under its processor's.
int TraceWriter::thread_track(int proc, int thread) const { return thread == 0 ? proc : thread * processors_ + proc; }

void TraceWriter::name_thread_track(int proc, int thread) {
  if (!named_threads_.insert({proc, thread}).second) return;
  const int tid = thread_track(proc, thread);
  json_buffer_ += fmt::format(
      ",\n{{\"ph\":\"M\",\"pid\":0,\"tid\":{},\"name\":\"thread_name\",\"args\":{{\"name\":\"P{} thread {}\"}}}}", tid, proc,
      thread);
  json_buffer_ += fmt::format(
      ",\n{{\"ph\":\"M\",\"pid\":0,\"tid\":{},\"name\":\"thread_sort_index\",\"args\":{{\"sort_index\":{}}}}}", tid,
      sort_index(proc, thread));
}

void TraceWriter::flush_buffers() {
  json_.write(json_buffer_);
  csv_.write(csv_buffer_);
  json_buffer_.clear();
  csv_buffer_.clear();
}

void TraceWriter::close() {
  if (!json_.is_open()) return;
  json_buffer_ += "\n]\n";
  flush_buffers();
  const bool csv_complete = !csv_.failed();
  try {
    json_.close();
  } catch (...) {
    if (csv_complete) csv_.close();  // the CSV is kept, whole, when only the JSON failed
    throw;
  }
  csv_.close();
  // Paje needs time order, which only the whole trace has: it is made from the finished CSV.
  write_paje(read_trace_csv(csv_path_), paje_path_);
}

}  // namespace gcsim::machine
