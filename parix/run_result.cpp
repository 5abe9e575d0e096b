#include "parix/run_result.hpp"

#include <algorithm>

namespace gcsim::parix {

double RunResult::mean_compute_seconds() const {
  if (processors.empty()) return 0;
  double s = 0;
  for (const auto& p : processors) s += machine::to_seconds(p.compute);
  return s / static_cast<double>(processors.size());
}

double RunResult::mean_comm_seconds() const {
  if (processors.empty()) return 0;
  double s = 0;
  for (const auto& p : processors) s += machine::to_seconds(p.comm);
  return s / static_cast<double>(processors.size());
}

double RunResult::mean_waiting_seconds() const {
  if (processors.empty()) return 0;
  double s = 0;
  for (const auto& p : processors) s += machine::to_seconds(p.waiting);
  return s / static_cast<double>(processors.size());
}

double RunResult::max_comm_seconds() const {
  double m = 0;
  for (const auto& p : processors) m = std::max(m, machine::to_seconds(p.comm));
  return m;
}

std::int64_t RunResult::total_messages() const {
  std::int64_t n = 0;
  for (const auto& p : processors) n += p.messages_sent;
  return n;
}

std::map<std::string, std::int64_t, std::less<>> RunResult::total_ops() const {
  std::map<std::string, std::int64_t, std::less<>> t;
  for (const auto& p : processors) {
    for (const auto& [k, v] : p.ops) t[k] += v;
  }
  return t;
}

nlohmann::json RunResult::to_json() const {
  nlohmann::json j;
  j["simulated"] = {{"total_s", simulated_seconds()},
                    {"compute_s", mean_compute_seconds()},
                    {"comm_s", mean_comm_seconds()},
                    {"comm_max_s", max_comm_seconds()},
                    {"waiting_s", mean_waiting_seconds()},
                    {"communicating_s", mean_communicating_seconds()},
                    {"total_ps", makespan}};
  j["wall"] = {{"total_s", wall_seconds}};
  j["events"] = events;
  j["nodes"] = nodes;
  j["model"] = model;
  j["config"] = config_name;
  j["messages"] = total_messages();
  j["ops"] = total_ops();
  nlohmann::json procs = nlohmann::json::array();
  for (std::size_t i = 0; i < processors.size(); ++i) {
    const auto& p = processors[i];
    procs.push_back({{"id", i},
                     {"finish_s", machine::to_seconds(p.finish)},
                     {"compute_s", machine::to_seconds(p.compute)},
                     {"comm_s", machine::to_seconds(p.comm)},
                     {"connect_s", machine::to_seconds(p.connect)},
                     {"waiting_s", machine::to_seconds(p.waiting)},
                     {"messages_sent", p.messages_sent},
                     {"bytes_sent", p.bytes_sent},
                     {"connections", p.connections}});
  }
  j["processors"] = procs;
  if (!memory_warning.empty()) {
    j["memory"] = {{"peak_bytes", memory_peak}, {"peak_processor", memory_peak_processor},
                   {"node_bytes", memory_capacity}, {"warning", memory_warning}};
  }
  return j;
}

}  // namespace gcsim::parix
