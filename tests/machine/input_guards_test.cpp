// The guards every reader and writer shares: only regular files are read, with a size cap; TOML is
// bounded before toml++ recurses on it; a failed write or close is an error naming the file.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "machine/input_file.hpp"
#include "machine/output_file.hpp"
#include "machine/toml_limits.hpp"

namespace gcsim::machine {
namespace {

std::string scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("gcsim-input-guards-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

TEST(InputFile, ReadsARegularFileWhole) {
  const std::string path = scratch("ok.txt");
  std::ofstream(path) << "a = 1\n";
  const InputFile in = read_input_file(path, 100);
  EXPECT_TRUE(in.ok()) << in.error;
  EXPECT_EQ(in.text, "a = 1\n");
}

TEST(InputFile, NamesWhatIsNotARegularFile) {
  EXPECT_EQ(read_input_file("/dev/zero", 1 << 20).error, "is a device, not a file");
  EXPECT_EQ(read_input_file(std::filesystem::temp_directory_path(), 1 << 20).error, "is a directory");
  EXPECT_EQ(read_input_file(scratch("missing.toml"), 1 << 20).error, "does not exist");
  const std::string fifo = scratch("pipe");
  std::filesystem::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(read_input_file(fifo, 1 << 20).error, "is a FIFO (named pipe), not a file");  // and does not block
}

TEST(InputFile, RefusesAFileOverItsCap) {
  const std::string path = scratch("big.txt");
  std::ofstream(path) << std::string(101, 'x');
  const InputFile in = read_input_file(path, 100);
  EXPECT_FALSE(in.ok());
  EXPECT_TRUE(in.text.empty());
  EXPECT_NE(in.error.find("101 bytes"), std::string::npos) << in.error;
  EXPECT_TRUE(read_input_file(path, 101).ok());
}

TEST(TomlLimits, BoundsDottedPartsNestingAndItemsWithTheLine) {
  std::string header = "x = 1\n[a";
  for (int i = 0; i < kMaxTomlKeyParts; ++i) header += ".a";
  const auto parts = check_toml_limits(header + "]\n");
  ASSERT_TRUE(parts);
  EXPECT_EQ(parts->line, 2);
  std::string longest_key = "a";
  for (int i = 1; i < kMaxTomlKeyParts; ++i) longest_key += ".a";
  EXPECT_FALSE(check_toml_limits(longest_key + " = 1\n"));  // exactly the limit: accepted
  const auto nested = check_toml_limits("v = " + std::string(kMaxTomlNesting + 1, '[') + std::string(kMaxTomlNesting + 1, ']'));
  ASSERT_TRUE(nested);
  EXPECT_NE(nested->message.find("nested"), std::string::npos);
  EXPECT_FALSE(check_toml_limits("v = " + std::string(kMaxTomlNesting, '[') + std::string(kMaxTomlNesting, ']')));
}

TEST(TomlLimits, SkipsStringsAndComments) {
  const std::string dots(500, '.');
  EXPECT_FALSE(check_toml_limits("a = \"" + dots + "\"\nb = '" + dots + "'\n# " + dots + "\nc = \"\"\"\n" + dots + "\n\"\"\"\n"));
  EXPECT_FALSE(check_toml_limits("a = 1.5\nb = [1.5, 2.5, 3.5]\nc = 1979-05-27T07:32:00.999\n"));
}

TEST(OutputFile, AFullDiskIsAnErrorNamingTheFile) {
  try {
    write_text_file("/dev/full", std::string(1 << 16, 'x'), "JSON file");
    FAIL() << "writing /dev/full succeeded";
  } catch (const OutputFileError& e) {
    EXPECT_NE(std::string(e.what()).find("'/dev/full'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("No space left on device"), std::string::npos) << e.what();
  }
  const std::string path = scratch("written.txt");
  write_text_file(path, "kept\n", "text file");
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "kept");
}

TEST(OutputFile, CloseCheckedReportsAFailedStream) {
  std::ofstream out("/dev/full");
  out << std::string(1 << 16, 'x');
  EXPECT_THROW(close_checked(out, "/dev/full", "CSV file"), OutputFileError);
}

}  // namespace
}  // namespace gcsim::machine
