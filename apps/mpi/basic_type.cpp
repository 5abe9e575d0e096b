#include "apps/mpi/basic_type.hpp"

#include <complex>
#include <cstdint>

namespace gcsim::mpi_layer {
namespace {

struct BasicInfo {
  std::size_t size;
  std::size_t alignment;
  TypeClass type_class;
  std::string_view name;
};

template <class T>
constexpr BasicInfo info_of(TypeClass c, std::string_view name) {
  return {sizeof(T), alignof(T), c, name};
}

// In the order of enum Basic, which is also the order of the handles MPI_CHAR..MPI_PACKED.
constexpr BasicInfo basic_table[basic_type_count] = {
    info_of<char>(TypeClass::Text, "MPI_CHAR"),
    info_of<signed char>(TypeClass::Integer, "MPI_SIGNED_CHAR"),
    info_of<unsigned char>(TypeClass::Integer, "MPI_UNSIGNED_CHAR"),
    info_of<unsigned char>(TypeClass::Byte, "MPI_BYTE"),
    info_of<wchar_t>(TypeClass::Text, "MPI_WCHAR"),
    info_of<short>(TypeClass::Integer, "MPI_SHORT"),
    info_of<unsigned short>(TypeClass::Integer, "MPI_UNSIGNED_SHORT"),
    info_of<int>(TypeClass::Integer, "MPI_INT"),
    info_of<unsigned>(TypeClass::Integer, "MPI_UNSIGNED"),
    info_of<long>(TypeClass::Integer, "MPI_LONG"),
    info_of<unsigned long>(TypeClass::Integer, "MPI_UNSIGNED_LONG"),
    info_of<long long>(TypeClass::Integer, "MPI_LONG_LONG_INT"),
    info_of<unsigned long long>(TypeClass::Integer, "MPI_UNSIGNED_LONG_LONG"),
    info_of<float>(TypeClass::Floating, "MPI_FLOAT"),
    info_of<double>(TypeClass::Floating, "MPI_DOUBLE"),
    info_of<long double>(TypeClass::Floating, "MPI_LONG_DOUBLE"),
    info_of<std::int8_t>(TypeClass::Integer, "MPI_INT8_T"),
    info_of<std::int16_t>(TypeClass::Integer, "MPI_INT16_T"),
    info_of<std::int32_t>(TypeClass::Integer, "MPI_INT32_T"),
    info_of<std::int64_t>(TypeClass::Integer, "MPI_INT64_T"),
    info_of<std::uint8_t>(TypeClass::Integer, "MPI_UINT8_T"),
    info_of<std::uint16_t>(TypeClass::Integer, "MPI_UINT16_T"),
    info_of<std::uint32_t>(TypeClass::Integer, "MPI_UINT32_T"),
    info_of<std::uint64_t>(TypeClass::Integer, "MPI_UINT64_T"),
    info_of<bool>(TypeClass::Logical, "MPI_C_BOOL"),
    info_of<std::complex<float>>(TypeClass::Complex, "MPI_C_FLOAT_COMPLEX"),
    info_of<std::complex<double>>(TypeClass::Complex, "MPI_C_DOUBLE_COMPLEX"),
    info_of<std::complex<long double>>(TypeClass::Complex, "MPI_C_LONG_DOUBLE_COMPLEX"),
    info_of<MPI_Aint>(TypeClass::Integer, "MPI_AINT"),
    info_of<MPI_Offset>(TypeClass::Integer, "MPI_OFFSET"),
    info_of<MPI_Count>(TypeClass::Integer, "MPI_COUNT"),
    info_of<unsigned char>(TypeClass::Packed, "MPI_PACKED"),
};

const BasicInfo& info(Basic b) { return basic_table[static_cast<int>(b)]; }

}  // namespace

std::size_t basic_size(Basic b) { return info(b).size; }
std::size_t basic_alignment(Basic b) { return info(b).alignment; }
TypeClass basic_class(Basic b) { return info(b).type_class; }
std::string_view basic_name(Basic b) { return info(b).name; }

std::optional<Basic> basic_of_handle(MPI_Datatype handle) {
  if (handle < MPI_CHAR || handle > MPI_PACKED) return std::nullopt;
  return static_cast<Basic>(handle - MPI_CHAR);
}

MPI_Datatype handle_of_basic(Basic b) { return MPI_CHAR + static_cast<int>(b); }

}  // namespace gcsim::mpi_layer
