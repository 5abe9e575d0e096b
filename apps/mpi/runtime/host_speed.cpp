#include "apps/mpi/runtime/host_speed.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "apps/mpi/runtime/compute_meter.hpp"

namespace gcsim::mpi_layer {
namespace {

// y += a x over arrays that stay in the first-level cache: 2 flops an element, one element at a
// time (the empty asm keeps the compiler from vectorizing it: the node's 601 has no vector unit,
// and a program's own loops are mostly scalar).
double daxpy_flops_per_second() {
  constexpr std::size_t n = 1024;
  std::vector<double> x(n, 1.0), y(n, 0.5);
  const double a = 1.0000001;
  double best = 0;
  for (int trial = 0; trial < 3; ++trial) {
    long long rounds = 0;
    const double start = thread_cpu_seconds();
    double elapsed = 0;
    do {
      for (int r = 0; r < 64; ++r, ++rounds) {
        for (std::size_t i = 0; i < n; ++i) {
          y[i] += a * x[i];
          asm volatile("" : : : "memory");
        }
      }
      elapsed = thread_cpu_seconds() - start;
    } while (elapsed < 0.02);
    best = std::max(best, 2.0 * static_cast<double>(n) * static_cast<double>(rounds) / elapsed);
  }
  return best;
}

std::optional<double> scaled_rate(const std::string& number, const std::string& unit) {
  static const std::vector<std::pair<std::string, double>> units = {
      {"f", 1.0}, {"kf", 1e3}, {"Mf", 1e6}, {"Gf", 1e9}, {"Tf", 1e12}};
  for (const auto& [name, scale] : units) {
    if (unit == name || unit == name + "lops") {
      std::size_t used = 0;
      const double v = std::stod(number, &used);
      if (used != number.size()) return std::nullopt;
      return v * scale;
    }
  }
  return std::nullopt;
}

}  // namespace

HostSpeedChoice parse_host_speed(const std::string& text) {
  const std::string expected = "expects auto, a ratio such as 4, or the host's rate such as 2Gf; got '" + text + "'";
  if (text == "auto") return {};
  HostSpeedChoice c;
  c.text = text;
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used == text.size()) {
      c.kind = HostSpeedChoice::Kind::ratio;
      c.value = v;
    } else {
      const std::optional<double> rate = scaled_rate(text.substr(0, used), text.substr(used));
      if (!rate) throw std::invalid_argument(expected);
      c.kind = HostSpeedChoice::Kind::rate;
      c.value = *rate;
    }
  } catch (const std::logic_error&) {  // stod's invalid_argument and out_of_range
    throw std::invalid_argument(expected);
  }
  if (!std::isfinite(c.value) || c.value <= 0) throw std::invalid_argument(expected + " (it must be positive)");
  return c;
}

double measure_host_flops(const std::string& kernel) {
  if (kernel == "daxpy") return daxpy_flops_per_second();
  throw std::invalid_argument("unknown host kernel '" + kernel + "' (known: daxpy)");
}

HostSpeed::HostSpeed(HostSpeedChoice choice, std::string kernel, double node_flops)
    : choice_(std::move(choice)), kernel_(std::move(kernel)), node_flops_(node_flops) {
  if (choice_.kind == HostSpeedChoice::Kind::ratio) ratio_ = choice_.value;
  if (choice_.kind == HostSpeedChoice::Kind::rate) {
    host_flops_ = choice_.value;
    ratio_ = choice_.value / node_flops_;
  }
}

double HostSpeed::ratio() {
  if (!ratio_) {
    host_flops_ = measure_host_flops(kernel_);
    ratio_ = *host_flops_ / node_flops_;
  }
  return *ratio_;
}

std::string HostSpeed::summary() const {
  if (!ratio_) return fmt::format("host speed {} (not needed: nothing measured)", choice_.text);
  if (choice_.kind == HostSpeedChoice::Kind::ratio) return fmt::format("host speed {:.6g} x the node (given)", *ratio_);
  return fmt::format("host speed {:.6g} x the node ({}: host {:.6g} Mflop/s, node {:.6g} Mflop/s on {})", *ratio_,
                     choice_.kind == HostSpeedChoice::Kind::rate ? "given" : "auto, measured once", *host_flops_ / 1e6,
                     node_flops_ / 1e6, kernel_);
}

nlohmann::json HostSpeed::to_json() const {
  nlohmann::json j{{"given", choice_.text}, {"kernel", kernel_}, {"node_flops", node_flops_}};
  j["ratio"] = ratio_ ? nlohmann::json(*ratio_) : nlohmann::json(nullptr);
  j["host_flops"] = host_flops_ ? nlohmann::json(*host_flops_) : nlohmann::json(nullptr);
  return j;
}

}  // namespace gcsim::mpi_layer
