#include "machine/config_inheritance.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "machine/builtin_machines.hpp"
#include "machine/input_file.hpp"
#include "machine/machine_config.hpp"
#include "machine/toml_limits.hpp"

namespace gcsim::machine {
namespace {

// Keys that say the same thing in different ways, with the keys that only refine them: a file
// that sets one of the alternatives replaces the whole group, while a file that sets only a
// refinement (the server block of a "servers" base) keeps its base's choice.
struct AlternativeKeys {
  std::vector<std::string_view> alternatives;
  std::vector<std::string_view> refinements;
};
const std::vector<AlternativeKeys> kAlternativeKeys = {
    {{"connect_model", "connect_serialized"}, {"connect_server_block"}},
};

void drop_replaced_alternatives(toml::table& base, const toml::table& overlay) {
  for (const auto& group : kAlternativeKeys) {
    bool overlay_sets_one = false;
    for (auto key : group.alternatives) overlay_sets_one = overlay_sets_one || overlay.contains(key);
    if (!overlay_sets_one) continue;
    for (const auto* keys : {&group.alternatives, &group.refinements})
      for (auto key : *keys)
        if (!overlay.contains(key)) base.erase(key);
  }
}

toml::table parse_text(std::string_view text, const std::string& source) {
  if (auto too_much = check_toml_limits(text)) throw ConfigError(source, too_much->line, too_much->message);
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw ConfigError(source, static_cast<int>(e.source().begin.line), std::string(e.description()));
  }
}

int line_of(const toml::node& n) { return static_cast<int>(n.source().begin.line); }

// The identity of a base in the chain, for finding cycles: a built-in file's source name, or the path.
std::string identity(const std::string& source) {
  if (source.empty() || source.front() == '<') return source;
  std::error_code ec;
  const auto p = std::filesystem::weakly_canonical(source, ec);
  return ec ? source : p.string();
}

toml::table load_chain(std::string_view text, const std::string& source, std::vector<std::string>& chain);

std::string builtin_base_names() {
  std::string names;
  for (std::string_view file : builtin_machine_file_names())
    names += (names.empty() ? "\"" : ", \"") + std::string(kBuiltinPrefix) +
             std::string(file.substr(0, file.size() - std::string_view(".toml").size())) + "\"";
  return names;
}

// Reads the file a `base` key names, relative to the file that names it.
toml::table load_base(const toml::node& key, const std::string& child, std::vector<std::string>& chain) {
  const auto* name = key.as_string();
  if (!name) {
    throw ConfigError(child, line_of(key),
                      "'base' must be a string: a machine file (relative to this one) or one of " + builtin_base_names());
  }
  std::string source;
  std::string text;
  const bool named_builtin = name->get().rfind(kBuiltinPrefix, 0) == 0;
  // A built-in file's own bases are built in too: the default resolves without reading files.
  const std::string builtin_prefix = builtin_source("").substr(0, builtin_source("").size() - 1);
  if (named_builtin || child.rfind(builtin_prefix, 0) == 0) {
    const std::string file = named_builtin ? name->get().substr(kBuiltinPrefix.size()) + ".toml" : name->get();
    text = std::string(builtin_machine_file(file));
    if (text.empty())
      throw ConfigError(child, line_of(key),
                        "base '" + name->get() + "' is not built in; expected a file or one of: " + builtin_base_names());
    source = builtin_source(file);
  } else {
    const std::filesystem::path here = child.empty() || child.front() == '<' ? "" : std::filesystem::path(child).parent_path();
    const std::filesystem::path file = here / name->get();
    InputFile in = read_input_file(file, kMaxTomlFileBytes);
    if (!in.ok()) throw ConfigError(child, line_of(key), "base '" + name->get() + "': " + file.string() + " " + in.error);
    source = file.string();
    text = std::move(in.text);
  }
  for (const auto& seen : chain) {
    if (seen == identity(source)) {
      std::string cycle;
      for (const auto& s : chain) cycle += s + " -> ";
      throw ConfigError(child, line_of(key), "machine files name each other as base: " + cycle + identity(source));
    }
  }
  return load_chain(text, source, chain);
}

toml::table load_chain(std::string_view text, const std::string& source, std::vector<std::string>& chain) {
  chain.push_back(identity(source));
  toml::table own = parse_text(text, source);
  const toml::node* key = own.get(kBaseKey);
  if (!key) {
    chain.pop_back();
    return own;
  }
  toml::table merged = load_base(*key, source, chain);
  own.erase(kBaseKey);
  overlay_tables(merged, std::move(own));
  chain.pop_back();
  return merged;
}

}  // namespace

void overlay_tables(toml::table& base, toml::table&& overlay) {
  drop_replaced_alternatives(base, overlay);
  for (auto&& [key, value] : overlay) {
    toml::node* mine = base.get(key.str());
    if (mine && mine->is_table() && value.is_table()) {
      overlay_tables(*mine->as_table(), std::move(*value.as_table()));
    } else {
      // Moving keeps the node's source (file and line); copying would lose it.
      base.insert_or_assign(key, std::move(value));
    }
  }
}

toml::table parse_with_bases(std::string_view text, const std::string& source) {
  std::vector<std::string> chain;
  return load_chain(text, source, chain);
}

}  // namespace gcsim::machine
