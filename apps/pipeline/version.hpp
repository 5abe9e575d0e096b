#pragma once
// Which gcsim this is: the release and the commit it was built from, for `gcsim --version` and
// for the records a run writes.
#include <string_view>

namespace gcsim::pipeline {

std::string_view version();  // "0.1.0"
std::string_view commit();   // "c8a1f7e" ("-dirty" when built from a changed tree; "unknown" outside git)
// "gcsim 0.1.0 (commit c8a1f7e)"
std::string_view version_line();

}  // namespace gcsim::pipeline
