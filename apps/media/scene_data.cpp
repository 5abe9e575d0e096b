#include "apps/media/scene_data.hpp"

#include <cstdlib>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace gcsim::media {

std::filesystem::path find_scene_data(const std::string& relative) {
  namespace fs = std::filesystem;
  std::vector<fs::path> candidates;
  if (const char* d = std::getenv("GCSIM_SCENES_DIR"); d && *d) candidates.push_back(fs::path(d) / relative);
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) candidates.push_back(exe.parent_path().parent_path() / "share" / "gcsim" / "scenes" / relative);
#ifdef GCSIM_SOURCE_DIR
  candidates.push_back(fs::path(GCSIM_SOURCE_DIR) / "scenes" / relative);
#endif
  for (const fs::path& c : candidates)
    if (fs::is_regular_file(c, ec)) return c;
  std::string tried;
  for (const fs::path& c : candidates) tried += "\n  " + c.string();
  throw std::runtime_error("cannot find the scene data file scenes/" + relative + "; looked in:" + tried +
                           "\n(set GCSIM_SCENES_DIR to the scenes/ folder of the gcsim sources)");
}

}  // namespace gcsim::media
