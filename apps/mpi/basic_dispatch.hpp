#pragma once
// Calls a generic function with the C++ type of a basic type: visit_basic(Basic::Int, f) calls
// f(BasicTag<int>{}).
#include <complex>
#include <cstdint>

#include "apps/mpi/basic_type.hpp"

namespace gcsim::mpi_layer {

template <class T>
struct BasicTag {
  using type = T;
};

template <class F>
void visit_basic(Basic b, F&& f) {
  switch (b) {
    case Basic::Char: return f(BasicTag<char>{});
    case Basic::SignedChar: return f(BasicTag<signed char>{});
    case Basic::UnsignedChar: return f(BasicTag<unsigned char>{});
    case Basic::Byte: return f(BasicTag<unsigned char>{});
    case Basic::WChar: return f(BasicTag<wchar_t>{});
    case Basic::Short: return f(BasicTag<short>{});
    case Basic::UnsignedShort: return f(BasicTag<unsigned short>{});
    case Basic::Int: return f(BasicTag<int>{});
    case Basic::Unsigned: return f(BasicTag<unsigned>{});
    case Basic::Long: return f(BasicTag<long>{});
    case Basic::UnsignedLong: return f(BasicTag<unsigned long>{});
    case Basic::LongLong: return f(BasicTag<long long>{});
    case Basic::UnsignedLongLong: return f(BasicTag<unsigned long long>{});
    case Basic::Float: return f(BasicTag<float>{});
    case Basic::Double: return f(BasicTag<double>{});
    case Basic::LongDouble: return f(BasicTag<long double>{});
    case Basic::Int8: return f(BasicTag<std::int8_t>{});
    case Basic::Int16: return f(BasicTag<std::int16_t>{});
    case Basic::Int32: return f(BasicTag<std::int32_t>{});
    case Basic::Int64: return f(BasicTag<std::int64_t>{});
    case Basic::UInt8: return f(BasicTag<std::uint8_t>{});
    case Basic::UInt16: return f(BasicTag<std::uint16_t>{});
    case Basic::UInt32: return f(BasicTag<std::uint32_t>{});
    case Basic::UInt64: return f(BasicTag<std::uint64_t>{});
    case Basic::Bool: return f(BasicTag<bool>{});
    case Basic::FloatComplex: return f(BasicTag<std::complex<float>>{});
    case Basic::DoubleComplex: return f(BasicTag<std::complex<double>>{});
    case Basic::LongDoubleComplex: return f(BasicTag<std::complex<long double>>{});
    case Basic::Aint: return f(BasicTag<MPI_Aint>{});
    case Basic::Offset: return f(BasicTag<MPI_Offset>{});
    case Basic::Count: return f(BasicTag<MPI_Count>{});
    case Basic::Packed: return f(BasicTag<unsigned char>{});
  }
}

}  // namespace gcsim::mpi_layer
