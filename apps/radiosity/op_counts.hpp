#pragma once
// Counted operations, so that simulated time is charged from work actually done (never from host
// time). Names match the [ops] table of configs/*.toml.
#include <array>
#include <cstdint>
#include <vector>

#include "parix/processor.hpp"

namespace gcsim::radiosity {

struct OpCounts {
  std::int64_t polygon_project = 0;   // an element transformed, clipped and projected onto a hemicube face
  std::int64_t hemicube_pixel = 0;    // a hemicube pixel tested against a projected element (Z-buffer step)
  std::int64_t hemicube_sample = 0;   // a hierarchical-hemicube sample tested against a candidate element
  std::int64_t hemicube_cull = 0;     // an element's projected bounding box tested against a hierarchical square
  std::int64_t form_factor_sum = 0;   // a (cell, element) partial form factor accumulated or merged
  std::int64_t element_update = 0;    // an element receiving one shooter's energy
  std::int64_t patch_select = 0;      // a patch examined when choosing the shooters
  std::int64_t path_transmittance = 0;  // a (shooter, element) segment's transmittance through media

  OpCounts& operator+=(const OpCounts& o) {
    polygon_project += o.polygon_project;
    hemicube_pixel += o.hemicube_pixel;
    hemicube_sample += o.hemicube_sample;
    hemicube_cull += o.hemicube_cull;
    form_factor_sum += o.form_factor_sum;
    element_update += o.element_update;
    patch_select += o.patch_select;
    path_transmittance += o.path_transmittance;
    return *this;
  }
  // Every count under its name in [ops].
  std::array<parix::OpCount, 8> named() const {
    return {{{"polygon_project", polygon_project},
             {"hemicube_pixel", hemicube_pixel},
             {"hemicube_sample", hemicube_sample},
             {"hemicube_cull", hemicube_cull},
             {"form_factor_sum", form_factor_sum},
             {"element_update", element_update},
             {"patch_select", patch_select},
             {"path_transmittance", path_transmittance}}};
  }
  // Charges the counts to the processor and clears them.
  void charge(parix::Processor& p) {
    std::vector<parix::OpCount> nonzero;
    for (const auto& o : named())
      if (o.count > 0) nonzero.push_back(o);
    if (!nonzero.empty()) p.compute(nonzero);
    *this = {};
  }
};

}  // namespace gcsim::radiosity
