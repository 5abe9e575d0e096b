#pragma once
// Machine-file keys a fit may change ("free parameters"), named by their table and key as in the
// file: network.connect_base_us, node.clock_mhz, ops.polygon_project. A machine with some of them
// set to new values is made by overriding them in the file's TOML and parsing it again, so every
// fitted machine passes the same checks as a hand-written one.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "machine/machine_config.hpp"

namespace gcsim::calibration {

class MachineFile {
 public:
  // The file (or, for an empty path, the built-in GC-PowerPlus).
  explicit MachineFile(const std::filesystem::path& file);

  // The numeric keys that may be freed, as "table.key".
  std::vector<std::string> free_keys() const;
  // Throws std::invalid_argument naming the key and listing the valid ones if it is unknown.
  void check_free_key(const std::string& key) const;
  double value(const std::string& key) const;
  machine::MachineConfig with(const std::map<std::string, double>& values) const;

  const machine::MachineConfig& config() const { return base_; }
  const std::string& text() const { return text_; }
  const std::string& source() const { return source_; }

 private:
  std::string text_;
  std::string source_;
  machine::MachineConfig base_;
};

}  // namespace gcsim::calibration
