#pragma once
// Hemicube form factors from a shooting patch to every element (thesis section 3.4.2, fig. 3.8).
// The hemicube sits on the patch centre. Every element is transformed into the hemicube's frame once,
// clipped against each face's frustum and projected; then each cell of the fixed partition (see
// delta_form_factors.hpp) is Z-buffered on its own. A pixel's answer never depends on which other
// cells are computed, so any distribution of cells over nodes gives the same per-cell sums, and
// adding the cells in their fixed order gives bit-identical form factors on any node count.
//
// With hierarchical_levels L > 0 (thesis section 4.5) the cells are sampled at resolution R / 2^L;
// a coarse pixel whose corners and centre do not all see the same element (an element border) is
// split into four, recursively, down to resolution R.
#include <array>
#include <vector>

#include "apps/radiosity/delta_form_factors.hpp"
#include "apps/radiosity/op_counts.hpp"
#include "apps/radiosity/scene.hpp"

namespace gcsim::radiosity {

// Form factor sums of one cell: element indices ascending, with their summed delta form factors.
struct CellFormFactors {
  int cell = -1;
  std::vector<int> element;
  std::vector<double> value;
};

struct HemicubeOptions {
  int resolution = 128;        // pixels across the top face
  int cells_per_side = 8;      // the parallel partition: T x T top cells, T x T/2 per side face
  int hierarchical_levels = 0; // 0: fixed hemicube
};

class HemicubeRenderer {
 public:
  HemicubeRenderer(const Scene& scene, const HemicubeOptions& options);

  int cell_count() const { return int(cells_.size()); }
  const HemicubeOptions& options() const { return options_; }

  // Transforms, clips and projects every element for the hemicube on patch `shooter`.
  void project(int shooter, OpCounts& ops);
  // Z-buffers one cell of the current projection.
  CellFormFactors cell_form_factors(int cell, OpCounts& ops);

  // The whole row F(shooter -> element) for every element: all cells, added in cell order.
  std::vector<double> form_factor_row(int shooter, OpCounts& ops);

 private:
  struct Projected {
    int element;
    bool front;                 // the element faces the shooter (only then does it receive)
    int count;
    std::array<double, 2> p[12];// pixel coordinates
    double edge_sign;
    Vec3 plane_n;               // element plane in face coordinates: plane_n . q = plane_k
    double plane_k;
    int bx0, by0, bx1, by1;     // pixels whose centres may be inside, inclusive-exclusive
    double fx0, fy0, fx1, fy1;  // bounding box in pixel units
  };
  bool inside(const Projected& poly, double px, double py) const;
  double depth(int face, const Projected& poly, double px, double py) const;
  void fixed_cell(const HemicubeCell& c, CellFormFactors& out, OpCounts& ops);
  void hierarchical_cell(const HemicubeCell& c, CellFormFactors& out, OpCounts& ops);
  int sample(int face, const std::vector<int>& candidates, double px, double py, OpCounts& ops) const;
  void subdivide(int face, const std::vector<int>& candidates, int i0, int j0, int size, OpCounts& ops);

  const Scene& scene_;
  HemicubeOptions options_;
  DeltaFormFactors dff_;
  std::vector<HemicubeCell> cells_;  // in fine pixels
  int shooter_ = -1;
  double near_;
  std::vector<Projected> faces_[kHemicubeFaces];
  // Scratch
  std::vector<double> acc_;
  std::vector<int> touched_;
  std::vector<double> zbuf_;
  std::vector<int> item_;
};

}  // namespace gcsim::radiosity
