#include "apps/pipeline/progress.hpp"

#include <unistd.h>

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
  if (!enabled_) return;
  std::fputs("\r\033[K", stderr);  // back to the line's start and erase it
  std::fflush(stderr);
}

void ProgressLine::update(int done, std::string_view detail) {
  if (enabled_ && total_ > 0) show(double(done) / total_, fmt::format("{}/{} done", done, total_), detail);
}

void ProgressLine::update_fraction(double fraction, std::string_view detail) {
  if (enabled_) show(fraction, fmt::format("{:.0f}%", 100 * fraction), detail);
}

void ProgressLine::show(double fraction, const std::string& done, std::string_view detail) {
  const auto now = std::chrono::steady_clock::now();
  if (now - last_ < std::chrono::milliseconds(100)) return;  // a terminal need not redraw faster
  last_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  // Time left if the rest goes at the pace so far: crude (later sweep points have more nodes),
  // but it moves the right way.
  const std::string left =
      fraction > 0 && fraction < 1 ? fmt::format(", ~{:.0f} s left", elapsed * (1 - fraction) / fraction) : std::string();
  std::fputs(fmt::format("\r\033[K{}: {} ({}){}, {:.0f} s so far", what_, done, detail, left, elapsed).c_str(), stderr);
  std::fflush(stderr);
}

}  // namespace gcsim::pipeline
