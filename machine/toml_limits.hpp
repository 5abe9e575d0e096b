#pragma once
// A cheap scan of TOML text before toml++ parses it: toml++ recurses once per dotted key part
// and per nesting level, so a header of 50,000 parts (`[a.a.a...]`) overflowed the host stack.
// Every TOML reader (machine files, scene files, calibration overrides) calls this first.
#include <optional>
#include <string>
#include <string_view>

namespace gcsim::machine {

inline constexpr int kMaxTomlKeyParts = 64;      // parts of one dotted key or table header
inline constexpr int kMaxTomlNesting = 64;       // arrays and inline tables inside each other
inline constexpr long kMaxTomlItems = 1000000;   // keys, headers and array elements in all

struct TomlLimitViolation {
  int line;             // 1-based
  std::string message;  // what is too deep or too many, and the limit
};

// The first place `text` goes beyond a limit above, or nothing. Strings and comments are skipped.
std::optional<TomlLimitViolation> check_toml_limits(std::string_view text);

}  // namespace gcsim::machine
