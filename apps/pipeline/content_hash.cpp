#include "apps/pipeline/content_hash.hpp"

#include <cstdint>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "apps/pipeline/failure.hpp"
#include "machine/builtin_machines.hpp"
#include "machine/config_inheritance.hpp"

namespace gcsim::pipeline {

namespace {

std::string read_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw FileError(fmt::format("cannot read '{}' to hash it (does it exist?)", file.string()));
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

std::string content_hash(std::string_view bytes) {
  std::uint64_t h = 14695981039346656037ULL;
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ULL;
  }
  return fmt::format("fnv1a64:{:016x}", h);
}

std::string file_content_hash(const std::filesystem::path& file) { return content_hash(read_file(file)); }

std::string machine_content_hash(const std::string& machine_file) {
  const std::string_view name = machine::kDefaultMachineFile;
  const toml::table resolved =
      machine_file.empty() ? machine::parse_with_bases(machine::builtin_machine_file(name), machine::builtin_source(name))
                           : machine::parse_with_bases(read_file(machine_file), machine_file);
  std::ostringstream text;
  text << toml::toml_formatter(resolved);  // toml::table keeps its keys sorted: the same tables, the same text
  return content_hash(text.str());
}

}  // namespace gcsim::pipeline
