#include "apps/calibration/predictor.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <mutex>
#include <optional>
#include <stdexcept>

#include "apps/common/ordered_parallel.hpp"
#include "apps/programs/broadcast_experiment.hpp"
#include "apps/radiosity/radiosity.hpp"
#include "parix/host/interruption.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::calibration {
namespace {

parix::SimulationOptions simulation(const machine::MachineConfig& c, int nodes, const std::string& model) {
  parix::SimulationOptions s;
  s.config = machine::with_nodes(c, nodes);
  if (!model.empty()) s.config.network_model = model;  // "": the machine file's own
  return s;
}

// Built-in scene names are lower case; table columns are the thesis's upper-case names.
std::string scene_of(const std::string& column) {
  std::string s = column;
  for (char& ch : s) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return s;
}

bool is_broadcast(const MeasuredTable& t) { return t.id == "4.6" || t.id == "4.7"; }

int measured_cells(const MeasuredTable& t) {
  int n = 0;
  for (const auto& row : t.values)
    for (double v : row) n += !std::isnan(v);
  return n;
}

}  // namespace

void Predictor::run_done() {
  ++predict_done_;
  if (on_run_) on_run_(predict_done_, predict_total_);
}

// Fills g (kNotMeasured to start) cell by cell: an interruption leaves the finished cells in it.
void Predictor::predict_broadcast(const MeasuredTable& t, const machine::MachineConfig& c, Grid& g) {
  const parix::BcastAlgo algo = t.id == "4.7" ? parix::BcastAlgo::tree : parix::BcastAlgo::sequential;
  std::mutex lock;
  std::vector<std::pair<int, int>> cells;
  for (std::size_t r = 0; r < t.nodes.size(); ++r)
    for (std::size_t k = 0; k < t.columns.size(); ++k)
      if (!std::isnan(t.values[r][k])) cells.emplace_back(int(r), int(k));
  const MeasuredTable layout = thesis_table(t.id);  // t's columns may be a subset, in any order
  apps::parallel_for(int(cells.size()), settings_.jobs, [&](int i) {
    const auto [r, k] = cells[i];
    const int column = layout.column_of(t.columns[k]);
    const std::int64_t bytes = programs::kThesisBroadcastSizes[column];
    const parix::RunResult run = parix::run_simulated(simulation(c, t.nodes[r], settings_.model), [&](parix::Processor& p) {
      programs::all_node_broadcast(p, bytes, algo);
    });
    std::lock_guard<std::mutex> guard(lock);
    g[r][k] = machine::to_milliseconds(run.makespan);
    ++runs_;
    run_done();
  });
}

Predictor::RadiosityRun Predictor::one_node_from_counts(const std::string& scene, const machine::MachineConfig& c) {
  RadiosityRun r;
  machine::SimTime t = 0;
  for (const auto& [op, count] : one_node_ops_.at(scene)) t += machine::op_time(c, op, count);
  r.seconds = machine::to_seconds(t);
  return r;
}

radiosity::SolverOptions Predictor::solver_options() const {
  radiosity::SolverOptions o;
  o.hemicube.resolution = settings_.hemicube;
  o.shooters = settings_.shooters;
  o.energy = settings_.energy;
  return o;
}

std::vector<Predictor::RunKey> Predictor::radiosity_keys(const std::vector<MeasuredTable>& tables) {
  std::vector<RunKey> keys;
  for (const MeasuredTable& t : tables) {
    if (is_broadcast(t)) continue;
    const bool tree = t.id == "4.8";
    for (std::size_t r = 0; r < t.nodes.size(); ++r)
      for (std::size_t k = 0; k < t.columns.size(); ++k) {
        if (std::isnan(t.values[r][k])) continue;
        keys.emplace_back(scene_of(t.columns[k]), t.nodes[r], tree);
        if (t.id == "4.4") keys.emplace_back(scene_of(t.columns[k]), 1, false);  // speedup needs the 1-node time
      }
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

void Predictor::prepare(const std::vector<MeasuredTable>& tables) { load_scenes(radiosity_keys(tables)); }

void Predictor::share_scenes(const Predictor& from) {
  if (from.settings_.match_thesis_loops != settings_.match_thesis_loops || from.settings_.energy != settings_.energy ||
      from.settings_.hemicube != settings_.hemicube || from.settings_.shooters != settings_.shooters)
    throw std::logic_error("share_scenes: the predictors' scenes would differ");
  scenes_.insert(from.scenes_.begin(), from.scenes_.end());
  matches_.insert(from.matches_.begin(), from.matches_.end());
}

// Each scene is loaded once per predictor, not once per run or per trial of a fit; runs only read
// it. Matching a scene to table 4.2 solves it a dozen times on the host, scenes side by side.
void Predictor::load_scenes(const std::vector<RunKey>& keys) {
  std::vector<std::string> missing;
  for (const RunKey& k : keys)
    if (!scenes_.count(std::get<0>(k)) && std::ranges::find(missing, std::get<0>(k)) == missing.end())
      missing.push_back(std::get<0>(k));
  std::vector<radiosity::Scene> loaded(missing.size());
  std::vector<std::optional<radiosity::LoopMatch>> matched(missing.size());
  apps::parallel_for(int(missing.size()), settings_.jobs, [&](int i) {
    loaded[i] = radiosity::flatten(radiosity::load_scene_world(missing[i]));
    const std::optional<int> target = radiosity::thesis_loops(missing[i], settings_.energy);
    if (!settings_.match_thesis_loops || !target) return;
    matched[i] = radiosity::match_loops(loaded[i], solver_options(), *target);
    loaded[i] = radiosity::with_reflectances_scaled(std::move(loaded[i]), matched[i]->scale);
  });
  for (std::size_t i = 0; i < missing.size(); ++i) {
    scenes_.emplace(missing[i], std::move(loaded[i]));
    if (matched[i]) matches_.emplace(missing[i], *matched[i]);
  }
}

void Predictor::run_radiosity(const std::vector<RunKey>& keys, const machine::MachineConfig& c,
                              std::map<RunKey, RadiosityRun>& out) {
  std::vector<RunKey> todo;
  for (const RunKey& k : keys) {
    if (std::get<1>(k) == 1 && one_node_ops_.count(std::get<0>(k))) out[k] = one_node_from_counts(std::get<0>(k), c);
    else todo.push_back(k);
  }
  predict_total_ += int(todo.size());
  load_scenes(todo);
  std::mutex lock;
  apps::parallel_for(int(todo.size()), settings_.jobs, [&](int i) {
    const auto& [scene_name, nodes, tree] = todo[i];
    const radiosity::Scene& scene = scenes_.at(scene_name);
    radiosity::ParallelOptions o;
    o.solver = solver_options();
    o.cell_assignment = settings_.cell_assignment;
    o.side_faces = settings_.side_faces;
    o.merge = settings_.merge;
    o.ff_exchange = settings_.ff_exchange;
    o.bcast = tree ? parix::BcastAlgo::tree : parix::BcastAlgo::sequential;
    radiosity::ParallelOutcome outcome;
    o = radiosity::with_shared_projections(o);
    const parix::RunResult run = parix::run_simulated(simulation(c, nodes, settings_.model), [&](parix::Processor& p) {
      radiosity::radiosity_program(p, scene, o, &outcome);
    });
    std::lock_guard<std::mutex> g(lock);
    const double comm = settings_.comm_time_of == CommTimeOf::root ? machine::to_seconds(run.processors.at(0).comm)
                                                                     : run.mean_comm_seconds();
    out[todo[i]] = {run.simulated_seconds(), comm};
    if (nodes == 1) one_node_ops_[scene_name] = run.total_ops();
    ++runs_;
    run_done();
  });
}

std::vector<Grid> Predictor::predict(const std::vector<MeasuredTable>& tables, const machine::MachineConfig& c,
                                     std::exception_ptr* interruption) {
  // Gather every radiosity run the tables need, then simulate each once.
  predict_done_ = predict_total_ = 0;
  for (const MeasuredTable& t : tables)
    if (is_broadcast(t)) predict_total_ += measured_cells(t);
  const std::vector<RunKey> keys = radiosity_keys(tables);
  // An interruption stops the runs; what finished is kept (the maps and grids are filled run by run).
  std::exception_ptr stopped;
  auto guarded = [&](auto&& step) {
    if (stopped) return;
    try {
      step();
    } catch (const parix::host::Interrupted&) {
      if (!interruption) throw;
      stopped = std::current_exception();
    }
  };
  std::map<RunKey, RadiosityRun> runs;
  guarded([&] { run_radiosity(keys, c, runs); });

  std::vector<Grid> out;
  for (const MeasuredTable& t : tables) {
    Grid g(t.nodes.size(), std::vector<double>(t.columns.size(), kNotMeasured));
    if (is_broadcast(t)) {
      guarded([&] { predict_broadcast(t, c, g); });
      out.push_back(std::move(g));
      continue;
    }
    for (std::size_t r = 0; r < t.nodes.size(); ++r)
      for (std::size_t k = 0; k < t.columns.size(); ++k) {
        if (std::isnan(t.values[r][k])) continue;
        const auto run = runs.find({scene_of(t.columns[k]), t.nodes[r], t.id == "4.8"});
        const auto one = runs.find({scene_of(t.columns[k]), 1, false});
        if (run == runs.end() || (t.id == "4.4" && one == runs.end())) continue;  // interrupted before it
        if (t.id == "4.3" || t.id == "4.8") g[r][k] = run->second.seconds;
        else if (t.id == "4.5") g[r][k] = run->second.comm_seconds;
        else g[r][k] = 100.0 * one->second.seconds / run->second.seconds;  // 4.4
      }
    out.push_back(std::move(g));
  }
  if (interruption) *interruption = stopped;
  return out;
}

}  // namespace gcsim::calibration
