#include "apps/common/scene/scene_file_reader.hpp"

#include <cmath>
#include <set>

#include <fmt/format.h>

#include "apps/common/scene/scene_file.hpp"

namespace gcsim::scene::file {

namespace {
std::string quoted(std::string_view key) { return fmt::format("'{}'", key); }
}  // namespace

void Reader::fail(const toml::node* n, const std::string& what) const { throw SceneFileError(file_, line_of(n), what); }

void Reader::only_keys(const toml::table& t, const std::string& where,
                       std::initializer_list<std::string_view> keys) const {
  const std::set<std::string_view> known(keys);
  for (const auto& [k, v] : t) {
    if (known.count(k.str())) continue;
    std::string list;
    for (auto key : keys) {
      if (!list.empty()) list += ", ";
      list += key;
    }
    fail(&v, fmt::format("unknown key {} in {} (expected one of: {})", quoted(k.str()), where, list));
  }
}

const toml::table* Reader::table(const toml::table& parent, std::string_view key, const std::string& where) const {
  const toml::node* n = parent.get(key);
  if (!n) return nullptr;
  if (!n->is_table()) fail(n, fmt::format("{} in {} must be a table", quoted(key), where));
  return n->as_table();
}

std::vector<const toml::table*> Reader::tables(const toml::table& parent, std::string_view key) const {
  std::vector<const toml::table*> out;
  const toml::node* n = parent.get(key);
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a) fail(n, fmt::format("{} must be an array of tables, written [[{}]]", quoted(key), key));
  for (const toml::node& e : *a) {
    if (!e.is_table()) fail(&e, fmt::format("every {} must be a table, written [[{}]]", quoted(key), key));
    out.push_back(e.as_table());
  }
  return out;
}

double Reader::as_number(const toml::node& n, const std::string& what) const {
  if (auto i = n.as_integer()) return double(i->get());
  if (auto f = n.as_floating_point()) return f->get();
  fail(&n, what + " must be a number");
}

double Reader::required_number(const toml::table& t, std::string_view key, const std::string& where, double lo,
                               double hi) const {
  const toml::node* n = t.get(key);
  if (!n) fail(&t, fmt::format("missing key {} in {}", quoted(key), where));
  const std::string what = fmt::format("{} in {}", quoted(key), where);
  const double v = as_number(*n, what);
  if (!std::isfinite(v) || v < lo || v > hi)
    fail(n, fmt::format("{} is {}; expected a finite value in [{}, {}]", what, v, lo, hi));
  return v;
}

double Reader::number(const toml::table& t, std::string_view key, const std::string& where, double lo, double hi,
                      double fallback) const {
  return t.get(key) ? required_number(t, key, where, lo, hi) : fallback;
}

int Reader::integer(const toml::table& t, std::string_view key, const std::string& where, int lo, int hi,
                    int fallback) const {
  const toml::node* n = t.get(key);
  if (!n) return fallback;
  auto i = n->as_integer();
  if (!i) fail(n, fmt::format("{} in {} must be an integer", quoted(key), where));
  if (i->get() < lo || i->get() > hi)
    fail(n, fmt::format("{} in {} is {}; expected an integer in [{}, {}]", quoted(key), where, i->get(), lo, hi));
  return int(i->get());
}

bool Reader::boolean(const toml::table& t, std::string_view key, const std::string& where, bool fallback) const {
  const toml::node* n = t.get(key);
  if (!n) return fallback;
  auto b = n->as_boolean();
  if (!b) fail(n, fmt::format("{} in {} must be true or false", quoted(key), where));
  return b->get();
}

std::string Reader::string(const toml::table& t, std::string_view key, const std::string& where,
                           const std::string* fallback) const {
  const toml::node* n = t.get(key);
  if (!n) {
    if (fallback) return *fallback;
    fail(&t, fmt::format("missing key {} in {}", quoted(key), where));
  }
  auto s = n->as_string();
  if (!s) fail(n, fmt::format("{} in {} must be a string", quoted(key), where));
  return s->get();
}

glm::dvec3 Reader::vec3_node(const toml::node& n, const std::string& what) const {
  const toml::array* a = n.as_array();
  if (!a || a->size() != 3) fail(&n, what + " must be an array of three numbers [x, y, z]");
  glm::dvec3 v;
  for (int k = 0; k < 3; ++k) {
    v[k] = as_number(*a->get(k), what + fmt::format(" component {}", k + 1));
    if (!std::isfinite(v[k]) || std::abs(v[k]) > kMaxCoordinate)
      fail(a->get(k), fmt::format("{} component {} is {}; expected a finite number within +-{:g}", what, k + 1, v[k],
                                  kMaxCoordinate));
  }
  return v;
}

glm::dvec3 Reader::vec3(const toml::table& t, std::string_view key, const std::string& where) const {
  const toml::node* n = t.get(key);
  if (!n) fail(&t, fmt::format("missing key {} in {}", quoted(key), where));
  return vec3_node(*n, fmt::format("{} in {}", quoted(key), where));
}

Rgb Reader::rgb(const toml::table& t, std::string_view key, const std::string& where, double lo, double hi,
                Rgb fallback) const {
  const toml::node* n = t.get(key);
  if (!n) return fallback;
  const std::string what = fmt::format("{} in {}", quoted(key), where);
  Rgb c;
  if (n->is_number()) {
    c = Rgb(as_number(*n, what));
  } else {
    const toml::array* a = n->as_array();
    if (!a || a->size() != 3) fail(n, what + " must be a number or an array of three numbers [r, g, b]");
    for (int k = 0; k < 3; ++k) c[k] = as_number(*a->get(k), what);
  }
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(c[k]) || c[k] < lo || c[k] > hi)
      fail(n, fmt::format("{} has {}; expected finite values in [{}, {}]", what, c[k], lo, hi));
  return c;
}

std::array<int, 2> Reader::grid(const toml::table& t, std::string_view key, const std::string& where, int hi) const {
  const toml::node* n = t.get(key);
  if (!n) return {1, 1};
  const toml::array* a = n->as_array();
  const std::string what = fmt::format("{} in {}", quoted(key), where);
  if (!a || a->size() != 2) fail(n, what + " must be two integers [columns, rows]");
  std::array<int, 2> g{};
  for (int k = 0; k < 2; ++k) {
    auto i = a->get(k)->as_integer();
    if (!i || i->get() < 1 || i->get() > hi) fail(n, fmt::format("{} must be two integers in [1, {}]", what, hi));
    g[k] = int(i->get());
  }
  return g;
}

std::filesystem::path Reader::existing_file(const toml::table& t, std::string_view key,
                                            const std::string& where) const {
  const std::string name = string(t, key, where);
  const toml::node* n = t.get(key);
  if (name.empty()) fail(n, fmt::format("{} in {} is empty; expected a file name", quoted(key), where));
  std::filesystem::path p(name);
  if (p.is_relative()) p = base_ / p;
  std::error_code ec;
  if (!std::filesystem::exists(p, ec))
    fail(n, fmt::format("{} in {}: file '{}' is missing (looked for {})", quoted(key), where, name, p.string()));
  if (!std::filesystem::is_regular_file(p, ec))
    fail(n, fmt::format("{} in {}: '{}' is not a regular file", quoted(key), where, p.string()));
  return p;
}

}  // namespace gcsim::scene::file
