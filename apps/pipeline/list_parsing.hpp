#pragma once
// Comma-separated lists on the command line (--nodes 1,2,4,8, --thresholds 0.9,0.99, ...).
// An option declared by add_list_option is split at ',' by CLI11 (its delimiter); the converters
// below check each item, which must convert in full (and, for integers, be positive); otherwise
// the error names the option, the item and what each item should be.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace gcsim::pipeline {

// Declares the list option `name` (e.g. "--nodes"): CLI11 splits each value at ',', and a value
// given again adds its items. It takes one value after the option, so a positional after it stays
// a positional. An empty value ("") is an empty list (list_is_empty).
CLI::Option* add_list_option(CLI::App* cmd, const std::string& name, std::vector<std::string>& items,
                             const std::string& help);
// No items, or only empty ones (`--levels ""`).
bool list_is_empty(const std::vector<std::string>& items);

std::vector<int> parse_int_list(const std::vector<std::string>& items, const char* what);
std::vector<double> parse_double_list(const std::vector<std::string>& items, const char* what);
// The same for a list in one string, split at ','.
std::vector<int> parse_int_list(const std::string& s, const char* what);
std::vector<double> parse_double_list(const std::string& s, const char* what);
// Numbers, possibly none; `expected` describes an item, e.g. "a number (expected ex,ey,ez)".
std::vector<double> parse_number_list(const std::string& s, const char* what, const char* expected);

}  // namespace gcsim::pipeline
