#pragma once
// Where a data file of the gcsim sources (a plotting script, a scene's mesh) is at run time:
// $ENV_VAR/<relative>, else beside an installed binary (<exe dir>/../share/gcsim/<folder>/<relative>),
// else in the source tree the binary was built from (<source>/<folder>/<relative>).
#include <filesystem>
#include <string>

namespace gcsim::apps {

// The first of those that is a regular file. Throws std::runtime_error naming `what`
// ("the plotting script"), <folder>/<relative>, every path tried and the variable to set.
std::filesystem::path find_data_file(const std::string& folder, const std::string& relative, const char* env_var,
                                     const std::string& what);

}  // namespace gcsim::apps
