#include "apps/mpi/type_constructors.hpp"

#include <cstddef>

#include "apps/mpi/error.hpp"

namespace gcsim::mpi_layer {
namespace {

void check_count(MPI_Count count) {
  if (count < 0) fail(MPI_ERR_COUNT, "negative count");
}

void check_blocklength(MPI_Count blocklength) {
  if (blocklength < 0) fail(MPI_ERR_ARG, "negative block length");
}

template <class Displacement>
void check_lengths(std::size_t blocks, std::span<const Displacement> displacements) {
  if (displacements.size() != blocks) fail(MPI_ERR_ARG, "block lengths and displacements differ in number");
}

Datatype pair_layout(Basic value, Basic index, MPI_Aint index_offset) {
  TypeBuilder b;
  b.add(Datatype::of_basic(value), 0);
  b.add(Datatype::of_basic(index), index_offset);
  Datatype t = b.finish();
  t.commit();
  return t;
}

}  // namespace

Datatype type_contiguous(MPI_Count count, const Datatype& old) {
  check_count(count);
  TypeBuilder b;
  b.add_copies(old, 0, count);
  return b.finish();
}

Datatype type_hvector(MPI_Count count, MPI_Count blocklength, MPI_Aint stride_bytes, const Datatype& old) {
  check_count(count);
  check_blocklength(blocklength);
  TypeBuilder b;
  for (MPI_Count i = 0; i < count; ++i) b.add_copies(old, checked_multiply(stride_bytes, i), blocklength);
  return b.finish();
}

Datatype type_vector(MPI_Count count, MPI_Count blocklength, MPI_Aint stride_elements, const Datatype& old) {
  return type_hvector(count, blocklength, checked_multiply(stride_elements, old.extent()), old);
}

Datatype type_hindexed(std::span<const int> blocklengths, std::span<const MPI_Aint> displacements_bytes,
                       const Datatype& old) {
  check_lengths(blocklengths.size(), displacements_bytes);
  TypeBuilder b;
  for (std::size_t i = 0; i < blocklengths.size(); ++i) {
    check_blocklength(blocklengths[i]);
    b.add_copies(old, displacements_bytes[i], blocklengths[i]);
  }
  return b.finish();
}

Datatype type_indexed(std::span<const int> blocklengths, std::span<const int> displacements_elements,
                      const Datatype& old) {
  check_lengths(blocklengths.size(), displacements_elements);
  std::vector<MPI_Aint> bytes;
  bytes.reserve(displacements_elements.size());
  for (int d : displacements_elements) bytes.push_back(checked_multiply(d, old.extent()));
  return type_hindexed(blocklengths, bytes, old);
}

Datatype type_hindexed_block(MPI_Count blocklength, std::span<const MPI_Aint> displacements_bytes,
                             const Datatype& old) {
  check_blocklength(blocklength);
  TypeBuilder b;
  for (MPI_Aint d : displacements_bytes) b.add_copies(old, d, blocklength);
  return b.finish();
}

Datatype type_indexed_block(MPI_Count blocklength, std::span<const int> displacements_elements, const Datatype& old) {
  std::vector<MPI_Aint> bytes;
  bytes.reserve(displacements_elements.size());
  for (int d : displacements_elements) bytes.push_back(checked_multiply(d, old.extent()));
  return type_hindexed_block(blocklength, bytes, old);
}

Datatype type_struct(std::span<const int> blocklengths, std::span<const MPI_Aint> displacements_bytes,
                     std::span<const Datatype* const> types) {
  check_lengths(blocklengths.size(), displacements_bytes);
  if (types.size() != blocklengths.size()) fail(MPI_ERR_ARG, "block lengths and types differ in number");
  TypeBuilder b;
  for (std::size_t i = 0; i < blocklengths.size(); ++i) {
    check_blocklength(blocklengths[i]);
    b.add_copies(*types[i], displacements_bytes[i], blocklengths[i]);
  }
  return b.finish();
}

Datatype type_resized(const Datatype& old, MPI_Aint lb, MPI_Aint extent) {
  TypeBuilder b;
  b.add(old, 0);
  b.set_bounds(lb, checked_add(lb, extent));
  return b.finish();
}

Datatype type_dup(const Datatype& old) { return old; }

Datatype type_subarray(std::span<const int> sizes, std::span<const int> subsizes, std::span<const int> starts,
                       int order, const Datatype& old) {
  const std::size_t n = sizes.size();
  if (n == 0 || subsizes.size() != n || starts.size() != n) fail(MPI_ERR_ARG, "subarray needs ndims > 0 entries of each");
  if (order != MPI_ORDER_C && order != MPI_ORDER_FORTRAN) fail(MPI_ERR_ARG, "invalid array order");
  for (std::size_t d = 0; d < n; ++d)
    if (sizes[d] <= 0 || subsizes[d] <= 0 || subsizes[d] > sizes[d] || starts[d] < 0 || starts[d] > sizes[d] - subsizes[d])
      fail(MPI_ERR_ARG, "the subarray does not lie inside the array");
  // Dimension k from the fastest-varying one outwards.
  const auto dim = [&](std::size_t k) { return order == MPI_ORDER_C ? n - 1 - k : k; };
  Datatype block = type_contiguous(subsizes[dim(0)], old);
  MPI_Aint stride = old.extent();  // bytes between neighbours in dimension dim(k)
  MPI_Aint offset = checked_multiply(starts[dim(0)], stride);
  for (std::size_t k = 1; k < n; ++k) {
    stride = checked_multiply(stride, sizes[dim(k - 1)]);
    block = type_hvector(subsizes[dim(k)], 1, stride, block);
    offset = checked_add(offset, checked_multiply(starts[dim(k)], stride));
  }
  const MPI_Aint whole = checked_multiply(stride, sizes[dim(n - 1)]);
  TypeBuilder b;
  b.add(block, offset);
  b.set_bounds(0, whole);  // the standard puts the bounds at 0 and the whole array
  return b.finish();
}

Datatype pair_type(MPI_Datatype handle) {
  switch (handle) {
    case MPI_FLOAT_INT: {
      struct P { float v; int i; };
      return pair_layout(Basic::Float, Basic::Int, offsetof(P, i));
    }
    case MPI_DOUBLE_INT: {
      struct P { double v; int i; };
      return pair_layout(Basic::Double, Basic::Int, offsetof(P, i));
    }
    case MPI_LONG_INT: {
      struct P { long v; int i; };
      return pair_layout(Basic::Long, Basic::Int, offsetof(P, i));
    }
    case MPI_2INT: {
      struct P { int v; int i; };
      return pair_layout(Basic::Int, Basic::Int, offsetof(P, i));
    }
    case MPI_SHORT_INT: {
      struct P { short v; int i; };
      return pair_layout(Basic::Short, Basic::Int, offsetof(P, i));
    }
    case MPI_LONG_DOUBLE_INT: {
      struct P { long double v; int i; };
      return pair_layout(Basic::LongDouble, Basic::Int, offsetof(P, i));
    }
    default: fail(MPI_ERR_TYPE, "not a pair type");
  }
}

}  // namespace gcsim::mpi_layer
