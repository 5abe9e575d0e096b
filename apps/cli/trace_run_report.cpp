#include "apps/cli/trace_run_report.hpp"

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "apps/cli/trace_plot_runner.hpp"
#include "machine/input_file.hpp"
#include "machine/output_file.hpp"

namespace gcsim::cli {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr const char* kPlots[][2] = {
    {"gantt.png", "Timeline of every processor: compute, send, receive, wait and connection, with message arrows"},
    {"utilization.png", "Share of processor time busy, communicating and waiting, over time"},
    {"mesh_heatmap.png", "The physical mesh: bytes carried and busy fraction of each channel"},
    {"message_matrix.png", "Bytes sent from each processor to each other processor"},
};

std::string escape(std::string_view s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string show(const json& v) {
  if (v.is_string()) return escape(v.get<std::string>());
  if (v.is_number_float()) return fmt::format("{:.6g}", v.get<double>());
  return escape(v.dump());
}

json read_run_json(const std::string& path) {
  const machine::InputFile in = machine::read_input_file(path, machine::kMaxDataFileBytes);
  if (!in.ok()) throw machine::InputFileError("cannot read run JSON '" + path + "': it " + in.error);
  json j;
  try {
    j = json::parse(in.text);
  } catch (const json::exception& e) {  // parse errors and out-of-range numbers such as 1e309
    const std::string why = e.what();     // "[json.exception.parse_error.101] parse error at line 1, ..."
    const std::size_t tag_end = why.find("] ");
    throw machine::InputFileError(fmt::format("{}: not JSON ({}); expected the file written by --json", path,
                                              tag_end == std::string::npos ? why : why.substr(tag_end + 2)));
  }
  if (!j.is_object() || !j.contains("simulated") || !j["simulated"].is_object() || !j.contains("wall")) {
    throw machine::InputFileError(path + ": not a gcsim run JSON (expected the keys \"simulated\" and \"wall\" that --json writes)");
  }
  return j;
}

// A path named inside the JSON is taken relative to the JSON's folder, else to the current one.
fs::path resolve_named(const std::string& named, const std::string& json_path) {
  const fs::path p(named);
  if (p.is_absolute()) return p;
  const fs::path beside = fs::path(json_path).parent_path() / p;
  if (fs::exists(beside)) return beside;
  return p;
}

double number_at(const json& j, const char* a, const char* b) {
  if (j.contains(a) && j[a].is_object() && j[a].contains(b) && j[a][b].is_number()) return j[a][b].get<double>();
  return -1;
}

void table_row(std::ostream& h, std::string_view name, const std::string& a, const std::string& b = {}) {
  h << "<tr><th>" << escape(name) << "</th><td>" << a << "</td>";
  if (!b.empty()) h << "<td>" << b << "</td>";
  h << "</tr>\n";
}

std::string seconds(double s) { return s < 0 ? "&ndash;" : fmt::format("{:.6f} s", s); }

// Run JSONs keep app settings in an object named after the app ({"APP": {"scene", "image", ...}}):
// a key is looked up at the top level, then in those objects. Returns (app, value) or nulls.
std::pair<std::string, const json*> find_setting(const json& j, const char* key) {
  if (j.contains(key) && j[key].is_string()) return {"", &j[key]};
  static const std::set<std::string> kRunBlocks{"simulated", "wall", "ops"};
  for (const auto& [k, v] : j.items()) {
    if (v.is_object() && !kRunBlocks.count(k) && v.contains(key) && v[key].is_string()) return {k, &v[key]};
  }
  return {"", nullptr};
}

// Settings as dotted rows: {"APP": {"scene": "CORNELL", "counts": {"patches": 112}}} gives
// APP.scene and APP.counts.patches.
void setting_rows(std::ostream& h, const std::string& prefix, const json& v, int depth) {
  if (v.is_object()) {
    if (depth > 2) return;
    for (const auto& [k, sub] : v.items()) setting_rows(h, prefix.empty() ? k : prefix + "." + k, sub, depth + 1);
  } else if (!v.is_array()) {
    table_row(h, prefix, show(v));
  }
}

// The command the run's JSON recorded: "gcsim bcast", "gcsim run" (the app follows), "gcsim render".
std::string recorded_command(const json& j) {
  const json* argv = j.contains("provenance") && j["provenance"].is_object() && j["provenance"].contains("command_line")
                         ? &j["provenance"]["command_line"] : nullptr;
  if (!argv || !argv->is_array() || argv->size() < 2 || !(*argv)[1].is_string()) return "gcsim run";
  return "gcsim " + escape((*argv)[1].get<std::string>());
}

// The page's title: the command, the app, algorithm and scene the run names, and its node count.
std::string report_heading(const json& j) {
  std::string heading = recorded_command(j);
  for (const char* k : {"experiment", "app", "algo", "scene"}) {
    const auto [app, v] = find_setting(j, k);
    if (!v) continue;
    if (!app.empty() && heading.find(app) == std::string::npos) heading += " &middot; " + escape(app);
    const std::string value = escape(v->get<std::string>());
    if (heading == "gcsim " + value) continue;  // `gcsim bcast`'s experiment is bcast: said once
    heading += " &middot; " + value;
  }
  if (j.contains("nodes") && j["nodes"].is_number_integer()) heading += fmt::format(" &middot; {} nodes", j["nodes"].get<int>());
  return heading;
}

// A number named key at the top level or in an app's settings object; -1 when absent.
double find_number(const json& j, const char* key) {
  if (j.contains(key) && j[key].is_number()) return j[key].get<double>();
  for (const auto& [k, v] : j.items()) {
    if (v.is_object() && k != "simulated" && k != "wall" && v.contains(key) && v[key].is_number()) return v[key].get<double>();
  }
  return -1;
}

void folded_configuration(std::ostream& h, const json& j) {
  h << "<details><summary><b>Configuration</b> (every setting of the run JSON)</summary>\n<table>\n";
  static const std::set<std::string> kShownElsewhere{"simulated", "wall", "processors", "ops", "events", "messages"};
  for (const auto& [k, v] : j.items()) {
    if (!kShownElsewhere.count(k)) setting_rows(h, k, v, 1);
  }
  h << "</table></details>\n";
}

void folded_times(std::ostream& h, const json& j) {
  const double sim_total = number_at(j, "simulated", "total_s");
  const double wall_total = number_at(j, "wall", "total_s");
  h << "<details><summary><b>Simulated time next to wall-clock time</b></summary>\n<table>\n"
    << "<tr><th></th><th>simulated GC-PowerPlus</th><th>host wall clock</th></tr>\n";
  table_row(h, "total", seconds(sim_total), seconds(wall_total));
  table_row(h, "computation (mean per processor)", seconds(number_at(j, "simulated", "compute_s")), "&ndash;");
  table_row(h, "blocked in communication calls (mean per processor)", seconds(number_at(j, "simulated", "comm_s")), "&ndash;");
  table_row(h, "blocked in communication calls (busiest processor)", seconds(number_at(j, "simulated", "comm_max_s")),
            "&ndash;");
  if (j.contains("events")) table_row(h, "discrete events", show(j["events"]), "&nbsp;");
  if (j.contains("messages")) table_row(h, "messages sent", show(j["messages"]), "&nbsp;");
  h << "</table></details>\n";
  if (j.contains("ops") && j["ops"].is_object() && !j["ops"].empty()) {
    h << "<details><summary><b>Counted operations</b> (" << j["ops"].size() << ")</summary>\n<table>\n";
    for (const auto& [k, v] : j["ops"].items()) table_row(h, k, show(v));
    h << "</table></details>\n";
  }
}

void folded_processors(std::ostream& h, const json& j) {
  if (!j.contains("processors") || !j["processors"].is_array() || j["processors"].empty()) return;
  const auto& ps = j["processors"];
  h << "<details><summary><b>Processors</b> (" << ps.size()
    << ")</summary>\n<table>\n<tr><th>id</th><th>finish (s)</th><th>compute (s)</th><th>comm (s)</th>"
       "<th>connect (s)</th><th>messages sent</th><th>bytes sent</th><th>connections</th></tr>\n";
  for (const auto& p : ps) {
    h << "<tr>";
    for (const char* k : {"id", "finish_s", "compute_s", "comm_s", "connect_s", "messages_sent", "bytes_sent", "connections"}) {
      const bool time = std::string_view(k).ends_with("_s") && p.contains(k) && p[k].is_number();
      h << "<td>" << (time ? fmt::format("{:.6f}", p[k].get<double>()) : p.contains(k) ? show(p[k]) : "") << "</td>";
    }
    h << "</tr>\n";
  }
  h << "</table></details>\n";
}

// The run's image, copied beside the page; "" when the run names none.
std::string image_figure(const json& j, const ReportOptions& o) {
  const auto [app, named] = find_setting(j, "image");
  if (!named) return {};
  const fs::path image = resolve_named(named->get<std::string>(), o.run_json);
  if (!fs::exists(image)) {
    return "<p class=\"note\">The run names the image " + escape(image.string()) + ", which does not exist.</p>\n";
  }
  std::error_code ec;
  fs::copy_file(image, fs::path(o.out_dir) / image.filename(), fs::copy_options::overwrite_existing, ec);
  const std::string ext = image.extension().string();
  const std::string name = escape(image.filename().string());
  if (ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".gif" || ext == ".svg") {
    return "<figure class=\"image\"><img src=\"" + name + "\" alt=\"rendered image\"><figcaption>" +
           escape(image.string()) + "</figcaption></figure>\n";
  }
  return "<p><a href=\"" + name + "\">" + escape(image.string()) + "</a></p>\n";
}

// The trace the report plots: --trace, else the one the run JSON names; "" when none.
std::string trace_of(const json& j, const ReportOptions& o) {
  if (!o.trace.empty()) return o.trace;
  if (const auto [app, named] = find_setting(j, "trace"); named) {
    return resolve_named(named->get<std::string>(), o.run_json).string();
  }
  return {};
}

// Busy / communicating / waiting / idle, as gcsim plot measured them from the trace.
std::string shares_line(const std::string& plots_dir) {
  std::ifstream in(fs::path(plots_dir) / "utilization.json");
  if (!in) return {};
  const json u = json::parse(in, nullptr, false);
  if (!u.is_object()) return {};
  std::string line;
  for (const char* k : {"busy", "communicating", "waiting", "idle"}) {
    if (u.contains(k) && u[k].is_number()) line += fmt::format("{}{} {:.1f}&nbsp;%", line.empty() ? "" : ", ", k, u[k].get<double>());
  }
  if (line.empty()) return {};
  return "<p class=\"shares\">Processor time, from the trace: " + line +
         " <small>(waiting: blocked before the peer had sent or asked for the link; traces/README.md)</small></p>\n";
}

std::string headline_figure(const std::string& value, const std::string& label) {
  return "<div class=\"figure\"><div class=\"value\">" + value + "</div><div class=\"label\">" + label + "</div></div>\n";
}

// The first screen: simulated and wall time, speedup if the JSON knows it, the machine, the image.
void write_headline(std::ostream& h, const json& j, const std::string& image, const std::string& shares) {
  const double sim = number_at(j, "simulated", "total_s");
  const double wall = number_at(j, "wall", "total_s");
  h << "<section class=\"headline\"><div class=\"figures\">\n"
    << headline_figure(sim < 0 ? "&ndash;" : fmt::format("{:.6g} s", sim), "simulated time of the run")
    << headline_figure(wall < 0 ? "&ndash;" : fmt::format("{:.3g} s", wall), "wall-clock time on the host");
  if (const double speedup = find_number(j, "speedup"); speedup > 0) {
    h << headline_figure(fmt::format("{:.3g}&times;", speedup), "speedup");
  }
  if (sim > 0 && wall > 0) h << headline_figure(fmt::format("{:.3g}", sim / wall), "simulated seconds per wall second");
  h << "</div>\n<p class=\"machine\">";
  if (j.contains("config")) h << show(j["config"]);
  if (j.contains("nodes")) h << " &middot; " << show(j["nodes"]) << " nodes";
  if (j.contains("model")) h << " &middot; network model " << show(j["model"]);
  h << "</p>\n" << shares << image << "</section>\n";
}

// The trace's plots, drawn by gcsim plot into OUT/plots, and the trace files with how to open each.
std::string trace_section(const std::string& trace, const ReportOptions& o) {
  std::ostringstream h;
  h << "<h2>Trace</h2>\n";
  if (trace.empty()) {
    h << "<p>No trace: rerun with <code>--trace FILE.json</code> (and <code>--json</code>), or give "
         "<code>gcsim report --trace FILE.json</code>.</p>\n";
    return h.str();
  }
  const std::string plots = (fs::path(o.out_dir) / "plots").string();
  if (const int status = run_plot_script({trace, "--out", plots}); status != 0) {
    h << "<p class=\"note\">The plots of " << escape(trace) << " could not be drawn (gcsim plot exited with " << status
      << "; its message is on the terminal).</p>\n";
  } else {
    for (const auto& [file, caption] : kPlots) {
      h << "<figure><img src=\"plots/" << file << "\" alt=\"" << caption << "\"><figcaption>" << caption
        << "</figcaption></figure>\n";
    }
  }
  static const char* kOpen[][2] = {
      {".json", "Chrome trace-event JSON: open it in <a href=\"https://ui.perfetto.dev\">ui.perfetto.dev</a> "
                "(&ldquo;Open trace file&rdquo;) or chrome://tracing"},
      {".paje", "Paje: open it in ViTE (<code>vite FILE.paje</code>, Debian package vite)"},
      {".csv", "CSV, one record per line: <code>gcsim plot FILE.csv</code>, or pandas "
               "<code>read_csv(FILE, comment='#')</code>"},
  };
  h << "<ul class=\"files\">\n";
  const fs::path base = fs::absolute(trace);
  for (const auto& [ext, how] : kOpen) {
    const fs::path file = fs::path(base).replace_extension(ext);
    if (!fs::exists(file)) continue;
    std::error_code ec;
    const fs::path relative = fs::relative(file, fs::absolute(o.out_dir), ec);
    const std::string link = ec || relative.empty() ? file.string() : relative.string();
    h << "<li><a href=\"" << escape(link) << "\"><code>" << escape(file.filename().string()) << "</code></a> &mdash; " << how
      << "</li>\n";
  }
  h << "</ul>\n";
  return h.str();
}

}  // namespace

std::string write_run_report(const ReportOptions& o) {
  const json j = read_run_json(o.run_json);
  if (!o.trace.empty() && !fs::exists(o.trace) && !fs::exists(fs::path(o.trace).replace_extension(".csv"))) {
    throw machine::InputFileError("--trace " + o.trace + ": no such file (expected FILE.json written by --trace, with FILE.csv beside it)");
  }
  std::error_code ec;
  fs::create_directories(o.out_dir, ec);
  if (ec) throw machine::OutputFileError("--out " + o.out_dir + ": cannot create the directory: " + ec.message());

  const std::string trace = trace_of(j, o);
  const std::string traced = trace_section(trace, o);  // draws the plots, whose shares lead the page
  const std::string shares = trace.empty() ? std::string() : shares_line((fs::path(o.out_dir) / "plots").string());
  std::ostringstream h;
  const std::string heading = report_heading(j);
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << heading << "</title>\n"
    << "<style>body{font-family:sans-serif;max-width:1200px;margin:1.5em auto;padding:0 1em;color:#222}"
       "table{border-collapse:collapse;margin:0.5em 0 1.5em}th,td{border:1px solid #ccc;padding:3px 10px;text-align:left}"
       "td{font-variant-numeric:tabular-nums}th{background:#f4f4f4}img{max-width:100%;border:1px solid #ddd}"
       "figure{margin:1em 0 2em}figcaption{color:#555;font-size:0.9em}.note{color:#a33}"
       ".figures{display:flex;flex-wrap:wrap;gap:1em}.figure{border:1px solid #ddd;border-radius:6px;padding:0.6em 1.2em}"
       ".value{font-size:2em;font-weight:bold;font-variant-numeric:tabular-nums}.label{color:#555}"
       ".machine{color:#444}.image img{min-width:256px;max-height:420px;image-rendering:pixelated}details{margin:0.6em 0}summary{cursor:pointer}</style></head><body>\n";
  h << "<h1>" << heading << "</h1>\n";
  write_headline(h, j, image_figure(j, o), shares);
  h << traced << "<h2>Counters and configuration</h2>\n";
  folded_times(h, j);
  folded_processors(h, j);
  folded_configuration(h, j);
  h << "<hr><p><small>Report of <code>" << escape(o.run_json) << "</code>, written by <code>gcsim report</code>. "
       "Simulated times are the modelled machine's; wall times are the host's.</small></p>\n</body></html>\n";

  const std::string index = (fs::path(o.out_dir) / "index.html").string();
  machine::write_text_file(index, h.str(), "report page");
  return index;
}

}  // namespace gcsim::cli
