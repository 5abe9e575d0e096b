#pragma once
// Element-wise kernels of the predefined ops. Elements may sit at any address inside a derived
// type, so every load and store goes through memcpy. Integer SUM and PROD are computed in the
// unsigned counterpart: they wrap as two's complement, never overflow a signed type.
#include <complex>
#include <cstring>
#include <type_traits>

#include "apps/mpi/reduction.hpp"

namespace gcsim::mpi_layer {

template <class T>
T load_element(const std::byte* p) {
  T v;
  std::memcpy(&v, p, sizeof(T));
  return v;
}

template <class T>
void store_element(std::byte* p, T v) {
  std::memcpy(p, &v, sizeof(T));
}

template <class T>
inline constexpr bool is_complex_v = false;
template <class T>
inline constexpr bool is_complex_v<std::complex<T>> = true;

template <class T>
T wrapping_add(T a, T b) {
  using U = std::make_unsigned_t<T>;
  using Wide = decltype(U{} + 0u);  // unsigned, at least unsigned int: no promotion to int
  return static_cast<T>(static_cast<U>(static_cast<Wide>(static_cast<U>(a)) + static_cast<Wide>(static_cast<U>(b))));
}

template <class T>
T wrapping_multiply(T a, T b) {
  using U = std::make_unsigned_t<T>;
  using Wide = decltype(U{} + 0u);
  return static_cast<T>(static_cast<U>(static_cast<Wide>(static_cast<U>(a)) * static_cast<Wide>(static_cast<U>(b))));
}

// a op b, a from in, b from inout.
template <class T>
T combine_values(PredefinedOp op, T a, T b) {
  if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
    switch (op) {
      case PredefinedOp::Max: return a > b ? a : b;
      case PredefinedOp::Min: return a < b ? a : b;
      case PredefinedOp::Sum: return wrapping_add(a, b);
      case PredefinedOp::Prod: return wrapping_multiply(a, b);
      case PredefinedOp::Land: return static_cast<T>(a != 0 && b != 0);
      case PredefinedOp::Lor: return static_cast<T>(a != 0 || b != 0);
      case PredefinedOp::Lxor: return static_cast<T>((a != 0) != (b != 0));
      case PredefinedOp::Band: return static_cast<T>(a & b);
      case PredefinedOp::Bor: return static_cast<T>(a | b);
      case PredefinedOp::Bxor: return static_cast<T>(a ^ b);
      default: return b;
    }
  } else if constexpr (std::is_same_v<T, bool>) {
    switch (op) {
      case PredefinedOp::Land: return a && b;
      case PredefinedOp::Lor: return a || b;
      case PredefinedOp::Lxor: return a != b;
      default: return b;
    }
  } else if constexpr (std::is_floating_point_v<T>) {
    switch (op) {
      case PredefinedOp::Max: return a > b ? a : b;
      case PredefinedOp::Min: return a < b ? a : b;
      case PredefinedOp::Sum: return a + b;
      case PredefinedOp::Prod: return a * b;
      default: return b;
    }
  } else if constexpr (is_complex_v<T>) {
    if (op == PredefinedOp::Sum) return a + b;
    if (op == PredefinedOp::Prod) return a * b;
    return b;
  } else {
    return b;
  }
}

// n consecutive elements: inout[i] = in[i] op inout[i].
template <class T>
void combine_run(PredefinedOp op, const std::byte* in, std::byte* inout, MPI_Count n) {
  if (op == PredefinedOp::Replace) {
    std::memmove(inout, in, static_cast<std::size_t>(n) * sizeof(T));
    return;
  }
  for (MPI_Count i = 0; i < n; ++i) {
    const auto at = static_cast<std::size_t>(i) * sizeof(T);
    store_element<T>(inout + at, combine_values<T>(op, load_element<T>(in + at), load_element<T>(inout + at)));
  }
}

// MINLOC/MAXLOC on one (value, index) pair; equal values keep the lower index.
template <class T>
void combine_loc(bool minimum, const std::byte* in_value, const std::byte* in_index, std::byte* inout_value,
                 std::byte* inout_index) {
  const T u = load_element<T>(in_value), v = load_element<T>(inout_value);
  const int i = load_element<int>(in_index), j = load_element<int>(inout_index);
  const bool in_wins = minimum ? u < v : u > v;
  if (in_wins) {
    store_element<T>(inout_value, u);
    store_element<int>(inout_index, i);
  } else if (u == v) {
    store_element<int>(inout_index, i < j ? i : j);
  }
}

}  // namespace gcsim::mpi_layer
