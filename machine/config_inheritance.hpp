#pragma once
// Machine files that inherit: `base = "gc-powerplus.toml"` (relative to the file) or
// `base = "builtin:gc-powerplus"` (configs/gc-powerplus.toml as compiled into the binary;
// builtin_machine_file lists them). The file's tables are laid over its base's,
// key by key, so a what-if file names only what it changes. Every node keeps the file and line it
// came from, so errors found after merging still name the file that wrote the bad key.
#include <string>
#include <string_view>

#include <toml++/toml.h>

namespace gcsim::machine {

// The key that names a file's base.
inline constexpr std::string_view kBaseKey = "base";
// `base = "builtin:NAME"` names configs/NAME.toml as compiled into the binary.
inline constexpr std::string_view kBuiltinPrefix = "builtin:";

// Parses text (named source) and, recursively, the bases it names; returns the merged tables
// with the `base` keys removed. Throws ConfigError naming the file and line of a syntax error,
// of a `base` that is not a string or cannot be opened, or of a cycle of bases.
toml::table parse_with_bases(std::string_view text, const std::string& source);

// Lays overlay over base: tables merge key by key, every other value replaces the base's.
// Setting one of a group of alternative keys (connect_model / connect_serialized) drops the
// base's others, so a child can switch connect model without contradicting its base.
void overlay_tables(toml::table& base, toml::table&& overlay);

}  // namespace gcsim::machine
