// gcsim's <mpi.h> in a C++17 program compiled with -Wall -Wextra -pedantic -Werror: the header
// is valid C++, its handles are ints, its constants are what the standard requires of them.
#include <mpi.h>

#include <cstdio>
#include <type_traits>

static_assert(std::is_same_v<MPI_Comm, int> && std::is_same_v<MPI_Datatype, int> && std::is_same_v<MPI_Op, int>);
static_assert(std::is_same_v<MPI_Group, int> && std::is_same_v<MPI_Request, int> && std::is_same_v<MPI_Errhandler, int>);
static_assert(sizeof(MPI_Aint) == sizeof(void*));
static_assert(MPI_SUCCESS == 0 && MPI_ERR_LASTCODE >= MPI_ERR_PENDING);
static_assert(MPI_IDENT < MPI_CONGRUENT && MPI_CONGRUENT < MPI_SIMILAR && MPI_SIMILAR < MPI_UNEQUAL);
static_assert(MPI_THREAD_SINGLE < MPI_THREAD_FUNNELED && MPI_THREAD_SERIALIZED < MPI_THREAD_MULTIPLE);
static_assert(MPI_ANY_SOURCE != MPI_PROC_NULL && MPI_UNDEFINED < 0 && MPI_ANY_TAG < 0);
static_assert(MPI_LONG_LONG == MPI_LONG_LONG_INT && MPI_C_COMPLEX == MPI_C_FLOAT_COMPLEX);
static_assert(MPI_MAX_ERROR_STRING >= 64 && MPI_MAX_PROCESSOR_NAME >= 64);
static_assert(MPI_VERSION == 3 && MPI_SUBVERSION == 1);

int main() {
  MPI_Status status{};
  status.MPI_SOURCE = 1;
  status.MPI_TAG = 2;
  status.MPI_ERROR = MPI_SUCCESS;
  int dims[2] = {0, 0};
  int version = 0, subversion = 0;
  MPI_Get_version(&version, &subversion);
  if (MPI_Dims_create(12, 2, dims) != MPI_SUCCESS || dims[0] != 4 || dims[1] != 3 || version != 3) return 1;
  std::printf("C++17 program: dims 4x3, MPI %d.%d\n", version, subversion);
  return status.MPI_TAG == 2 ? 0 : 1;
}
