#include "apps/common/data_file.hpp"

#include <cstdlib>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace gcsim::apps {

std::filesystem::path find_data_file(const std::string& folder, const std::string& relative, const char* env_var,
                                     const std::string& what) {
  namespace fs = std::filesystem;
  std::vector<fs::path> candidates;
  if (const char* d = std::getenv(env_var); d && *d) candidates.push_back(fs::path(d) / relative);
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) candidates.push_back(exe.parent_path().parent_path() / "share" / "gcsim" / folder / relative);
#ifdef GCSIM_SOURCE_DIR
  candidates.push_back(fs::path(GCSIM_SOURCE_DIR) / folder / relative);
#endif
  for (const fs::path& c : candidates)
    if (fs::is_regular_file(c, ec)) return c;
  std::string tried;
  for (const fs::path& c : candidates) tried += "\n  " + c.string();
  throw std::runtime_error("cannot find " + what + " " + folder + "/" + relative + "; looked in:" + tried + "\n(set " +
                           env_var + " to the " + folder + "/ folder of the gcsim sources)");
}

}  // namespace gcsim::apps
