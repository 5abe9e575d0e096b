#include "apps/mpi/app/program_copies.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "apps/pipeline/failure.hpp"

namespace gcsim::mpi_layer::app {
namespace fs = std::filesystem;

namespace {

// A fresh folder for the copies (under TMPDIR), removed when the copies are loaded.
fs::path scratch_folder() {
  std::string pattern = (fs::temp_directory_path() / "gcsim-mpirun-XXXXXX").string();
  if (!::mkdtemp(pattern.data())) throw pipeline::FileError("gcsim mpirun: cannot make a folder in " + fs::temp_directory_path().string());
  return pattern;
}

}  // namespace

ProgramCopies::ProgramCopies(const std::string& program, int copies) {
  std::error_code ec;
  if (fs::is_directory(program, ec)) throw pipeline::FileError(program + ": is a folder, not a program");
  if (!fs::is_regular_file(program, ec)) throw pipeline::FileError(program + ": no such program file");
  const fs::path folder = scratch_folder();
  struct Remove {
    fs::path p;
    ~Remove() {
      std::error_code ignored;
      fs::remove_all(p, ignored);
    }
  } remove{folder};
  try {
    load(program, folder, copies);
  } catch (...) {
    unload();  // the copies loaded so far
    throw;
  }
}

void ProgramCopies::load(const std::string& program, const std::filesystem::path& folder, int copies) {
  std::error_code ec;
  for (int rank = 0; rank < copies; ++rank) {
    const fs::path copy = folder / ("rank-" + std::to_string(rank) + ".so");
    if (!fs::copy_file(program, copy, ec)) throw pipeline::FileError(program + ": cannot copy it to " + copy.string() + ": " + ec.message());
    void* handle = ::dlopen(copy.c_str(), RTLD_NOW | RTLD_LOCAL);
    fs::remove(copy, ec);
    if (!handle) {
      const char* why = ::dlerror();
      throw pipeline::FileError(program + ": cannot load it as an MPI program (" + (why ? why : "?") +
                                "); build it with gcsim-mpicc or gcsim-mpicxx");
    }
    handles_.push_back(handle);
    auto main = reinterpret_cast<ProgramMain>(::dlsym(handle, "main"));
    if (!main) throw pipeline::FileError(program + ": has no main function");
    mains_.push_back(main);
  }
}

ProgramCopies::~ProgramCopies() { unload(); }

void ProgramCopies::unload() noexcept {
  for (auto it = handles_.rbegin(); it != handles_.rend(); ++it) ::dlclose(*it);
  handles_.clear();
  mains_.clear();
}

}  // namespace gcsim::mpi_layer::app
