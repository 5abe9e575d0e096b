// The C entry points of derived datatypes (MPI 3.1 section 4.1), MPI-1's removed names included.
#include <span>
#include <vector>

#include "apps/mpi/c_call.hpp"
#include "apps/mpi/type_constructors.hpp"

using namespace gcsim::mpi_layer;

namespace {

template <class T>
std::span<const T> array_arg(const T* p, int count) {
  check_count_arg(count);
  if (count > 0 && !p) fail(MPI_ERR_ARG, "null array argument");
  return {p, static_cast<std::size_t>(count)};
}

// Runs a constructor on the resolved old type and registers the result.
template <class Make>
int construct(MPI_Datatype oldtype, MPI_Datatype* newtype, Make make, std::source_location where = std::source_location::current()) {
  return c_call([&](Registry& r) {
    MPI_Datatype& out = out_arg(newtype);
    out = r.datatypes.insert(make(datatype_arg(r, oldtype, false)));
  }, where);
}

}  // namespace

extern "C" {

int MPI_Type_contiguous(int count, MPI_Datatype oldtype, MPI_Datatype* newtype) {
  return construct(oldtype, newtype, [&](const Datatype& old) { return type_contiguous(count, old); });
}

int MPI_Type_vector(int count, int blocklength, int stride, MPI_Datatype oldtype, MPI_Datatype* newtype) {
  return construct(oldtype, newtype, [&](const Datatype& old) { return type_vector(count, blocklength, stride, old); });
}

int MPI_Type_create_hvector(int count, int blocklength, MPI_Aint stride, MPI_Datatype oldtype, MPI_Datatype* newtype) {
  return construct(oldtype, newtype, [&](const Datatype& old) { return type_hvector(count, blocklength, stride, old); });
}

int MPI_Type_indexed(int count, const int array_of_blocklengths[], const int array_of_displacements[],
                     MPI_Datatype oldtype, MPI_Datatype* newtype) {
  return construct(oldtype, newtype, [&](const Datatype& old) {
    return type_indexed(array_arg(array_of_blocklengths, count), array_arg(array_of_displacements, count), old);
  });
}

int MPI_Type_create_hindexed(int count, const int array_of_blocklengths[], const MPI_Aint array_of_displacements[],
                             MPI_Datatype oldtype, MPI_Datatype* newtype) {
  return construct(oldtype, newtype, [&](const Datatype& old) {
    return type_hindexed(array_arg(array_of_blocklengths, count), array_arg(array_of_displacements, count), old);
  });
}

int MPI_Type_create_indexed_block(int count, int blocklength, const int array_of_displacements[],
                                  MPI_Datatype oldtype, MPI_Datatype* newtype) {
  return construct(oldtype, newtype, [&](const Datatype& old) {
    return type_indexed_block(blocklength, array_arg(array_of_displacements, count), old);
  });
}

int MPI_Type_create_hindexed_block(int count, int blocklength, const MPI_Aint array_of_displacements[],
                                   MPI_Datatype oldtype, MPI_Datatype* newtype) {
  return construct(oldtype, newtype, [&](const Datatype& old) {
    return type_hindexed_block(blocklength, array_arg(array_of_displacements, count), old);
  });
}

int MPI_Type_create_struct(int count, const int array_of_blocklengths[], const MPI_Aint array_of_displacements[],
                           const MPI_Datatype array_of_types[], MPI_Datatype* newtype) {
  return c_call([&](Registry& r) {
    MPI_Datatype& out = out_arg(newtype);
    std::vector<const Datatype*> types;
    for (MPI_Datatype t : array_arg(array_of_types, count)) types.push_back(&datatype_arg(r, t, false));
    out = r.datatypes.insert(
        type_struct(array_arg(array_of_blocklengths, count), array_arg(array_of_displacements, count), types));
  });
}

int MPI_Type_create_subarray(int ndims, const int array_of_sizes[], const int array_of_subsizes[],
                             const int array_of_starts[], int order, MPI_Datatype oldtype, MPI_Datatype* newtype) {
  return construct(oldtype, newtype, [&](const Datatype& old) {
    return type_subarray(array_arg(array_of_sizes, ndims), array_arg(array_of_subsizes, ndims),
                         array_arg(array_of_starts, ndims), order, old);
  });
}

int MPI_Type_create_resized(MPI_Datatype oldtype, MPI_Aint lb, MPI_Aint extent, MPI_Datatype* newtype) {
  return construct(oldtype, newtype, [&](const Datatype& old) { return type_resized(old, lb, extent); });
}

int MPI_Type_dup(MPI_Datatype oldtype, MPI_Datatype* newtype) {
  return construct(oldtype, newtype, [&](const Datatype& old) { return type_dup(old); });
}

int MPI_Type_commit(MPI_Datatype* datatype) {
  return c_call([&](Registry& r) {
    const MPI_Datatype handle = out_arg(datatype);
    if (is_predefined_datatype(handle)) return;
    Datatype* t = find_user_datatype(r, handle);
    if (!t) fail(MPI_ERR_TYPE, "invalid datatype");
    t->commit();
  });
}

int MPI_Type_free(MPI_Datatype* datatype) {
  return c_call([&](Registry& r) {
    MPI_Datatype& handle = out_arg(datatype);
    if (is_predefined_datatype(handle)) fail(MPI_ERR_TYPE, "a predefined datatype cannot be freed");
    if (!r.datatypes.erase(handle)) fail(MPI_ERR_TYPE, "invalid datatype");
    handle = MPI_DATATYPE_NULL;
  });
}

int MPI_Type_size_x(MPI_Datatype datatype, MPI_Count* size) {
  return c_call([&](Registry& r) { out_arg(size) = datatype_arg(r, datatype, false).size(); });
}

int MPI_Type_size(MPI_Datatype datatype, int* size) {
  return c_call([&](Registry& r) { out_arg(size) = int_or_undefined(datatype_arg(r, datatype, false).size()); });
}

int MPI_Type_get_extent(MPI_Datatype datatype, MPI_Aint* lb, MPI_Aint* extent) {
  return c_call([&](Registry& r) {
    const Datatype& t = datatype_arg(r, datatype, false);
    out_arg(lb) = t.lb();
    out_arg(extent) = t.extent();
  });
}

int MPI_Type_get_true_extent(MPI_Datatype datatype, MPI_Aint* true_lb, MPI_Aint* true_extent) {
  return c_call([&](Registry& r) {
    const Datatype& t = datatype_arg(r, datatype, false);
    out_arg(true_lb) = t.true_lb();
    out_arg(true_extent) = t.true_extent();
  });
}

int MPI_Get_address(const void* location, MPI_Aint* address) {
  return c_call([&](Registry&) { out_arg(address) = reinterpret_cast<MPI_Aint>(location); });
}

int MPI_Type_hvector(int count, int blocklength, MPI_Aint stride, MPI_Datatype oldtype, MPI_Datatype* newtype) {
  return MPI_Type_create_hvector(count, blocklength, stride, oldtype, newtype);
}

int MPI_Type_hindexed(int count, int array_of_blocklengths[], MPI_Aint array_of_displacements[], MPI_Datatype oldtype,
                      MPI_Datatype* newtype) {
  return MPI_Type_create_hindexed(count, array_of_blocklengths, array_of_displacements, oldtype, newtype);
}

int MPI_Type_struct(int count, int array_of_blocklengths[], MPI_Aint array_of_displacements[],
                    MPI_Datatype array_of_types[], MPI_Datatype* newtype) {
  return MPI_Type_create_struct(count, array_of_blocklengths, array_of_displacements, array_of_types, newtype);
}

int MPI_Address(void* location, MPI_Aint* address) { return MPI_Get_address(location, address); }

int MPI_Type_extent(MPI_Datatype datatype, MPI_Aint* extent) {
  MPI_Aint lb = 0;
  return MPI_Type_get_extent(datatype, &lb, extent);
}

int MPI_Type_lb(MPI_Datatype datatype, MPI_Aint* displacement) {
  MPI_Aint extent = 0;
  return MPI_Type_get_extent(datatype, displacement, &extent);
}

int MPI_Type_ub(MPI_Datatype datatype, MPI_Aint* displacement) {
  return c_call([&](Registry& r) { out_arg(displacement) = datatype_arg(r, datatype, false).ub(); });
}

}  // extern "C"
