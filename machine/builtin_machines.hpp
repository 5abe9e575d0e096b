#pragma once
// The machine files compiled into the binary (machine/CMakeLists.txt embeds them from configs/):
// the default machine and the files it inherits from, so that it resolves without reading files.
#include <string>
#include <string_view>
#include <vector>

namespace gcsim::machine {

// The default machine's file: the GC as measured (the published machine with the mechanisms of
// tables 4.6/4.7 and costs fitted to the thesis's tables; docs/calibration.md).
inline constexpr std::string_view kDefaultMachineFile = "gc-powerplus-calibrated.toml";
// The GC-PowerPlus as published.
inline constexpr std::string_view kPublishedMachineFile = "gc-powerplus.toml";

// A built-in file's text by its name under configs/ ("gc-powerplus.toml"); empty if not built in.
std::string_view builtin_machine_file(std::string_view file_name);
std::vector<std::string_view> builtin_machine_file_names();
// The source name a built-in file's errors carry, "<built-in configs/NAME>". A `base = "F"` in a
// file of that source resolves to the built-in F, never to a file on disk.
std::string builtin_source(std::string_view file_name);

}  // namespace gcsim::machine
