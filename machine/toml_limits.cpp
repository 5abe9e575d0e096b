#include "machine/toml_limits.hpp"

#include <fmt/format.h>

namespace gcsim::machine {

namespace {

class Scanner {
 public:
  explicit Scanner(std::string_view text) : s_(text) {}

  std::optional<TomlLimitViolation> run() {
    while (i_ < s_.size()) {
      const char c = s_[i_];
      if (c == '"' || c == '\'') {
        skip_string(c);
        continue;
      }
      ++i_;
      if (auto v = structural(c)) return v;
    }
    return std::nullopt;
  }

 private:
  std::optional<TomlLimitViolation> structural(char c) {
    switch (c) {
      case '\n': ++line_; key_parts_ = 1; break;
      case '#': while (i_ < s_.size() && s_[i_] != '\n') ++i_; break;
      case '.':
        if (++key_parts_ > kMaxTomlKeyParts)
          return fail(fmt::format("a dotted key or table header of more than {} parts", kMaxTomlKeyParts));
        break;
      case '[': case '{':
        key_parts_ = 1;
        if (++depth_ > kMaxTomlNesting)
          return fail(fmt::format("arrays or tables nested more than {} deep", kMaxTomlNesting));
        return count_item();
      case ']': case '}': --depth_; key_parts_ = 1; break;
      case '=': case ',': key_parts_ = 1; return count_item();
      default: break;
    }
    return std::nullopt;
  }

  std::optional<TomlLimitViolation> count_item() {
    if (++items_ > kMaxTomlItems) return fail(fmt::format("more than {} keys, tables and array elements", kMaxTomlItems));
    return std::nullopt;
  }

  // Skips a basic or literal string, single- or multi-line; escapes only in basic strings.
  void skip_string(char quote) {
    const bool multi = s_.substr(i_, 3) == std::string_view(quote == '"' ? "\"\"\"" : "'''");
    i_ += multi ? 3 : 1;
    while (i_ < s_.size()) {
      const char c = s_[i_];
      if (c == '\\' && quote == '"') {
        if (i_ + 1 < s_.size() && s_[i_ + 1] == '\n') ++line_;
        i_ += 2;
        continue;
      }
      if (c == '\n') {
        ++line_;
        if (!multi) return;  // an unterminated string: toml++ reports it
      }
      if (c == quote && (!multi || s_.substr(i_, 3) == std::string_view(quote == '"' ? "\"\"\"" : "'''"))) {
        i_ += multi ? 3 : 1;
        return;
      }
      ++i_;
    }
  }

  TomlLimitViolation fail(std::string what) const { return {line_, "too deep or too large for a gcsim file: " + what}; }

  std::string_view s_;
  std::size_t i_ = 0;
  int line_ = 1;
  int key_parts_ = 1;
  int depth_ = 0;
  long items_ = 0;
};

}  // namespace

std::optional<TomlLimitViolation> check_toml_limits(std::string_view text) { return Scanner(text).run(); }

}  // namespace gcsim::machine
