#include "apps/pipeline/option_checks.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "apps/pipeline/failure.hpp"

namespace gcsim::pipeline {

namespace {

// Whether s reads in full as a number (strtod's syntax) and that number is not finite.
bool non_finite_number(const std::string& s) {
  if (s.empty()) return false;
  errno = 0;
  char* end = nullptr;
  const double x = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size()) return false;  // not a number at all: another check's business
  return !std::isfinite(x) || (errno == ERANGE && std::abs(x) > 1);
}

// CLI11 reads integers with strtoll's base 0: "010" is 8 and "0x10" 16. gcsim's numbers are
// decimal: on a numeric option, leading zeros are dropped ("010" is 10, as --nodes reads it) and
// an 0x, 0b or 0o prefix is refused.
std::string check_decimal(std::string& value) {
  std::size_t i = value.find_first_not_of(" \t");
  if (i == std::string::npos) return "";
  if (value[i] == '+' || value[i] == '-') ++i;
  if (i + 1 >= value.size() || value[i] != '0') return "";
  const char next = char(std::tolower(static_cast<unsigned char>(value[i + 1])));
  if (next == 'x' || next == 'b' || next == 'o')
    return "'" + value + "': numbers are decimal (no 0x, 0b or 0o prefix)";
  const bool digits = std::all_of(value.begin() + long(i), value.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
  if (digits) value.erase(i, std::min(value.find_first_not_of('0', i), value.size() - 1) - i);
  return "";
}

std::string check_finite(std::string& value) {
  std::size_t start = 0;
  for (;;) {  // each item of a comma-separated list
    const std::size_t comma = value.find(',', start);
    const std::string item = value.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (non_finite_number(item)) return "'" + item + "' is not a finite number";
    if (comma == std::string::npos) return "";
    start = comma + 1;
  }
}

// CLI11 assigns an empty value to a number as 0 (or as "not given" to a std::optional), which
// some options read as "the default": an explicit empty number is refused instead.
std::string check_not_empty(std::string& value) {
  return value.find_first_not_of(" \t") == std::string::npos ? "an empty value is not a number" : "";
}

bool takes_numbers(const CLI::Option& o) {
  const std::string type = o.get_type_name();
  return type.rfind("INT", 0) == 0 || type.rfind("UINT", 0) == 0 || type.rfind("FLOAT", 0) == 0 ||
         type.rfind("NUMBER", 0) == 0 || type.rfind("SIZE", 0) == 0;
}

}  // namespace

void reject_non_finite_numbers(CLI::App* app) {
  for (CLI::Option* o : app->get_options()) {
    if (o->get_type_size() != 0) o->check(CLI::Validator(check_finite, "", "FINITE"));  // not on flags
    if (o->get_type_size() == 0 || !takes_numbers(*o)) continue;
    o->transform(CLI::Validator(check_not_empty, "", "NONEMPTY"));  // first: before any range check
    o->transform(CLI::Validator(check_decimal, "", "DECIMAL"));  // a transform: it rewrites "010" as "10"
  }
  for (CLI::App* sub : app->get_subcommands({})) reject_non_finite_numbers(sub);
}

CLI::Validator no_negative_size() {
  return CLI::Validator(
      [](std::string& v) -> std::string {
        const std::size_t first = v.find_first_not_of(" \t");
        if (first != std::string::npos && v[first] == '-') return "'" + v + "': a size cannot be negative (expected e.g. 0, 512, 16KB)";
        return "";
      },
      "", "NONNEGATIVE");
}

CLI::Validator positive_number() {
  return CLI::Validator(
      [](std::string& v) -> std::string {
        char* end = nullptr;
        const double x = std::strtod(v.c_str(), &end);
        if (v.empty() || end != v.c_str() + v.size()) return "'" + v + "' is not a number";
        if (!std::isfinite(x) || x <= 0) return "'" + v + "' must be a positive finite number";
        return "";
      },
      "> 0", "POSITIVE");
}

void check_scene_file(const std::string& name, const std::vector<std::string>& builtins) {
  auto lower = [](std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
  };
  for (const std::string& b : builtins)
    if (lower(b) == lower(name)) return;
  if (name.find_first_of("/.") == std::string::npos) return;
  std::error_code ec;
  if (std::filesystem::is_directory(name, ec)) throw FileError(fmt::format("--scene {}: is a directory, not a scene file", name));
  if (!std::filesystem::exists(name, ec)) {
    std::string known;
    for (const std::string& b : builtins) known += (known.empty() ? "" : ", ") + b;
    throw FileError(fmt::format("--scene {}: the file does not exist (built-in scenes: {})", name, known));
  }
}

}  // namespace gcsim::pipeline
