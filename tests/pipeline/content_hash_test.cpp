// The hashes a run records: a machine file hashes by what it resolves to after inheritance, so a
// file that inherits everything hashes as its base, and any changed key changes the hash.
#include <string>

#include <gtest/gtest.h>

#include "apps/pipeline/content_hash.hpp"
#include "apps/pipeline/failure.hpp"
#include "tests/support/scratch_path.hpp"

namespace gcsim::pipeline {
namespace {

TEST(ContentHash, IsFnv1a64OfTheBytes) {
  // The FNV-1a reference values: the empty string is the offset basis; "a" one step of it.
  EXPECT_EQ(content_hash(""), "fnv1a64:cbf29ce484222325");
  EXPECT_EQ(content_hash("a"), "fnv1a64:af63dc4c8601ec8c");
  EXPECT_EQ(content_hash("foobar"), "fnv1a64:85944171f73967e8");
}

class MachineHash : public ::testing::Test {
 protected:
  test_support::ScratchDir dir{"gcsim-machine-hash-"};
  const std::string base = dir.write("base.toml", "name = \"m\"\n[topology]\nmesh = [2, 2]\n[node]\nmemory_mb = 32\n");
};

TEST_F(MachineHash, FilesThatResolveAlikeHashAlike) {
  const std::string child = dir.write("child.toml", "base = \"base.toml\"\n");
  const std::string respelled = dir.write("respelled.toml", "name = 'm'  # the same tables, another order\n[node]\nmemory_mb = 32\n\n[topology]\nmesh = [ 2,2 ]\n");
  EXPECT_EQ(machine_content_hash(child), machine_content_hash(base));
  EXPECT_EQ(machine_content_hash(respelled), machine_content_hash(base));
}

TEST_F(MachineHash, AChangedKeyChangesTheHash) {
  const std::string child = dir.write("child.toml", "base = \"base.toml\"\n[node]\nmemory_mb = 64\n");
  EXPECT_NE(machine_content_hash(child), machine_content_hash(base));
  const std::string edited_base = machine_content_hash(base);
  dir.write("base.toml", "name = \"m\"\n[topology]\nmesh = [2, 2]\n[node]\nmemory_mb = 16\n");
  EXPECT_NE(machine_content_hash(base), edited_base);
}

TEST_F(MachineHash, TheBuiltInDefaultHashesAsItsFileAndAMissingFileIsAFileError) {
  // The compiled-in default and the shipped file it was embedded from (inheriting from the file
  // beside it) resolve alike; the published machine is another.
  EXPECT_EQ(machine_content_hash(""), machine_content_hash(GCSIM_SOURCE_DIR "/configs/gc-powerplus-calibrated.toml"));
  EXPECT_NE(machine_content_hash(""), machine_content_hash(GCSIM_SOURCE_DIR "/configs/gc-powerplus.toml"));
  EXPECT_THROW(machine_content_hash((dir.path() / "none.toml").string()), FileError);
}

}  // namespace
}  // namespace gcsim::pipeline
