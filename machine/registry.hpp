#pragma once
// A list of named entries that each join from their own file, through a namespace-scope
// registrar object, so that adding one edits no central list: network models
// (machine/network_registry.hpp), physical interconnects (machine/interconnect_registry.hpp) and
// virtual topologies (machine/topology.hpp) keep theirs in one.
//
// Registration order across files is unspecified (it follows the link), so the list is kept
// sorted by each entry's `order`, then by name: help texts and error messages list the entries in
// a fixed order whatever the build links first. Entry is a struct with `std::string_view name` and
// `int order`.
//
// Registrars run before main(). Built-in entries live in gcsim_machine_registered, which every
// program links whole (machine/CMakeLists.txt), so the linker keeps them although nothing names
// them; an entry from another folder comes in an OBJECT library (gcsim_add_interconnect,
// gcsim_add_network_model).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace gcsim::machine {

template <class Entry>
class Registry {
 public:
  // The one registry of Entry, built on first use, so registrars in other files may run in any order.
  static Registry& instance() {
    static Registry r;
    return r;
  }

  // A second entry under one name is a build mistake: it is reported before main() runs.
  void add(Entry e) {
    if (find(e.name)) {
      std::fprintf(stderr, "gcsim: two registered entries are named '%.*s'\n", int(e.name.size()), e.name.data());
      std::abort();
    }
    const auto before = [](const Entry& a, const Entry& b) { return a.order != b.order ? a.order < b.order : a.name < b.name; };
    entries_.insert(std::upper_bound(entries_.begin(), entries_.end(), e, before), std::move(e));
  }

  const std::vector<Entry>& entries() const { return entries_; }

  const Entry* find(std::string_view name) const {
    for (const Entry& e : entries_)
      if (e.name == name) return &e;
    return nullptr;
  }

  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const Entry& e : entries_) out.emplace_back(e.name);
    return out;
  }

  // "analytic, flow, packet": for error messages.
  std::string list() const {
    std::string out;
    for (const Entry& e : entries_) out.append(out.empty() ? "" : ", ").append(e.name);
    return out;
  }

 private:
  Registry() = default;
  std::vector<Entry> entries_;
};

}  // namespace gcsim::machine
