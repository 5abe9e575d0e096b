#pragma once
// Comma-separated lists on the command line (--nodes 1,2,4,8, --thresholds 0.9,0.99, ...).
// Each item must convert in full (and, for integers, be positive); otherwise the error names the
// option, the item and what each item should be.
#include <string>
#include <vector>

namespace gcsim::pipeline {

std::vector<int> parse_int_list(const std::string& s, const char* what);
std::vector<double> parse_double_list(const std::string& s, const char* what);
// Numbers, possibly none; `expected` describes an item, e.g. "a number (expected ex,ey,ez)".
std::vector<double> parse_number_list(const std::string& s, const char* what, const char* expected);

}  // namespace gcsim::pipeline
