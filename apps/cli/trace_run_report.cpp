#include "apps/cli/trace_run_report.hpp"

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "apps/cli/trace_plot_runner.hpp"

namespace gcsim::cli {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr const char* kPlots[][2] = {
    {"gantt.png", "Timeline of every processor: compute, send, receive, wait and connection, with message arrows"},
    {"utilization.png", "Share of processor time in each activity over time"},
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
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read run JSON '" + path + "' (expected the file written by --json)");
  json j;
  try {
    j = json::parse(in);
  } catch (const json::parse_error& e) {
    throw std::runtime_error(fmt::format("{}: not JSON ({}); expected the file written by --json", path, e.what()));
  }
  if (!j.is_object() || !j.contains("simulated") || !j["simulated"].is_object() || !j.contains("wall")) {
    throw std::runtime_error(path + ": not a gcsim run JSON (expected the keys \"simulated\" and \"wall\" that --json writes)");
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

// The page's title: the app, algorithm and scene the run names, and its node count.
std::string report_heading(const json& j) {
  std::string heading = "gcsim run";
  for (const char* k : {"experiment", "app", "algo", "scene"}) {
    const auto [app, v] = find_setting(j, k);
    if (!v) continue;
    if (!app.empty() && heading.find(app) == std::string::npos) heading += " &middot; " + escape(app);
    heading += " &middot; " + escape(v->get<std::string>());
  }
  if (j.contains("nodes") && j["nodes"].is_number_integer()) heading += fmt::format(" &middot; {} nodes", j["nodes"].get<int>());
  return heading;
}

void write_configuration(std::ostream& h, const json& j) {
  h << "<h2>Configuration</h2>\n<table>\n";
  static const std::set<std::string> kShownElsewhere{"simulated", "wall", "processors", "ops", "events", "messages"};
  for (const auto& [k, v] : j.items()) {
    if (!kShownElsewhere.count(k)) setting_rows(h, k, v, 1);
  }
  h << "</table>\n";
}

void write_times(std::ostream& h, const json& j) {
  const double sim_total = number_at(j, "simulated", "total_s");
  const double wall_total = number_at(j, "wall", "total_s");
  h << "<h2>Simulated time next to wall-clock time</h2>\n<table>\n"
    << "<tr><th></th><th>simulated GC-PowerPlus</th><th>host wall clock</th></tr>\n";
  table_row(h, "total", seconds(sim_total), seconds(wall_total));
  table_row(h, "computation (mean per processor)", seconds(number_at(j, "simulated", "compute_s")), "&ndash;");
  table_row(h, "communication (mean per processor)", seconds(number_at(j, "simulated", "comm_s")), "&ndash;");
  table_row(h, "communication (busiest processor)", seconds(number_at(j, "simulated", "comm_max_s")), "&ndash;");
  if (sim_total > 0 && wall_total > 0) {
    table_row(h, "simulated seconds per wall second", fmt::format("{:.4g}", sim_total / wall_total), "&nbsp;");
  }
  if (j.contains("events")) table_row(h, "discrete events", show(j["events"]), "&nbsp;");
  if (j.contains("messages")) table_row(h, "messages sent", show(j["messages"]), "&nbsp;");
  h << "</table>\n";
  if (j.contains("ops") && j["ops"].is_object() && !j["ops"].empty()) {
    h << "<h2>Counted operations</h2>\n<table>\n";
    for (const auto& [k, v] : j["ops"].items()) table_row(h, k, show(v));
    h << "</table>\n";
  }
}

void write_processors(std::ostream& h, const json& j) {
  if (j.contains("processors") && j["processors"].is_array() && !j["processors"].empty()) {
    const auto& ps = j["processors"];
    h << "<details" << (ps.size() <= 16 ? " open" : "") << "><summary><b>Processors</b> (" << ps.size()
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
}

// The run's image, copied beside the page.
void write_image(std::ostream& h, const json& j, const ReportOptions& o) {
  std::error_code ec;
  if (const auto [app, named] = find_setting(j, "image"); named) {
    const fs::path image = resolve_named(named->get<std::string>(), o.run_json);
    h << "<h2>Image</h2>\n";
    if (fs::exists(image)) {
      const fs::path copy = fs::path(o.out_dir) / image.filename();
      fs::copy_file(image, copy, fs::copy_options::overwrite_existing, ec);
      const std::string ext = image.extension().string();
      if (ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".gif" || ext == ".svg") {
        h << "<figure><img src=\"" << escape(image.filename().string()) << "\" alt=\"rendered image\"><figcaption>"
          << escape(image.string()) << "</figcaption></figure>\n";
      } else {
        h << "<p><a href=\"" << escape(image.filename().string()) << "\">" << escape(image.string()) << "</a></p>\n";
      }
    } else {
      h << "<p class=\"note\">The run names the image " << escape(image.string()) << ", which does not exist.</p>\n";
    }
  }
}

// The trace's plots, drawn by gcsim plot into OUT/plots.
void write_trace(std::ostream& h, const json& j, const ReportOptions& o) {
  std::string trace = o.trace;
  if (const auto [app, named] = find_setting(j, "trace"); trace.empty() && named) {
    trace = resolve_named(named->get<std::string>(), o.run_json).string();
  }
  h << "<h2>Communication trace</h2>\n";
  if (trace.empty()) {
    h << "<p>No trace: rerun with <code>--trace FILE.json</code> (and <code>--json</code>), or give "
         "<code>gcsim report --trace FILE.json</code>.</p>\n";
  } else {
    const std::string plots = (fs::path(o.out_dir) / "plots").string();
    const int status = run_plot_script({trace, "--out", plots});
    if (status != 0) {
      h << "<p class=\"note\">The plots of " << escape(trace) << " could not be drawn (gcsim plot exited with "
        << status << "; its message is on the terminal).</p>\n";
    } else {
      h << "<p>Trace <code>" << escape(trace) << "</code> (open the .json in Perfetto or chrome://tracing, the "
           ".paje in ViTE).</p>\n";
      for (const auto& [file, caption] : kPlots) {
        h << "<figure><img src=\"plots/" << file << "\" alt=\"" << caption << "\"><figcaption>" << caption
          << "</figcaption></figure>\n";
      }
    }
  }
}

}  // namespace

std::string write_run_report(const ReportOptions& o) {
  const json j = read_run_json(o.run_json);
  if (!o.trace.empty() && !fs::exists(o.trace) && !fs::exists(fs::path(o.trace).replace_extension(".csv"))) {
    throw std::runtime_error("--trace " + o.trace + ": no such file (expected FILE.json written by --trace, with FILE.csv beside it)");
  }
  std::error_code ec;
  fs::create_directories(o.out_dir, ec);
  if (ec) throw std::runtime_error("--out " + o.out_dir + ": cannot create the directory: " + ec.message());

  std::ostringstream h;
  const std::string heading = report_heading(j);
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << heading << "</title>\n"
    << "<style>body{font-family:sans-serif;max-width:1200px;margin:2em auto;padding:0 1em;color:#222}"
       "table{border-collapse:collapse;margin:0.5em 0 1.5em}th,td{border:1px solid #ccc;padding:3px 10px;text-align:left}"
       "td{font-variant-numeric:tabular-nums}th{background:#f4f4f4}img{max-width:100%;border:1px solid #ddd}"
       "figure{margin:1em 0 2em}figcaption{color:#555;font-size:0.9em}.note{color:#a33}</style></head><body>\n";
  h << "<h1>" << heading << "</h1>\n<p>Report of <code>" << escape(o.run_json) << "</code>.</p>\n";

  write_configuration(h, j);
  write_times(h, j);
  write_processors(h, j);
  write_image(h, j, o);
  write_trace(h, j, o);
  h << "<hr><p><small>Written by <code>gcsim report</code>. Simulated times are the modelled machine's; wall "
       "times are the host's.</small></p>\n</body></html>\n";

  const std::string index = (fs::path(o.out_dir) / "index.html").string();
  std::ofstream out(index);
  if (!out) throw std::runtime_error("cannot write " + index);
  out << h.str();
  return index;
}

}  // namespace gcsim::cli
