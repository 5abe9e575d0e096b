#include "apps/pipeline/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <fmt/format.h>

namespace gcsim::pipeline {

bool progress_wanted() {
  if (const char* v = std::getenv("GCSIM_PROGRESS"); v && *v) return v[0] != '0';
  return ::isatty(STDERR_FILENO) != 0;
}

ProgressLine::ProgressLine(std::string what, int total)
    : what_(std::move(what)), total_(total), enabled_(progress_wanted() && total != 1),
      start_(std::chrono::steady_clock::now()), last_(start_ - std::chrono::seconds(1)) {}

ProgressLine::~ProgressLine() { clear(); }

void ProgressLine::clear() {
  if (!enabled_ || finished_) return;
  std::fputs("\r\033[K", stderr);  // back to the line's start and erase it
  std::fflush(stderr);
}

double ProgressLine::elapsed_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

namespace {

// Time left if the rest goes at the pace so far: crude (later sweep points have more nodes), but
// it moves the right way.
std::optional<double> at_pace_so_far(double fraction, double elapsed) {
  if (fraction > 0 && fraction < 1) return elapsed * (1 - fraction) / fraction;
  return std::nullopt;
}

// Whole percent, rounded down: 99.7 % of the work is not yet 100 %.
std::string percent(double fraction) { return fmt::format("{:.0f}%", std::floor(100 * std::clamp(fraction, 0.0, 1.0))); }

}  // namespace

void ProgressLine::update(int done, std::string_view detail) {
  if (!enabled_ || total_ <= 0 || finished_ || !due()) return;
  show(fmt::format("{}/{} done", done, total_), detail, at_pace_so_far(double(done) / total_, elapsed_seconds()));
}

void ProgressLine::update_fraction(double fraction, std::string_view detail) {
  update_fraction(fraction, detail, at_pace_so_far(fraction, elapsed_seconds()));
}

void ProgressLine::update_fraction(double fraction, std::string_view detail, std::optional<double> seconds_left) {
  if (enabled_ && !finished_ && due()) show(percent(fraction), detail, seconds_left);
}

void ProgressLine::finish(std::string_view detail) {
  if (!enabled_ || finished_) return;
  show("100%", detail, std::nullopt);
  std::fputs("\n", stderr);
  std::fflush(stderr);
  finished_ = true;
}

bool ProgressLine::due() {
  const auto now = std::chrono::steady_clock::now();
  if (now - last_ < std::chrono::milliseconds(100)) return false;  // a terminal need not redraw faster
  last_ = now;
  return true;
}

void ProgressLine::show(const std::string& done, std::string_view detail, std::optional<double> seconds_left) {
  const double elapsed = elapsed_seconds();
  const std::string left = seconds_left ? fmt::format(", ~{:.0f} s left", *seconds_left) : std::string();
  std::fputs(fmt::format("\r\033[K{}: {} ({}){}, {:.0f} s so far", what_, done, detail, left, elapsed).c_str(), stderr);
  std::fflush(stderr);
}

}  // namespace gcsim::pipeline
