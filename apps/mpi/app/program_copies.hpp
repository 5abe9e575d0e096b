#pragma once
// Privatization: each rank gets its own copy of the program's globals, as SimGrid's SMPI does it.
// gcsim-mpicc builds the program as a position-independent shared object; this loads one copy of
// that file per rank (each under its own name, so the dynamic loader maps each separately with
// its own data and bss), resolving its MPI_* calls against the gcsim executable, which exports
// them. The copies are unlinked once loaded and unloaded when this object goes.
#include <filesystem>
#include <string>
#include <vector>

namespace gcsim::mpi_layer::app {

using ProgramMain = int (*)(int, char**);

class ProgramCopies {
 public:
  // Throws pipeline::FileError naming the program and what the loader said.
  ProgramCopies(const std::string& program, int copies);
  ~ProgramCopies();
  ProgramCopies(const ProgramCopies&) = delete;
  ProgramCopies& operator=(const ProgramCopies&) = delete;

  ProgramMain main_of(int rank) const { return mains_[static_cast<std::size_t>(rank)]; }

 private:
  void load(const std::string& program, const std::filesystem::path& folder, int copies);
  void unload() noexcept;
  std::vector<void*> handles_;
  std::vector<ProgramMain> mains_;
};

}  // namespace gcsim::mpi_layer::app
