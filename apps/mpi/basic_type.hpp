#pragma once
// The predefined basic types of C that every type map is made of: their sizes, alignments and the
// classes of the standard's reduction rules (MPI 3.1 section 5.9.2).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "apps/mpi/include/mpi.h"

namespace gcsim::mpi_layer {

enum class Basic : std::uint8_t {
  Char, SignedChar, UnsignedChar, Byte, WChar, Short, UnsignedShort, Int, Unsigned, Long, UnsignedLong,
  LongLong, UnsignedLongLong, Float, Double, LongDouble, Int8, Int16, Int32, Int64, UInt8, UInt16, UInt32,
  UInt64, Bool, FloatComplex, DoubleComplex, LongDoubleComplex, Aint, Offset, Count, Packed,
};
inline constexpr int basic_type_count = static_cast<int>(Basic::Packed) + 1;

// The groups of the standard's table of which op applies to which type.
enum class TypeClass : std::uint8_t { Text, Integer, Floating, Complex, Logical, Byte, Packed };

std::size_t basic_size(Basic b);
std::size_t basic_alignment(Basic b);
TypeClass basic_class(Basic b);
std::string_view basic_name(Basic b);

// The basic type a predefined handle names (MPI_INT -> Int); none for pair types and others.
std::optional<Basic> basic_of_handle(MPI_Datatype handle);
MPI_Datatype handle_of_basic(Basic b);

}  // namespace gcsim::mpi_layer
