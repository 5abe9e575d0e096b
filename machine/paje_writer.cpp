#include "machine/paje_writer.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <set>
#include <stdexcept>

#include <fmt/format.h>

#include "machine/interconnect.hpp"
#include "machine/interconnect_registry.hpp"
#include "machine/output_file.hpp"

namespace gcsim::machine {

namespace {

// Event numbers of the %EventDef header; the header itself is written by write_header().
enum PajeEventId {
  kDefineContainerType = 0,
  kDefineStateType = 1,
  kDefineVariableType = 2,
  kDefineLinkType = 3,
  kDefineEntityValue = 4,
  kCreateContainer = 5,
  kDestroyContainer = 6,
  kPushState = 7,
  kPopState = 8,
  kStartLink = 9,
  kEndLink = 10,
  kAddVariable = 11,
  kSubVariable = 12,
  kSetVariable = 13,
};

constexpr const char* kHeader =
    "%EventDef PajeDefineContainerType 0\n%       Alias string\n%       Type string\n%       Name string\n%EndEventDef\n"
    "%EventDef PajeDefineStateType 1\n%       Alias string\n%       Type string\n%       Name string\n%EndEventDef\n"
    "%EventDef PajeDefineVariableType 2\n%       Alias string\n%       Type string\n%       Name string\n"
    "%       Color color\n%EndEventDef\n"
    "%EventDef PajeDefineLinkType 3\n%       Alias string\n%       Type string\n%       StartContainerType string\n"
    "%       EndContainerType string\n%       Name string\n%EndEventDef\n"
    "%EventDef PajeDefineEntityValue 4\n%       Alias string\n%       Type string\n%       Name string\n"
    "%       Color color\n%EndEventDef\n"
    "%EventDef PajeCreateContainer 5\n%       Time date\n%       Alias string\n%       Type string\n"
    "%       Container string\n%       Name string\n%EndEventDef\n"
    "%EventDef PajeDestroyContainer 6\n%       Time date\n%       Type string\n%       Name string\n%EndEventDef\n"
    "%EventDef PajePushState 7\n%       Time date\n%       Type string\n%       Container string\n"
    "%       Value string\n%EndEventDef\n"
    "%EventDef PajePopState 8\n%       Time date\n%       Type string\n%       Container string\n%EndEventDef\n"
    "%EventDef PajeStartLink 9\n%       Time date\n%       Type string\n%       Container string\n"
    "%       Value string\n%       StartContainer string\n%       Key string\n%EndEventDef\n"
    "%EventDef PajeEndLink 10\n%       Time date\n%       Type string\n%       Container string\n"
    "%       Value string\n%       EndContainer string\n%       Key string\n%EndEventDef\n"
    "%EventDef PajeAddVariable 11\n%       Time date\n%       Type string\n%       Container string\n"
    "%       Value double\n%EndEventDef\n"
    "%EventDef PajeSubVariable 12\n%       Time date\n%       Type string\n%       Container string\n"
    "%       Value double\n%EndEventDef\n"
    "%EventDef PajeSetVariable 13\n%       Time date\n%       Type string\n%       Container string\n"
    "%       Value double\n%EndEventDef\n";

// The same colours as the plots (traces/plot_trace.py), as Paje's "r g b" in [0, 1].
struct StateValue {
  TraceKind kind;
  const char* color;
};
constexpr StateValue kStates[] = {
    {TraceKind::compute, "0.302 0.686 0.290"},  // green
    {TraceKind::send, "0.216 0.494 0.722"},     // blue
    {TraceKind::recv, "1.000 0.498 0.000"},     // orange
    {TraceKind::wait, "0.894 0.102 0.110"},     // red
    {TraceKind::connect, "0.596 0.306 0.639"},  // purple
};

// Simulated milliseconds, exact: picoseconds are the ninth decimal.
std::string ms(SimTime t) {
  if (t < 0) return fmt::format("-{}", ms(-t));
  return fmt::format("{}.{:09d}", t / kMillisecond, t % kMillisecond);
}

// One timed Paje event to emit; sorted by (time, phase, sequence) so that at equal times an
// interval's end comes before the next one's start, and the order is otherwise the record order.
struct TimedEvent {
  SimTime time;
  int phase;  // 0: ends (pop, end link, sub), 1: starts (push, start link, add)
  std::size_t record;
  bool operator<(const TimedEvent& o) const {
    if (time != o.time) return time < o.time;
    if (phase != o.phase) return phase < o.phase;
    return record < o.record;
  }
};

bool is_state(TraceKind k) { return k != TraceKind::link && k != TraceKind::message; }

class PajeFile {
 public:
  explicit PajeFile(const std::string& path) { f_.open(path, "Paje trace"); }
  template <class... Args>
  void line(fmt::format_string<Args...> format, Args&&... args) {
    fmt::format_to(std::back_inserter(buffer_), format, std::forward<Args>(args)...);
    buffer_.push_back('\n');
    if (buffer_.size() > (1 << 16)) flush();
  }
  void raw(const char* text) { buffer_ += text; }
  void flush() {
    f_.write(buffer_);
    buffer_.clear();
  }
  void close() {
    flush();
    f_.close();  // throws OutputFileError for a write that failed
  }

 private:
  CheckedFile f_;
  std::string buffer_;
};

// Type hierarchy: Machine > Node > Channel; states on Node, a variable on Channel, links in Machine.
void write_types(PajeFile& out) {
  out.line("{} M 0 \"Machine\"", int(kDefineContainerType));
  out.line("{} N M \"Node\"", int(kDefineContainerType));
  out.line("{} T N \"Thread\"", int(kDefineContainerType));
  out.line("{} C N \"Channel\"", int(kDefineContainerType));
  out.line("{} S N \"Activity\"", int(kDefineStateType));
  out.line("{} TS T \"Activity\"", int(kDefineStateType));
  for (const StateValue& s : kStates) {
    out.line("{} {} S \"{}\" \"{}\"", int(kDefineEntityValue), to_string(s.kind), to_string(s.kind), s.color);
    out.line("{} t_{} TS \"{}\" \"{}\"", int(kDefineEntityValue), to_string(s.kind), to_string(s.kind), s.color);
  }
  out.line("{} V C \"transfers\" \"0.216 0.494 0.722\"", int(kDefineVariableType));
  out.line("{} L M N N \"Message\"", int(kDefineLinkType));
  // The links' value "msg" is left undefined: ViTE rejects entity values of link types, and
  // Paje readers (ViTE, pajeng) take an undefined link value as its own name.
}

// Containers: every processor, and the channels the trace uses (link records exist at level full).
struct Containers {
  std::set<int> channels;
  std::set<std::pair<int, int>> threads;  // (processor, thread > 0): threads spawned on a node overlap it in time
  SimTime last = 0;
};

Containers find_containers(const TraceCsv& trace, const Interconnect& net) {
  Containers c;
  for (const StoredTraceRecord& r : trace.records) {
    if (r.kind == TraceKind::link && r.id >= 0 && r.id < net.channel_count()) c.channels.insert(static_cast<int>(r.id));
    if (is_state(r.kind) && r.thread > 0 && r.proc >= 0 && r.proc < trace.processors) c.threads.insert({r.proc, r.thread});
    c.last = std::max(c.last, r.end);
  }
  return c;
}

void create_containers(PajeFile& out, const TraceCsv& trace, const Interconnect& net, const Containers& c) {
  out.line("{} {} gc M 0 \"GC-PowerPlus {} processors, {} {}x{}\"", int(kCreateContainer), ms(0), trace.processors,
           net.name(), trace.mesh_width, trace.mesh_height);
  for (int p = 0; p < trace.processors; ++p) {
    const NodeCoordinates at = net.coordinates(p);
    out.line("{} {} p{} N gc \"P{} ({},{})\"", int(kCreateContainer), ms(0), p, p, at.x, at.y);
  }
  for (const auto& [p, t] : c.threads) {
    out.line("{} {} p{}t{} T p{} \"P{} thread {}\"", int(kCreateContainer), ms(0), p, t, p, p, t);
  }
  for (int ch : c.channels) {
    const ChannelEnds e = net.channel_ends(ch);
    if (e.from >= trace.processors) continue;
    out.line("{} {} c{} C p{} \"channel {} P{}->P{} {}\"", int(kCreateContainer), ms(0), ch, e.from, ch, e.from, e.to,
             net.channel_label(ch));
    out.line("{} {} V c{} 0", int(kSetVariable), ms(0), ch);
  }
}

// Every record's start and end, in time order; records of containers that do not exist are left out.
std::vector<TimedEvent> timed_events(const TraceCsv& trace, const Interconnect& net, const Containers& c) {
  std::vector<TimedEvent> events;
  events.reserve(trace.records.size() * 2);
  auto in_range = [&](int p) { return p >= 0 && p < trace.processors; };
  for (std::size_t i = 0; i < trace.records.size(); ++i) {
    const StoredTraceRecord& r = trace.records[i];
    if (r.kind == TraceKind::link) {
      if (!c.channels.count(static_cast<int>(r.id)) || net.channel_ends(static_cast<int>(r.id)).from >= trace.processors) continue;
    } else if (r.kind == TraceKind::message) {
      if (!in_range(r.proc) || !in_range(r.peer)) continue;
    } else if (!in_range(r.proc) || r.end <= r.start) {
      continue;  // a zero-length state shows nothing and would unbalance push/pop at equal times
    }
    events.push_back({r.start, 1, i});
    events.push_back({r.end, 0, i});
  }
  std::sort(events.begin(), events.end());
  return events;
}

void write_event(PajeFile& out, const TimedEvent& e, const StoredTraceRecord& r) {
  const std::string t = ms(e.time);
  if (is_state(r.kind) && r.thread > 0) {
    if (e.phase == 1) out.line("{} {} TS p{}t{} t_{}", int(kPushState), t, r.proc, r.thread, to_string(r.kind));
    else out.line("{} {} TS p{}t{}", int(kPopState), t, r.proc, r.thread);
  } else if (is_state(r.kind)) {
    if (e.phase == 1) out.line("{} {} S p{} {}", int(kPushState), t, r.proc, to_string(r.kind));
    else out.line("{} {} S p{}", int(kPopState), t, r.proc);
  } else if (r.kind == TraceKind::message) {
    if (e.phase == 1) out.line("{} {} L gc msg p{} m{}", int(kStartLink), t, r.proc, r.id);
    else out.line("{} {} L gc msg p{} m{}", int(kEndLink), t, r.peer, r.id);
  } else {
    out.line("{} {} V c{} 1", int(e.phase == 1 ? kAddVariable : kSubVariable), t, r.id);
  }
}

// Closing the containers at the last event, innermost first.
void close_containers(PajeFile& out, const TraceCsv& trace, const Interconnect& net, const Containers& c) {
  for (int ch : c.channels) {
    if (net.channel_ends(ch).from < trace.processors) out.line("{} {} C c{}", int(kDestroyContainer), ms(c.last), ch);
  }
  for (const auto& [p, t] : c.threads) out.line("{} {} T p{}t{}", int(kDestroyContainer), ms(c.last), p, t);
  for (int p = 0; p < trace.processors; ++p) out.line("{} {} N p{}", int(kDestroyContainer), ms(c.last), p);
  out.line("{} {} M gc", int(kDestroyContainer), ms(c.last));
}

}  // namespace

void write_paje(const TraceCsv& trace, const std::string& path) {
  // The interconnect the trace names (the GC's mesh unless its header says otherwise).
  const std::unique_ptr<Interconnect> net =
      make_interconnect(trace.interconnect, std::max(1, trace.mesh_width), std::max(1, trace.mesh_height));
  PajeFile out(path);
  out.raw(kHeader);
  write_types(out);
  const Containers containers = find_containers(trace, *net);
  create_containers(out, trace, *net, containers);
  for (const TimedEvent& e : timed_events(trace, *net, containers)) write_event(out, e, trace.records[e.record]);
  close_containers(out, trace, *net, containers);
  out.close();
}

}  // namespace gcsim::machine
