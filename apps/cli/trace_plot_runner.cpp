#include "apps/cli/trace_plot_runner.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "apps/common/data_file.hpp"

extern char** environ;

namespace gcsim::cli {

namespace fs = std::filesystem;

std::string plot_python() {
  if (const char* p = std::getenv("GCSIM_PYTHON"); p && *p) return p;
  // Debian's interpreter first: a python3 earlier on the PATH (pyenv, a virtualenv) usually lacks
  // the python3-matplotlib package.
  if (fs::exists("/usr/bin/python3")) return "/usr/bin/python3";
  return "python3";
}

std::string plot_script() {
  return apps::find_data_file("traces", "plot_trace.py", "GCSIM_TRACES_DIR", "the plotting script").string();
}

namespace {

// Copies the script's stderr to ours as it comes; returns how many bytes it wrote.
std::size_t forward_stderr(int from) {
  std::size_t total = 0;
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(from, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    total += std::size_t(n);
    std::fwrite(buffer, 1, std::size_t(n), stderr);
  }
  return total;
}

int wait_for(pid_t pid) {
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error("waiting for the plotting script failed");
  }
  return status;
}

}  // namespace

int run_plot_script(const std::vector<std::string>& args) {
  const std::string python = plot_python();
  const std::string script = plot_script();
  std::vector<std::string> argv_strings{python, "-B", script};  // -B: no __pycache__ in the source tree
  argv_strings.insert(argv_strings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& s : argv_strings) argv.push_back(s.data());
  argv.push_back(nullptr);
  // The script's stderr comes through a pipe, so a failure that says nothing (a GCSIM_PYTHON
  // that is not python) is noticed and explained instead of ending gcsim silently.
  int pipe_fds[2];
  if (::pipe2(pipe_fds, O_CLOEXEC) != 0) throw std::runtime_error("cannot start the plotting script: no pipe");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDERR_FILENO);
  pid_t pid = 0;
  const int err = posix_spawnp(&pid, python.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(pipe_fds[1]);
  if (err != 0) {
    ::close(pipe_fds[0]);
    throw std::runtime_error(fmt::format("cannot start {} for the plots ({}); install Debian's python3, "
                                         "python3-matplotlib and python3-numpy, or set GCSIM_PYTHON",
                                         python, std::strerror(err)));
  }
  const std::size_t said = forward_stderr(pipe_fds[0]);
  ::close(pipe_fds[0]);
  const int status = wait_for(pid);
  if (WIFEXITED(status) && (WEXITSTATUS(status) == 0 || said > 0)) return WEXITSTATUS(status);
  if (WIFEXITED(status))
    throw std::runtime_error(fmt::format("the plotting script ({} {}) failed with exit status {} and no message; "
                                         "is GCSIM_PYTHON a python3 with python3-matplotlib?",
                                         python, script, WEXITSTATUS(status)));
  throw std::runtime_error(fmt::format("the plotting script ({} {}) was killed by signal {}", python, script,
                                       WIFSIGNALED(status) ? WTERMSIG(status) : 0));
}

}  // namespace gcsim::cli
