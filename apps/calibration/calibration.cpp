#include "apps/calibration/calibration.hpp"

#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "machine/builtin_machines.hpp"

namespace gcsim::calibration {

std::vector<std::string> split_list(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, sep)) out.push_back(item);
  return out;
}

namespace {

// Leaves only the listed rows and columns ("1+8", "CORNELL+PICROOM", "1+8+CORNELL"): a number is a
// node count, a name a column; rows or columns not named at all are all kept.
void keep_cells(MeasuredTable& t, const std::string& items, const std::string& spec, const std::string& option) {
  std::vector<int> rows, columns;
  for (const auto& item : split_list(items, '+')) {
    int n = 0;
    try {
      std::size_t used = 0;
      n = std::stoi(item, &used);
      if (used != item.size()) n = 0;
    } catch (const std::exception&) {
    }
    if (n >= 1 && t.row_of(n) >= 0) {
      rows.push_back(t.row_of(n));
    } else if (n < 1 && t.column_of(item) >= 0) {
      columns.push_back(t.column_of(item));
    } else {
      std::string names;
      for (const auto& c : t.columns) names += (names.empty() ? "" : ", ") + c;
      throw std::invalid_argument(fmt::format("{} {}: '{}' is neither a node count nor a column of table {} (columns: {})",
                                              option, spec, item, t.id, names));
    }
  }
  auto kept = [](const std::vector<int>& named, int i) {
    return named.empty() || std::find(named.begin(), named.end(), i) != named.end();
  };
  for (std::size_t r = 0; r < t.nodes.size(); ++r)
    for (std::size_t k = 0; k < t.columns.size(); ++k)
      if (!kept(rows, int(r)) || !kept(columns, int(k))) t.values[r][k] = kNotMeasured;
}

}  // namespace

MeasuredTable table_from_spec(const std::string& spec, const std::string& option) {
  std::string source = spec, rows;
  if (const auto at = spec.rfind('@'); at != std::string::npos) {
    source = spec.substr(0, at);
    rows = spec.substr(at + 1);
  }
  MeasuredTable t;
  if (const auto colon = source.rfind(".csv:"); colon != std::string::npos) {
    t = load_measured_csv(source.substr(0, colon + 4), source.substr(colon + 5));
  } else {
    t = thesis_table(source);
  }
  if (!rows.empty()) keep_cells(t, rows, spec, option);
  return t;
}

std::vector<MeasuredTable> tables_from_specs(const std::vector<std::string>& specs, const std::string& option) {
  std::vector<MeasuredTable> out;
  for (const auto& s : specs) {
    if (s.empty()) throw std::invalid_argument(option + ": empty table name (expected e.g. 4.6 or 4.6,4.3@1)");
    out.push_back(table_from_spec(s, option));
  }
  if (out.empty()) throw std::invalid_argument(option + ": no tables (expected e.g. 4.6 or 4.6,4.3@1)");
  return out;
}

CalibrationResult calibrate(const MachineFile& file, const std::vector<MeasuredTable>& tables,
                            const std::vector<std::string>& free, Predictor& predictor,
                            const std::function<void(const CalibrationTrial&)>& on_trial) {
  if (free.empty()) throw std::invalid_argument("--free: no parameters to fit");
  std::vector<double> initial;
  for (const auto& key : free) {
    file.check_free_key(key);
    initial.push_back(file.value(key));
    if (!(initial.back() > 0))
      throw std::invalid_argument(fmt::format("--free {}: its value in {} is {}; give it a positive starting value", key,
                                              file.source(), initial.back()));
  }
  // The fitter moves y; a key's value is initial * exp(L tanh(y / L)): positive, and never more than
  // a factor e^L = 1000 from its start, so a key the tables barely determine cannot step to a value
  // that overflows the simulated clock. Near the start the map is the plain log scale.
  const double L = std::log(1000.0);
  auto log_factor = [L](double y) { return L * std::tanh(y / L); };
  auto values_at = [&](const std::vector<double>& y) {
    std::map<std::string, double> v;
    for (std::size_t i = 0; i < free.size(); ++i) v[free[i]] = initial[i] * std::exp(log_factor(y[i]));
    return v;
  };
  std::size_t cells = 0;
  for (const auto& t : tables)
    for (const auto& row : t.values)
      for (double v : row) cells += !std::isnan(v);
  int trials = 0;
  auto residuals = [&](const std::vector<double>& x) {
    const auto values = values_at(x);
    const auto predicted = predictor.predict(tables, file.with(values));
    std::vector<double> r;
    double cost = 0;
    for (const auto& c : compare(tables, predicted)) r.push_back(c.error()), cost += c.error() * c.error();
    if (on_trial) on_trial({++trials, values, cost});
    return r;
  };
  CalibrationResult out;
  out.fit = least_squares(residuals, std::vector<double>(free.size(), 0.0), cells);
  const auto best = values_at(out.fit.x);
  for (std::size_t i = 0; i < free.size(); ++i) {
    const double slope = 1.0 / std::pow(std::cosh(out.fit.x[i] / L), 2);  // d log(value) / dy
    out.parameters.push_back({free[i], initial[i], best.at(free[i]), best.at(free[i]) * slope * out.fit.sigma[i]});
    if (std::abs(log_factor(out.fit.x[i])) > 0.99 * L)
      out.warnings.push_back(fmt::format("{} ended {} times its start ({} -> {:.6g}): the fitted tables hardly determine it; "
                                         "fix it in the machine file and leave it out of --free",
                                         free[i], best.at(free[i]) / initial[i], initial[i], best.at(free[i])));
  }
  out.fitted = file.with(best);
  out.cells = compare(tables, predictor.predict(tables, out.fitted));
  for (auto& c : out.cells) c.fitted = true;
  return out;
}

namespace {

// `base = ...` of a file written at out_path: the built-in machine, or file's path relative to it.
std::string base_of(const MachineFile& file, const std::string& out_path) {
  if (file.source().front() == '<') {  // the built-in default: builtin:NAME for configs/NAME.toml
    const std::string_view name = machine::kDefaultMachineFile;
    return "builtin:" + std::string(name.substr(0, name.rfind(".toml")));
  }
  const auto dir = std::filesystem::absolute(out_path).parent_path();
  return std::filesystem::relative(std::filesystem::absolute(file.source()), dir).generic_string();
}

// The keys grouped by table: [network] connect_base_us = ... (values in key order, tables once).
std::string key_lines(const std::vector<std::pair<std::string, std::string>>& keys) {
  std::string text, table;
  for (const auto& [key, line] : keys) {
    const auto dot = key.find('.');
    const std::string t = key.substr(0, dot);
    if (t != table) text += fmt::format("\n[{}]\n", table = t);
    text += key.substr(dot + 1) + " = " + line + "\n";
  }
  return text;
}

}  // namespace

std::string interrupted_file_text(const MachineFile& file, const std::string& out_path, const std::string& specs,
                                  const CalibrationTrial* best, int trials, const std::string& command) {
  std::string text = fmt::format("# {}: calibration INTERRUPTED after {} trials, not a converged fit.\n# Written by:\n#   {}\n",
                                 file.config().name, trials, command);
  text += best ? fmt::format("# The best trial so far (number {}, sum of squared relative errors {:.6g}) on table(s) {}.\n",
                             best->number, best->cost, specs)
               : "# No trial finished: this is the base machine unchanged.\n";
  text += fmt::format("base = \"{}\"\nname = \"{} (calibration on {} interrupted)\"\n", base_of(file, out_path),
                      file.config().name, specs);
  if (!best) return text;
  std::vector<std::pair<std::string, std::string>> keys;
  for (const auto& [key, value] : best->values)
    keys.emplace_back(key, fmt::format("{:.6g}    # best so far; was {:.6g}", value, file.value(key)));
  return text + key_lines(keys);
}

std::string fitted_file_text(const MachineFile& file, const std::string& out_path, const std::vector<std::string>& specs,
                             const CalibrationResult& r, const std::string& command, const std::string& workload) {
  const std::string base = base_of(file, out_path);
  const auto s = summarize(r.cells);
  std::string text = fmt::format("# {}, calibrated.\n# Written by:\n#   {}\n", file.config().name, command);
  text += fmt::format("# Fitted by least squares (GSL Levenberg-Marquardt, {} iterations, {}) to {} measured figures:\n",
                      r.fit.iterations, r.fit.reason, r.cells.size());
  for (const auto& t : s)
    text += fmt::format("#   table {}: {} cells, median |error| {:.1f} %, max {:.1f} %\n", t.table, t.cells,
                        100 * t.median_error, 100 * t.max_error);
  if (!workload.empty()) text += "# The scenes as the thesis's runs converged (table 4.2's loops; --workload):\n" + workload;
  text += "# Every other table is a prediction: `gcsim validate --config " + out_path + "`.\n";
  text += fmt::format("base = \"{}\"\nname = \"{} (calibrated on {})\"\n\n", base, file.config().name, fmt::join(specs, ","));
  text += fmt::format("[calibration]\nfitted = [");
  for (std::size_t i = 0; const auto& t : specs) text += (i++ ? ", " : "") + fmt::format("\"{}\"", t);
  text += "]\n";
  std::string table;
  for (const auto& p : r.parameters) {
    const auto dot = p.key.find('.');
    const std::string t = p.key.substr(0, dot);
    if (t != table) text += fmt::format("\n[{}]\n", table = t);
    text += fmt::format("{} = {:.6g}    # fitted: +- {:.2g} (one standard error); was {:.6g}\n", p.key.substr(dot + 1), p.value,
                        p.sigma, p.initial);
  }
  return text;
}

}  // namespace gcsim::calibration
