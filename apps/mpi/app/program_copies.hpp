#pragma once
// Privatization: each rank gets its own copy of the program's globals, as SimGrid's SMPI does it.
// gcsim-mpicc builds the program as a position-independent shared object; this loads one copy of
// that file per rank (each under its own name, so the dynamic loader maps each separately with
// its own data and bss), resolving its MPI_* calls against the gcsim executable, which exports
// them. Each copy is an in-memory file (memfd_create) loaded through /proc/self/fd: no file system
// work per rank, nothing left behind; the descriptors are closed once every copy is loaded.
#include <string>
#include <vector>

namespace gcsim::mpi_layer::app {

using ProgramMain = int (*)(int, char**);

// What becomes of the copies when this object goes: unloaded (dlclose, a run among several in one
// process: gcsim sweep mpi), or left to the process's exit (gcsim mpirun's one run). glibc's
// dlclose scans every loaded object per call, so unloading 4096 copies one by one is quadratic;
// at exit the loader finalizes them all in one pass.
enum class CopiesAtEnd { unload, leave_to_exit };

class ProgramCopies {
 public:
  // Throws pipeline::FileError naming the program and what the loader said.
  ProgramCopies(const std::string& program, int copies, CopiesAtEnd at_end);
  ~ProgramCopies();
  ProgramCopies(const ProgramCopies&) = delete;
  ProgramCopies& operator=(const ProgramCopies&) = delete;

  ProgramMain main_of(int rank) const { return mains_[static_cast<std::size_t>(rank)]; }

 private:
  void load(const std::string& program, const std::string& bytes, int copies, std::vector<int>& fds);
  void unload() noexcept;
  CopiesAtEnd at_end_;
  std::vector<void*> handles_;
  std::vector<ProgramMain> mains_;
};

}  // namespace gcsim::mpi_layer::app
