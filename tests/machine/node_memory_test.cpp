// A node's memory (machine/node_memory.hpp): declared by kind, refused past the node's memory
// under enforce, granted and remembered as a peak under warn; releases never make memory.
#include "machine/node_memory.hpp"

#include <gtest/gtest.h>

namespace gcsim::machine {
namespace {

TEST(NodeMemory, EnforceRefusesWhatWouldExceedTheNodeAndChangesNothing) {
  NodeMemory m(32 << 20, MemoryLimit::enforce);
  EXPECT_TRUE(m.use(20 << 20, "scene"));
  EXPECT_TRUE(m.use(12 << 20, "hemicube"));  // exactly full is allowed
  EXPECT_FALSE(m.use(1, "message"));
  EXPECT_EQ(m.used(), 32 << 20);
  EXPECT_TRUE(m.use(-(12 << 20), "hemicube"));
  EXPECT_TRUE(m.use(1, "message"));
  EXPECT_EQ(m.peak(), 32 << 20);
}

TEST(NodeMemory, WarnGrantsAndKeepsThePeak) {
  NodeMemory m(32 << 20, MemoryLimit::warn);
  EXPECT_TRUE(m.use(100 << 20, "broadcast data"));
  EXPECT_TRUE(m.over());
  EXPECT_TRUE(m.use(-(100 << 20), "broadcast data"));
  EXPECT_FALSE(m.over());
  EXPECT_EQ(m.used(), 0);
  EXPECT_EQ(m.peak(), 100 << 20);
}

TEST(NodeMemory, AReleaseNeverTakesAKindBelowZero) {
  NodeMemory m(1000, MemoryLimit::enforce);
  ASSERT_TRUE(m.use(600, "scene"));
  ASSERT_TRUE(m.use(300, "image"));
  EXPECT_TRUE(m.use(-500, "image"));  // more than it holds: only its 300 come back
  EXPECT_EQ(m.used(), 600);
  EXPECT_FALSE(m.use(401, "image"));
}

// add and release, the runtime's per-message forms (which use(+bytes) and use(-bytes) call), on
// their own: refused past the node under enforce, a peak, and no kind below zero (the final sums).
TEST(NodeMemory, AddAndReleaseKeepTheSumsOfUse) {
  NodeMemory a(100, MemoryLimit::enforce), b(100, MemoryLimit::enforce);
  const NodeMemory::Kind ka = a.kind("messages"), kb = b.kind("messages");
  for (const std::int64_t bytes : {40, 50, 20, -30, 60, -70, -80, 10}) {
    const bool granted = bytes > 0 ? a.add(bytes, ka) : (a.release(-bytes, ka), true);
    EXPECT_EQ(granted, b.use(bytes, kb)) << bytes;
    EXPECT_EQ(a.used(), b.used()) << bytes;
    EXPECT_EQ(a.peak(), b.peak()) << bytes;
    EXPECT_EQ(a.breakdown(), b.breakdown()) << bytes;
  }
  EXPECT_EQ(a.used(), 10);
  EXPECT_EQ(a.peak(), 90);
}

// add_within, the runtime's in-line form: what add grants within the node's memory, under either
// limit; past it nothing changes (the caller then adds, refused or warned).
TEST(NodeMemory, AddWithinGrantsWhatFitsAndLeavesAnOverrunToTheCaller) {
  for (const MemoryLimit limit : {MemoryLimit::enforce, MemoryLimit::warn}) {
    NodeMemory a(100, limit), b(100, limit);
    const NodeMemory::Kind ka = a.kind("messages"), kb = b.kind("messages");
    for (const std::int64_t bytes : {40, 60, 1, 30}) {  // 60 fills the node exactly; 1 would overrun
      const bool fits = b.used() + bytes <= 100;
      EXPECT_EQ(a.add_within(bytes, ka), fits) << bytes;
      if (fits) {
        EXPECT_TRUE(b.add(bytes, kb));
      }
      EXPECT_EQ(a.used(), b.used()) << bytes;
      EXPECT_EQ(a.peak(), b.peak()) << bytes;
      EXPECT_EQ(a.breakdown(), b.breakdown()) << bytes;
      if (bytes == 60) {
        a.release(70, ka);  // 70 of the 100 go back before the next, 1 byte then fits
        b.release(70, kb);
      }
    }
    EXPECT_EQ(a.used(), 61);
    EXPECT_EQ(a.peak(), 100);
    EXPECT_FALSE(a.add_within(40, ka));  // 101: refused under enforce, a warning's case under warn
    EXPECT_EQ(a.used(), 61);
  }
}

// give_back, for bytes the caller holds: the same sums as release.
TEST(NodeMemory, GiveBackOfWhatIsHeldKeepsTheSumsOfRelease) {
  NodeMemory a(1000, MemoryLimit::enforce), b(1000, MemoryLimit::enforce);
  const NodeMemory::Kind ka = a.kind("messages"), kb = b.kind("messages");
  ASSERT_TRUE(a.use(300, "scene") && b.use(300, "scene"));
  ASSERT_TRUE(a.add(500, ka) && b.add(500, kb));
  for (const std::int64_t bytes : {120, 80, 300}) {
    a.give_back(bytes, ka);
    b.release(bytes, kb);
    EXPECT_EQ(a.used(), b.used()) << bytes;
    EXPECT_EQ(a.breakdown(), b.breakdown()) << bytes;
  }
  EXPECT_EQ(a.used(), 300);
  EXPECT_EQ(a.peak(), 800);
  EXPECT_TRUE(a.add_within(700, ka));  // all the node's memory is free again but the scene's
}

TEST(NodeMemory, TheReportNamesProcessorKindsLargestFirstAndTheLimit) {
  NodeMemory m(32 << 20, MemoryLimit::enforce);
  ASSERT_TRUE(m.use(1 << 20, "scene"));
  ASSERT_TRUE(m.use(3 << 20, "image"));
  EXPECT_EQ(m.breakdown(), "image 3.0 MB, scene 1.0 MB");
  EXPECT_EQ(m.report(5, 576 << 20, "hemicube"),
            "processor 5: out of node memory: hemicube 576.0 MB asked while holding 4.0 MB (image 3.0 MB, scene "
            "1.0 MB); the node has 32.0 MB");
  EXPECT_EQ(NodeMemory(1024, MemoryLimit::enforce).breakdown(), "nothing");
}

TEST(NodeMemory, BytesAreFormattedInBinaryUnits) {
  EXPECT_EQ(format_bytes(12), "12 bytes");
  EXPECT_EQ(format_bytes(1536), "1.5 KB");
  EXPECT_EQ(format_bytes(std::int64_t(10) << 30), "10.0 GB");
  EXPECT_THROW(parse_memory_limit("sometimes"), std::invalid_argument);
  EXPECT_EQ(parse_memory_limit("warn"), MemoryLimit::warn);
}

}  // namespace
}  // namespace gcsim::machine
