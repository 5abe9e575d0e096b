#include "apps/cli/trace_plot_runner.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
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

int run_plot_script(const std::vector<std::string>& args) {
  const std::string python = plot_python();
  const std::string script = plot_script();
  std::vector<std::string> argv_strings{python, "-B", script};  // -B: no __pycache__ in the source tree
  argv_strings.insert(argv_strings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& s : argv_strings) argv.push_back(s.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int err = posix_spawnp(&pid, python.c_str(), nullptr, nullptr, argv.data(), environ);
  if (err != 0) {
    throw std::runtime_error(fmt::format("cannot start {} for the plots ({}); install Debian's python3, "
                                         "python3-matplotlib and python3-numpy, or set GCSIM_PYTHON",
                                         python, std::strerror(err)));
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error("waiting for the plotting script failed");
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  throw std::runtime_error(fmt::format("the plotting script ({} {}) was killed by signal {}", python, script,
                                       WIFSIGNALED(status) ? WTERMSIG(status) : 0));
}

}  // namespace gcsim::cli
