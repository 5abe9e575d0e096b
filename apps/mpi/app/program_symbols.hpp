#pragma once
// The MPI functions a program calls that gcsim's MPI does not provide. gcsim's mpi.h renames every
// function it declares to gcsim_MPI_*, so a call still named MPI_* or PMPI_* in the compiled
// program is one the header did not declare (C compiles it as an implicit declaration): loaded as
// is, it would bind to whatever MPI_* the gcsim process happens to contain (the real-MPI backend's
// Open MPI) and fail without a word. Checked before the program is loaded, from its ELF dynamic
// symbol table.
#include <string>
#include <string_view>
#include <vector>

namespace gcsim::mpi_layer::app {

// The undefined MPI_*/PMPI_* symbols of the ELF shared object in `bytes`, in table order; empty
// when there are none or the bytes are not a 64-bit ELF (the loader then says what is wrong).
std::vector<std::string> missing_mpi_functions(std::string_view bytes);

}  // namespace gcsim::mpi_layer::app
