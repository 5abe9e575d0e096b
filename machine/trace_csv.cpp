#include "machine/trace_csv.hpp"

#include <charconv>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <unordered_map>

#include <fmt/format.h>

#include "machine/input_file.hpp"
#include "machine/interconnect_registry.hpp"

namespace gcsim::machine {

namespace {

constexpr std::string_view kColumns = "kind,proc,peer,start_ps,end_ps,bytes,id,label,thread";
constexpr std::string_view kColumnsWithoutThread = "kind,proc,peer,start_ps,end_ps,bytes,id,label";  // older traces

InputFileError bad_line(const std::string& path, std::size_t line_number, std::string_view why) {
  return InputFileError(fmt::format("{}:{}: {}", path, line_number, why));
}

bool parse_kind(std::string_view s, TraceKind& k) {
  for (TraceKind c : {TraceKind::compute, TraceKind::send, TraceKind::recv, TraceKind::wait, TraceKind::connect,
                      TraceKind::link, TraceKind::message}) {
    if (s == to_string(c)) {
      k = c;
      return true;
    }
  }
  return false;
}

template <class T>
bool parse_number(std::string_view s, T& v) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

}  // namespace

std::string trace_sibling_path(const std::string& path, std::string_view extension) {
  const auto dot = path.rfind('.');
  const auto slash = path.rfind('/');
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) {
    return path.substr(0, dot) + std::string(extension);
  }
  return path + std::string(extension);
}

TraceCsv read_trace_csv(const std::string& path) {
  InputFile file = read_input_file(path, kMaxDataFileBytes);
  if (!file.ok()) throw InputFileError(fmt::format("cannot read trace CSV '{}': it {}", path, file.error));
  std::istringstream in(std::move(file.text));
  TraceCsv t;
  std::string line;
  if (!std::getline(in, line)) throw bad_line(path, 1, "empty file; expected a gcsim trace CSV");
  char level[32] = {0};
  long long processors = 0, width = 0, height = 0;  // read wide, then bounded: %d overflow is undefined
  if (std::sscanf(line.c_str(), "# gcsim trace; level %31[a-z]; %lld processors; mesh %lldx%lld", level, &processors,
                  &width, &height) != 4) {
    throw bad_line(path, 1,
                   "not a gcsim trace CSV: expected the header '# gcsim trace; level L; N processors; mesh WxH; ...'");
  }
  // The largest machine gcsim simulates has 2^20 processors on a mesh of at most 2^24 nodes; a
  // header beyond that is damage, and would have the Paje writer declare billions of containers.
  constexpr long long kMaxProcessors = 1 << 20, kMaxMeshNodes = 1 << 24;
  if (processors < 1 || processors > kMaxProcessors)
    throw bad_line(path, 1, fmt::format("{} processors in the header; expected 1..{}", processors, kMaxProcessors));
  if (width < 1 || height < 1 || width > kMaxMeshNodes || height > kMaxMeshNodes || width * height > kMaxMeshNodes)
    throw bad_line(path, 1, fmt::format("mesh {}x{} in the header; expected W x H of at most {} nodes", width, height,
                                        kMaxMeshNodes));
  t.processors = int(processors), t.mesh_width = int(width), t.mesh_height = int(height);
  constexpr std::string_view kInterconnect = "; interconnect ";
  if (const auto at = line.find(kInterconnect); at != std::string::npos) {
    const auto from = at + kInterconnect.size();
    t.interconnect = line.substr(from, line.find(';', from) - from);
    if (!is_interconnect(t.interconnect))
      throw bad_line(path, 1, fmt::format("interconnect '{}' in the header; expected one of: {}", t.interconnect,
                                          interconnect_list()));
  }
  t.level = level;
  if (!std::getline(in, line) || (line != kColumns && line != kColumnsWithoutThread)) {
    throw bad_line(path, 2, fmt::format("expected the column line '{}'", kColumns));
  }
  const int field_count = line == kColumns ? 9 : 8;
  std::unordered_map<std::string, std::int32_t> label_index;
  std::size_t line_number = 2;
  std::string_view fields[9];
  while (std::getline(in, line)) {
    ++line_number;
    if (line.empty()) continue;
    std::string_view rest(line);
    int n = 0;
    for (; n < field_count - 1; ++n) {
      const auto comma = rest.find(',');
      if (comma == std::string_view::npos) break;
      fields[n] = rest.substr(0, comma);
      rest.remove_prefix(comma + 1);
    }
    if (n != field_count - 1 || rest.find(',') != std::string_view::npos) {
      throw bad_line(path, line_number, fmt::format("expected {} comma-separated fields", field_count));
    }
    fields[field_count - 1] = rest;
    StoredTraceRecord r{};
    if (!parse_kind(fields[0], r.kind)) throw bad_line(path, line_number, "unknown record kind '" + std::string(fields[0]) + "'");
    if (!parse_number(fields[1], r.proc) || !parse_number(fields[2], r.peer) || !parse_number(fields[3], r.start) ||
        !parse_number(fields[4], r.end) || !parse_number(fields[5], r.bytes) || !parse_number(fields[6], r.id)) {
      throw bad_line(path, line_number, "expected integers in fields 2 to 7");
    }
    r.thread = 0;
    if (field_count == 9 && (!parse_number(fields[8], r.thread) || r.thread < 0)) {
      throw bad_line(path, line_number, "expected a thread number in field 9");
    }
    auto [it, inserted] = label_index.try_emplace(std::string(fields[7]), static_cast<std::int32_t>(t.labels.size()));
    if (inserted) t.labels.emplace_back(fields[7]);
    r.label = it->second;
    t.records.push_back(r);
  }
  return t;
}

}  // namespace gcsim::machine
