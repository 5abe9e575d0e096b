#include "machine/trace.hpp"

#include <stdexcept>

#include <fmt/format.h>

namespace gcsim::machine {

TraceLevel parse_trace_level(std::string_view s) {
  if (s == "summary") return TraceLevel::summary;
  if (s == "messages") return TraceLevel::messages;
  if (s == "full") return TraceLevel::full;
  throw std::invalid_argument("unknown trace level '" + std::string(s) + "' (expected summary, messages or full)js");
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

std::string csv_path_for(const std::string& json_path) {
  const auto dot = json_path.rfind('.');
  const auto slash = json_path.rfind('/');
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) return json_path.substr(0, dot) + ".csv";
  return json_path + ".csv";
}

}  // namespace

TraceWriter::TraceWriter(const TraceOptions& options, int processors, int mesh_width, int mesh_height)
    : level_(options.level), mesh_width_(mesh_width) {
  if (options.path.empty()) return;
  json_ = std::fopen(options.path.c_str(), "wb");
  if (!json_) throw std::runtime_error("cannot write trace file '" + options.path + "'");
  const std::string csv = csv_path_for(options.path);
  csv_ = std::fopen(csv.c_str(), "wb");
  if (!csv_) throw std::runtime_error("cannot write trace file '" + csv + "'");
  // Array form of the Chrome trace-event format: the closing bracket is optional, so the file
  // is readable at every record boundary.
  json_buffer_ += "[\n";
  json_buffer_ += R"js({"ph":"M","pid":0,"name":"process_name","args":{"name":"processors"}})js";
  json_buffer_ += fmt::format(",\n{{\"ph\":\"M\",\"pid\":1,\"name\":\"process_name\",\"args\":{{\"name\":\"mesh channels ({}x{})\"}}}}",
                              mesh_width, mesh_height);
  for (int p = 0; p < processors; ++p) {
    json_buffer_ += fmt::format(
        ",\n{{\"ph\":\"M\",\"pid\":0,\"tid\":{},\"name\":\"thread_name\",\"args\":{{\"name\":\"P{} node ({},{})\"}}}}", p, p,
        p % mesh_width, p / mesh_width);
    json_buffer_ += fmt::format(
        ",\n{{\"ph\":\"M\",\"pid\":0,\"tid\":{},\"name\":\"thread_sort_index\",\"args\":{{\"sort_index\":{}}}}}", p, p);
  }
  csv_buffer_ += fmt::format("# gcsim trace; level {}; {} processors; mesh {}x{}; times in picoseconds\n",
                             to_string(level_), processors, mesh_width, mesh_height);
  csv_buffer_ += "kind,proc,peer,start_ps,end_ps,bytes,id,label\n";
  flush_buffers();
}

TraceWriter::~TraceWriter() { close(); }

void TraceWriter::record(const TraceRecord& r) {
  if (!json_) return;
  if (level_ == TraceLevel::summary) return;
  if (r.kind == TraceKind::link && level_ != TraceLevel::full) return;
  csv_buffer_ += fmt::format("{},{},{},{},{},{},{},{}\n", to_string(r.kind), r.proc, r.peer, r.start, r.end, r.bytes,
                             r.id, r.label);
  switch (r.kind) {
    case TraceKind::message:
      // An arrow from the send on the source's track to the arrival on the destination's.
      json_buffer_ += fmt::format(
          ",\n{{\"ph\":\"s\",\"pid\":0,\"tid\":{},\"ts\":{},\"id\":{},\"cat\":\"message\",\"name\":\"message\"}}", r.proc,
          us(r.start), r.id);
      json_buffer_ += fmt::format(
          ",\n{{\"ph\":\"f\",\"bp\":\"e\",\"pid\":0,\"tid\":{},\"ts\":{},\"id\":{},\"cat\":\"message\",\"name\":\"message\"}}",
          r.peer, us(r.end), r.id);
      break;
    case TraceKind::link:
      json_buffer_ += fmt::format(
          ",\n{{\"ph\":\"X\",\"pid\":1,\"tid\":{},\"ts\":{},\"dur\":{},\"cat\":\"link\",\"name\":\"{}->{}\",\"args\":{{\"bytes\":{}}}}}",
          r.id, us(r.start), us(r.end - r.start), r.proc, r.peer, r.bytes);
      break;
    default:
      json_buffer_ += fmt::format(
          ",\n{{\"ph\":\"X\",\"pid\":0,\"tid\":{},\"ts\":{},\"dur\":{},\"cat\":\"{}\",\"name\":\"{}\",\"args\":{{\"peer\":{},\"bytes\":{}}}}}",
          r.proc, us(r.start), us(r.end - r.start), to_string(r.kind), r.label.empty() ? to_string(r.kind) : r.label,
          r.peer, r.bytes);
      break;
  }
  if (json_buffer_.size() > kFlushBytes || csv_buffer_.size() > kFlushBytes) flush_buffers();
}

void TraceWriter::flush_buffers() {
  if (json_) {
    std::fwrite(json_buffer_.data(), 1, json_buffer_.size(), json_);
    std::fflush(json_);
  }
  if (csv_) {
    std::fwrite(csv_buffer_.data(), 1, csv_buffer_.size(), csv_);
    std::fflush(csv_);
  }
  json_buffer_.clear();
  csv_buffer_.clear();
}

void TraceWriter::close() {
  if (!json_) return;
  json_buffer_ += "\n]\n";
  flush_buffers();
  std::fclose(json_);
  std::fclose(csv_);
  json_ = nullptr;
  csv_ = nullptr;
}

}  // namespace gcsim::machine
