#pragma once
// Per-element radiosities as a user can check them without decoding an image: one row per
// element with its id, patch, surface, area and radiosity r, g, b. CSV or JSON, chosen by the file
// name (.json: JSON, anything else: CSV). Numbers are written with 17 significant digits, so they
// read back to the same doubles.
#include <iosfwd>
#include <string>
#include <vector>

#include "apps/radiosity/scene.hpp"

namespace gcsim::radiosity {

void write_radiosities_csv(std::ostream& out, const Scene& scene, const std::vector<Rgb>& element_radiosity);
void write_radiosities_json(std::ostream& out, const Scene& scene, const std::vector<Rgb>& element_radiosity);
// Writes the file; throws std::runtime_error naming it if it cannot be written, and
// std::invalid_argument if the radiosities do not match the scene's elements.
void write_radiosities(const std::string& path, const Scene& scene, const std::vector<Rgb>& element_radiosity);

}  // namespace gcsim::radiosity
