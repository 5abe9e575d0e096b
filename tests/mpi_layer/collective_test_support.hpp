#pragma once
// What the collective tests share: running one collective on n in-memory ranks, test data, and
// the reduction cases with their direct sequential references (written here on plain C++ types,
// independent of the layer's reduction code).
#include <gtest/gtest.h>

#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "apps/mpi/collective_algorithms.hpp"
#include "tests/mpi_layer/in_memory_channel.hpp"

namespace gcsim::mpi_layer::testing {

using Bytes = std::vector<std::byte>;

inline constexpr int rank_counts[] = {1, 2, 3, 4, 5, 7, 8, 16};

// Runs body(call, rank) on n ranks; returns every rank's output. Sends are synchronous unless
// asked otherwise, the stricter runtime. Fails the test if a message was left unreceived.
template <class Body>
std::vector<Bytes> outputs_of(int n, Body body, ScheduleStats* stats = nullptr, SendMode mode = SendMode::Synchronous) {
  constexpr std::uint32_t sequence = 5;
  std::vector<Bytes> out(static_cast<std::size_t>(n));
  InMemoryNetwork network(n, mode);
  const ScheduleStats s = network.run([&](CollectiveChannel& channel) {
    out[static_cast<std::size_t>(channel.rank())] = body(CollectiveCall{channel, sequence}, channel.rank());
  });
  EXPECT_EQ(s.left_unreceived, 0u);
  if (stats != nullptr) *stats = s;
  return out;
}

// Distinct bytes for each rank, position and salt.
inline Bytes pattern(int rank, std::size_t bytes, int salt = 0) {
  Bytes b(bytes);
  for (std::size_t i = 0; i < bytes; ++i) b[i] = static_cast<std::byte>((rank * 31 + static_cast<int>(i) * 7 + salt * 13 + 1) & 0xFF);
  return b;
}

inline Bytes concat(const std::vector<Bytes>& parts) {
  Bytes out;
  for (const Bytes& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

// A reduction with its test data and its reference: reference(lower, higher, count) sets higher =
// lower op higher element by element.
struct OpCase {
  std::string name;
  Reduction reduction;
  std::function<Bytes(int rank, std::size_t count)> data;
  std::function<void(const std::byte* lower, std::byte* higher, std::size_t count)> reference;
};

// sum/int, prod/double, min/int, max/double, maxloc/double_int (a type with a gap: packed through
// its layout) and the product of 2x2 integer matrices, a non-commutative user op.
std::vector<OpCase> op_cases();

// The reference reduction of ranks [first, last)'s inputs, in rank order.
inline Bytes reference_fold(const OpCase& op, const std::vector<Bytes>& inputs, int first, int last, std::size_t count) {
  Bytes acc = inputs[static_cast<std::size_t>(first)];
  for (int r = first + 1; r < last; ++r) {
    Bytes next = inputs[static_cast<std::size_t>(r)];
    op.reference(acc.data(), next.data(), count);
    acc.swap(next);
  }
  return acc;
}

inline std::vector<Bytes> inputs_of(const OpCase& op, int n, std::size_t count) {
  std::vector<Bytes> in;
  for (int r = 0; r < n; ++r) in.push_back(op.data(r, count));
  return in;
}

// Auto and every named algorithm of c.
inline std::vector<Algorithm> every_algorithm(Collective c) {
  std::vector<Algorithm> all{Algorithm::Auto};
  for (Algorithm a : algorithms_of(c)) all.push_back(a);
  return all;
}

inline std::string describe(Algorithm a, int n, std::size_t size) {
  return std::string(algorithm_name(a)) + " on " + std::to_string(n) + " ranks, size " + std::to_string(size);
}

}  // namespace gcsim::mpi_layer::testing
