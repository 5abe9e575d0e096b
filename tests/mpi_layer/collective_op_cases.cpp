#include <algorithm>
#include <cstdint>

#include "apps/mpi/type_constructors.hpp"
#include "tests/mpi_layer/collective_test_support.hpp"
#include "tests/mpi_layer/mpi_test_support.hpp"

namespace gcsim::mpi_layer::testing {
namespace {

template <class T>
T load(const std::byte* p, std::size_t i) {
  T v;
  std::memcpy(&v, p + i * sizeof(T), sizeof(T));
  return v;
}
template <class T>
void store(std::byte* p, std::size_t i, T v) {
  std::memcpy(p + i * sizeof(T), &v, sizeof(T));
}

template <class T, class Value, class Combine>
OpCase elementwise(std::string name, PredefinedOp op, const Datatype& type, MPI_Datatype handle, Value value,
                   Combine combine) {
  OpCase c{std::move(name), reduction_for(Op::predefined(op), type, handle), {}, {}};
  c.data = [value](int rank, std::size_t count) {
    Bytes b(count * sizeof(T));
    for (std::size_t i = 0; i < count; ++i) store<T>(b.data(), i, value(rank, i));
    return b;
  };
  c.reference = [combine](const std::byte* lower, std::byte* higher, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) store<T>(higher, i, combine(load<T>(lower, i), load<T>(higher, i)));
  };
  return c;
}

// A 2x2 matrix of 32-bit integers (wrapping), row-major, packed as four ints.
using Matrix = std::array<std::uint32_t, 4>;
Matrix times(const Matrix& a, const Matrix& b) {
  return {a[0] * b[0] + a[1] * b[2], a[0] * b[1] + a[1] * b[3], a[2] * b[0] + a[3] * b[2], a[2] * b[1] + a[3] * b[3]};
}

// MPI_User_function: inout = in * inout, in being the lower ranks' product.
void matrix_product(void* in, void* inout, int* len, MPI_Datatype*) {
  for (int k = 0; k < *len; ++k) {
    Matrix a, b;
    std::memcpy(a.data(), static_cast<std::byte*>(in) + k * 16, 16);
    std::memcpy(b.data(), static_cast<std::byte*>(inout) + k * 16, 16);
    const Matrix c = times(a, b);
    std::memcpy(static_cast<std::byte*>(inout) + k * 16, c.data(), 16);
  }
}

OpCase matrix_case() {
  static const Datatype matrix_type = type_contiguous(4, int_type);
  OpCase c{"matrix_product/user", reduction_for(Op::user(&matrix_product, false), matrix_type, 0), {}, {}};
  c.data = [](int rank, std::size_t count) {
    Bytes b(count * 16);
    for (std::size_t k = 0; k < count; ++k) {
      const auto r = static_cast<std::uint32_t>(rank), i = static_cast<std::uint32_t>(k);
      const Matrix m{1 + (r + i) % 3, r + 1, i % 2, 1 + r % 2};
      std::memcpy(b.data() + k * 16, m.data(), 16);
    }
    return b;
  };
  c.reference = [](const std::byte* lower, std::byte* higher, std::size_t count) {
    for (std::size_t k = 0; k < count; ++k) {
      Matrix a, b;
      std::memcpy(a.data(), lower + k * 16, 16);
      std::memcpy(b.data(), higher + k * 16, 16);
      const Matrix m = times(a, b);
      std::memcpy(higher + k * 16, m.data(), 16);
    }
  };
  return c;
}

// MAXLOC on MPI_DOUBLE_INT: packed as a double then an int (12 bytes; 16 in memory).
OpCase maxloc_case() {
  static const Datatype pair = pair_type(MPI_DOUBLE_INT);
  OpCase c{"maxloc/double_int", reduction_for(Op::predefined(PredefinedOp::Maxloc), pair, MPI_DOUBLE_INT), {}, {}};
  c.data = [](int rank, std::size_t count) {
    Bytes b(count * 12);
    for (std::size_t i = 0; i < count; ++i) {
      const double value = static_cast<double>((rank * 3 + static_cast<int>(i)) % 5);  // ties on purpose
      std::memcpy(b.data() + i * 12, &value, 8);
      std::memcpy(b.data() + i * 12 + 8, &rank, 4);
    }
    return b;
  };
  c.reference = [](const std::byte* lower, std::byte* higher, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
      double a, b;
      int ia, ib;
      std::memcpy(&a, lower + i * 12, 8), std::memcpy(&ia, lower + i * 12 + 8, 4);
      std::memcpy(&b, higher + i * 12, 8), std::memcpy(&ib, higher + i * 12 + 8, 4);
      const bool lower_wins = a > b || (a == b && ia < ib);
      if (lower_wins) std::memcpy(higher + i * 12, lower + i * 12, 12);
    }
  };
  return c;
}

}  // namespace

std::vector<OpCase> op_cases() {
  std::vector<OpCase> cases;
  cases.push_back(elementwise<int>("sum/int", PredefinedOp::Sum, int_type, MPI_INT,
                                   [](int r, std::size_t i) { return (r * 7 + static_cast<int>(i) * 3) % 23 - 11; },
                                   [](int a, int b) { return a + b; }));
  // Powers of two: every product is exact whatever the order of rounding.
  cases.push_back(elementwise<double>("prod/double", PredefinedOp::Prod, double_type, MPI_DOUBLE,
                                      [](int r, std::size_t i) { return std::array{0.5, 1.0, 2.0}[(r + i) % 3]; },
                                      [](double a, double b) { return a * b; }));
  cases.push_back(elementwise<int>("min/int", PredefinedOp::Min, int_type, MPI_INT,
                                   [](int r, std::size_t i) { return (r * 13 + static_cast<int>(i) * 5) % 17 - 8; },
                                   [](int a, int b) { return std::min(a, b); }));
  cases.push_back(elementwise<double>("max/double", PredefinedOp::Max, double_type, MPI_DOUBLE,
                                      [](int r, std::size_t i) { return ((r * 11 + static_cast<int>(i) * 3) % 19) * 0.25; },
                                      [](double a, double b) { return std::max(a, b); }));
  cases.push_back(maxloc_case());
  cases.push_back(matrix_case());
  return cases;
}

}  // namespace gcsim::mpi_layer::testing
