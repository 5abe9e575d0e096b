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
    : what_(std::move(what)), total_(total), enabled_(progress_wanted() && total > 1),
      start_(std::chrono::steady_clock::now()) {}

ProgressLine::~ProgressLine() { clear(); }

void ProgressLine::clear() {
  if (!enabled_) return;
  std::fputs("\r\033[K", stderr);  // back to the line's start and erase it
  std::fflush(stderr);
}

void ProgressLine::update(int done, std::string_view detail) {
  if (!enabled_) return;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  // Time left if the remaining steps take as long as the finished ones did on average: a crude
  // guess (later sweep points have more nodes), but it moves the right way.
  const std::string left =
      done > 0 && done < total_ ? fmt::format(", ~{:.0f} s left", elapsed / done * (total_ - done)) : std::string();
  std::fputs(fmt::format("\r\033[K{}: {}/{} done ({}){}, {:.0f} s so far", what_, done, total_, detail, left, elapsed).c_str(),
             stderr);
  std::fflush(stderr);
}

}  // namespace gcsim::pipeline
