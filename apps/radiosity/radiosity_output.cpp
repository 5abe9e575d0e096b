#include "apps/radiosity/radiosity_output.hpp"

#include <fstream>
#include <ostream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "machine/output_file.hpp"

namespace gcsim::radiosity {

namespace {

void check_sizes(const Scene& scene, const std::vector<Rgb>& b) {
  if (b.size() != scene.elements.size())
    throw std::invalid_argument(fmt::format("{} radiosities for {} elements of scene '{}'", b.size(),
                                            scene.elements.size(), scene.name));
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

void write_radiosities_csv(std::ostream& out, const Scene& scene, const std::vector<Rgb>& b) {
  check_sizes(scene, b);
  out << "element,patch,surface,area,r,g,b\n";
  for (std::size_t e = 0; e < b.size(); ++e) {
    const SceneElement& el = scene.elements[e];
    out << fmt::format("{},{},{},{:.17g},{:.17g},{:.17g},{:.17g}\n", e, el.patch, scene.patches[el.patch].surface,
                       el.area, b[e].r, b[e].g, b[e].b);
  }
}

void write_radiosities_json(std::ostream& out, const Scene& scene, const std::vector<Rgb>& b) {
  check_sizes(scene, b);
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (std::size_t e = 0; e < b.size(); ++e) {
    const SceneElement& el = scene.elements[e];
    rows.push_back({{"element", e},
                    {"patch", el.patch},
                    {"surface", scene.patches[el.patch].surface},
                    {"area", el.area},
                    {"radiosity", {b[e].r, b[e].g, b[e].b}}});
  }
  nlohmann::ordered_json doc{{"scene", scene.name}, {"elements", std::move(rows)}};
  out << doc.dump(1) << "\n";
}

void write_radiosities(const std::string& path, const Scene& scene, const std::vector<Rgb>& b) {
  check_sizes(scene, b);
  std::ofstream out(path, std::ios::trunc);
  if (!out) throw std::runtime_error(fmt::format("cannot write the radiosities to '{}'", path));
  if (ends_with(path, ".json"))
    write_radiosities_json(out, scene, b);
  else
    write_radiosities_csv(out, scene, b);
  machine::close_checked(out, path, "radiosities file");
}

}  // namespace gcsim::radiosity
