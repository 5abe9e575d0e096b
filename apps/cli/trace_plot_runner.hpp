#pragma once
// Runs traces/plot_trace.py (the matplotlib plots of `gcsim plot` and `gcsim report`) with
// Debian's python3, which is where python3-matplotlib installs. The script reports bad input
// itself, in one line naming the file; this only finds the interpreter and the script.
#include <string>
#include <vector>

namespace gcsim::cli {

// The python3 to use: $GCSIM_PYTHON, else /usr/bin/python3, else python3 on the PATH.
std::string plot_python();
// traces/plot_trace.py: $GCSIM_TRACES_DIR, else beside an installed binary
// (../share/gcsim/traces), else in the source tree the binary was built from.
std::string plot_script();
// Runs python3 plot_trace.py args...; returns its exit status (its output goes to ours).
// Throws std::runtime_error when the interpreter or the script cannot be found or started.
int run_plot_script(const std::vector<std::string>& args);

}  // namespace gcsim::cli
