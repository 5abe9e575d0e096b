// The C entry points of error texts, versions, MPI_Pcontrol and MPI_Dims_create: no runtime involved.
#include <algorithm>
#include <cstring>
#include <span>

#include "apps/mpi/c_call.hpp"
#include "apps/mpi/topology.hpp"

using namespace gcsim::mpi_layer;

extern "C" {

int MPI_Error_string(int errorcode, char* string, int* resultlen) {
  return c_call([&](Registry&) {
    if (!string) fail(MPI_ERR_ARG, "null string");
    const std::string_view text = error_text(errorcode);
    if (text.empty()) fail(MPI_ERR_ARG, "not an error code");
    const std::size_t n = std::min<std::size_t>(text.size(), MPI_MAX_ERROR_STRING - 1);
    std::memcpy(string, text.data(), n);
    string[n] = '\0';
    out_arg(resultlen) = static_cast<int>(n);
  });
}

int MPI_Error_class(int errorcode, int* errorclass) {
  return c_call([&](Registry&) {
    if (!is_error_code(errorcode)) fail(MPI_ERR_ARG, "not an error code");
    out_arg(errorclass) = errorcode;
  });
}

int MPI_Get_version(int* version, int* subversion) {
  return c_call([&](Registry&) {
    out_arg(version) = MPI_VERSION;
    out_arg(subversion) = MPI_SUBVERSION;
  });
}

int MPI_Get_library_version(char* version, int* resultlen) {
  return c_call([&](Registry&) {
    if (!version) fail(MPI_ERR_ARG, "null string");
    const std::string_view text = "gcsim MPI layer for the simulated Parsytec GC-PowerPlus (MPI 3.1 subset)";
    std::memcpy(version, text.data(), text.size());
    version[text.size()] = '\0';
    out_arg(resultlen) = static_cast<int>(text.size());
  });
}

// Profiling control: gcsim's traces record every run whole, so levels change nothing.
int MPI_Pcontrol(const int level, ...) {
  (void)level;
  return MPI_SUCCESS;
}

int MPI_Dims_create(int nnodes, int ndims, int dims[]) {
  return c_call([&](Registry&) {
    if (ndims < 0) fail(MPI_ERR_DIMS, "negative number of dimensions");
    if (ndims > 0 && !dims) fail(MPI_ERR_ARG, "null dims");
    dims_create(nnodes, std::span(dims, static_cast<std::size_t>(ndims)));
  });
}

}  // extern "C"
