// Random nested datatypes against a naive model written straight from the standard's
// definitions: every entry (displacement, basic type) listed one by one, bounds by the formula of
// MPI 3.1 section 4.1.6. The flattened runs, sizes and bounds must agree, and pack must read the
// entries in type-map order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <optional>
#include <random>
#include <vector>

#include "apps/mpi/type_constructors.hpp"
#include "apps/mpi/type_transfer.hpp"
#include "tests/mpi_layer/mpi_test_support.hpp"

namespace gcsim::mpi_layer {
namespace {

struct Entry {
  MPI_Aint displacement;
  Basic basic;
  friend bool operator==(const Entry&, const Entry&) = default;
};

struct Model {
  std::vector<Entry> entries;
  std::optional<MPI_Aint> lb_marker, ub_marker;
  MPI_Aint alignment = 1;

  MPI_Aint lb() const {
    if (lb_marker) return *lb_marker;
    MPI_Aint low = entries.empty() ? 0 : entries[0].displacement;
    for (const Entry& e : entries) low = std::min(low, e.displacement);
    return low;
  }
  MPI_Aint ub() const {
    if (ub_marker) return *ub_marker;
    MPI_Aint high = lb();
    for (const Entry& e : entries) high = std::max(high, e.displacement + static_cast<MPI_Aint>(basic_size(e.basic)));
    const MPI_Aint rest = (high - lb()) % alignment;
    return rest == 0 ? high : high + alignment - rest;
  }
  MPI_Aint extent() const { return ub() - lb(); }
  // Appends old displaced by d: its entries and markers.
  void add(const Model& old, MPI_Aint d) {
    for (const Entry& e : old.entries) entries.push_back({e.displacement + d, e.basic});
    if (old.lb_marker) lb_marker = lb_marker ? std::min(*lb_marker, *old.lb_marker + d) : *old.lb_marker + d;
    if (old.ub_marker) ub_marker = ub_marker ? std::max(*ub_marker, *old.ub_marker + d) : *old.ub_marker + d;
    alignment = std::max(alignment, old.alignment);
  }
};

struct Pair {
  Datatype type;
  Model model;
};

Pair basic_pair(Basic b) {
  Model m;
  m.entries.push_back({0, b});
  m.alignment = static_cast<MPI_Aint>(basic_alignment(b));
  return {Datatype::of_basic(b), m};
}

// One random constructor over old (or two olds for a struct).
Pair random_step(std::mt19937& rng, const Pair& old, const Pair& other) {
  auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  Model m;
  switch (pick(0, 4)) {
    case 0: {
      const int n = pick(0, 3);
      for (int i = 0; i < n; ++i) m.add(old.model, i * old.model.extent());
      return {type_contiguous(n, old.type), m};
    }
    case 1: {
      const int count = pick(0, 3), block = pick(0, 3), stride = pick(-4, 4);
      for (int i = 0; i < count; ++i)
        for (int j = 0; j < block; ++j) m.add(old.model, (i * stride + j) * old.model.extent());
      return {type_vector(count, block, stride, old.type), m};
    }
    case 2: {
      const std::vector<int> lengths{pick(0, 2), pick(0, 2)};
      const std::vector<MPI_Aint> displacements{pick(-40, 40), pick(-40, 40)};
      for (std::size_t i = 0; i < 2; ++i)
        for (int j = 0; j < lengths[i]; ++j) m.add(old.model, displacements[i] + j * old.model.extent());
      return {type_hindexed(lengths, displacements, old.type), m};
    }
    case 3: {
      const std::vector<int> lengths{pick(0, 2), pick(1, 2)};
      const std::vector<MPI_Aint> displacements{pick(-40, 40), pick(-40, 40)};
      const Pair* parts[] = {&old, &other};
      for (std::size_t i = 0; i < 2; ++i)
        for (int j = 0; j < lengths[i]; ++j) m.add(parts[i]->model, displacements[i] + j * parts[i]->model.extent());
      const Datatype* types[] = {&old.type, &other.type};
      return {type_struct(lengths, displacements, types), m};
    }
    default: {
      const MPI_Aint lb = pick(-16, 16), extent = pick(0, 48);
      m.add(old.model, 0);
      m.lb_marker = lb;
      m.ub_marker = lb + extent;
      return {type_resized(old.type, lb, extent), m};
    }
  }
}

std::vector<Entry> expanded(const Datatype& t) {
  std::vector<Entry> out;
  for (const mpi_layer::Run& r : t.runs())
    for (MPI_Count i = 0; i < r.count; ++i)
      out.push_back({r.offset + static_cast<MPI_Aint>(basic_size(r.basic)) * i, r.basic});
  return out;
}

TEST(MpiTypeModel, RandomNestedTypesAgreeWithTheStandardsDefinition) {
  std::mt19937 rng(20261201);
  const Basic basics[] = {Basic::Char, Basic::Short, Basic::Int, Basic::Double, Basic::LongDouble};
  int nested = 0, with_markers = 0;
  for (int trial = 0; trial < 400; ++trial) {
    Pair t = basic_pair(basics[trial % 5]);
    const Pair other = basic_pair(basics[(trial / 5) % 5]);
    const int depth = 1 + trial % 4;
    for (int d = 0; d < depth; ++d) t = random_step(rng, t, other);
    SCOPED_TRACE("trial " + std::to_string(trial));
    ASSERT_EQ(expanded(t.type), t.model.entries);
    EXPECT_EQ(t.type.lb(), t.model.lb());
    EXPECT_EQ(t.type.ub(), t.model.ub());
    MPI_Count size = 0;
    for (const Entry& e : t.model.entries) size += static_cast<MPI_Count>(basic_size(e.basic));
    EXPECT_EQ(t.type.size(), size);
    EXPECT_EQ(t.type.elements(), static_cast<MPI_Count>(t.model.entries.size()));

    // Pack 2 elements from a buffer of distinct bytes: entry by entry, in type-map order.
    const MPI_Count count = 2;
    ASSERT_GE(t.type.extent(), 0);  // no constructor here makes a negative extent
    const MPI_Aint low = std::min<MPI_Aint>(0, t.type.true_lb());
    const MPI_Aint high = (count - 1) * t.type.extent() + t.type.true_lb() + t.type.true_extent();
    std::vector<std::byte> buffer(static_cast<std::size_t>(std::max<MPI_Aint>(high, 0) - low + 16));
    for (std::size_t i = 0; i < buffer.size(); ++i) buffer[i] = static_cast<std::byte>(i * 13 + 5);
    const std::byte* origin = buffer.data() - low + 8;
    std::vector<std::byte> packed(static_cast<std::size_t>(pack_size(count, t.type))), expected;
    MPI_Count position = 0;
    pack(origin, count, t.type, packed, position);
    for (MPI_Count k = 0; k < count; ++k)
      for (const Entry& e : t.model.entries) {
        const std::byte* at = origin + k * t.model.extent() + e.displacement;
        expected.insert(expected.end(), at, at + basic_size(e.basic));
      }
    EXPECT_EQ(packed, expected);
    nested += t.model.entries.size() > 3;
    with_markers += t.model.ub_marker.has_value();
  }
  EXPECT_GT(nested, 100);  // the random types are not mostly trivial
  EXPECT_GT(with_markers, 50);
}

}  // namespace
}  // namespace gcsim::mpi_layer
