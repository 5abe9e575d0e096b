#pragma once
// Hemicube form factors from a shooting patch to every element (thesis section 3.4.2, fig. 3.8).
// The hemicube sits on the patch centre. Every element is transformed into the hemicube's frame once,
// clipped against each face's frustum and projected; then each cell of the fixed partition (see
// delta_form_factors.hpp) is Z-buffered on its own. A pixel's answer never depends on which other
// cells are computed, so any distribution of cells over nodes gives the same per-cell sums, and
// adding the cells in their fixed order gives bit-identical form factors on any node count.
//
// A shooter near its receivers shoots from several points of its area (shooter_samples.hpp): each
// cell then Z-buffers every sample's hemicube in turn, weighted by the sample's share of the
// area, so the cells and their fixed order (and the bit-identity across node counts) stay.
//
// With hierarchical_levels L > 0 (thesis section 4.5) the cells are sampled at resolution R / 2^L;
// a coarse pixel whose corners and centre do not all see the same element (an element border) is
// split into four, recursively, down to resolution R.
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "apps/radiosity/delta_form_factors.hpp"
#include "apps/radiosity/op_counts.hpp"
#include "apps/radiosity/scene.hpp"
#include "apps/radiosity/shooter_samples.hpp"

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
  // Near field (shooter_samples.hpp): a shooter larger than near_field_ratio x the distance to its
  // nearest receiver shoots from up to max_shooter_samples^2 points, each hemicube of resolution
  // / samples-per-side so that the pixel work stays that of one hemicube (the projection work
  // grows n^2). 1: the thesis's one hemicube at the centre. Default 2 (README.md: the furnace box
  // to 2%; 1-node CORNELL 297 s instead of 284 s, thesis 289 s).
  int max_shooter_samples = 2;
  double near_field_ratio = 1.0;
};

// Bytes of a hemicube's buffers at options.resolution: a Z value and an item for each of the
// 3 r^2 pixels of the top face and four half faces (12 bytes a pixel).
inline std::int64_t hemicube_buffer_bytes(const HemicubeOptions& o) {
  return std::int64_t(o.resolution) * o.resolution * 3 * 12;
}

// Host bytes of a renderer's tables: delta form factors and their summed-area tables (3 r^2
// doubles each) for every sample grid (the smaller grids add at most a third).
inline std::int64_t hemicube_host_bytes(const HemicubeOptions& o) {
  return std::int64_t(o.resolution) * o.resolution * 3 * 8 * 2 * 4 / 3;
}

// One element clipped and projected onto one hemicube face.
struct ProjectedElement {
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
using HemicubeFaces = std::array<std::vector<ProjectedElement>, kHemicubeFaces>;

// Every element projected for one shooter: what project() computes and cell_form_factors()
// reads. It depends on the shooter alone, so the replicas of one simulation may share it
// (projection_cache.hpp) instead of each computing the same on the host.
struct HemicubeProjection {
  int shooter = -1;
  int samples_per_side = 1;
  std::vector<ShooterSample> samples;
  std::vector<HemicubeFaces> faces;  // per sample
  OpCounts cost;                     // what projecting counted (charged again by every user)
};

// Throws std::invalid_argument with the reason when `o` cannot make a hemicube (resolution,
// partition, hierarchical levels, near-field settings), without allocating its pixel tables: a
// command checks its options before the run, even at resolution 4096 (1 GB of tables).
void check_hemicube_options(const HemicubeOptions& o);

class HemicubeRenderer {
 public:
  // memo: where replicas of one run share the samples-per-side table (null: compute it here).
  HemicubeRenderer(const Scene& scene, const HemicubeOptions& options, SamplesPerSideMemo* memo = nullptr);

  int cell_count() const { return int(grids_[0].cells.size()); }
  // Samples per side the shooter `patch` shoots from (1: its centre).
  int samples_per_side(int patch) const { return (*per_side_)[patch]; }
  const HemicubeOptions& options() const { return options_; }

  // Transforms, clips and projects every element for the hemicube on patch `shooter`.
  void project(int shooter, OpCounts& ops);
  // Takes a projection another renderer of the same scene and options made, and counts its cost
  // in `ops` as if this renderer had projected (the simulated time is the same).
  void use_projection(std::shared_ptr<const HemicubeProjection> projection, OpCounts& ops);
  // The current projection (after project or use_projection).
  const std::shared_ptr<const HemicubeProjection>& projection() const { return current_; }
  // Z-buffers one cell of the current projection.
  CellFormFactors cell_form_factors(int cell, OpCounts& ops);

  // The whole row F(shooter -> element) for every element: all cells, added in cell order.
  std::vector<double> form_factor_row(int shooter, OpCounts& ops);

 private:
  // The pixels of one hemicube resolution: every samples-per-side n has its own (resolution / n).
  struct Grid {
    int resolution;
    std::shared_ptr<const DeltaFormFactors> dff;  // shared_delta_form_factors
    std::vector<HemicubeCell> cells;  // in fine pixels
  };
  using Faces = HemicubeFaces;
  using Projected = ProjectedElement;
  void project_from(const Vec3& origin, Faces& faces, OpCounts& ops);
  // The ray through (px, py) on `face`, in face coordinates (z = 1), and where it meets `poly`'s
  // plane (infinity behind or parallel).
  Vec3 pixel_ray(int face, double px, double py) const;
  static double depth(const Projected& poly, const Vec3& ray);
  void fixed_cell(const Faces& faces, const HemicubeCell& c, double weight, OpCounts& ops);
  void gather_cell(const HemicubeCell& c, double weight);
  void hierarchical_cell(const Faces& faces, const HemicubeCell& c, double weight, OpCounts& ops);
  int sample(const Faces& faces, int face, const std::vector<int>& candidates, double px, double py, OpCounts& ops) const;
  void subdivide(const Faces& faces, int face, const std::vector<int>& candidates, int i0, int j0, int size,
                 double weight, OpCounts& ops);
  void add(int element, double form_factor);

  const Scene& scene_;
  HemicubeOptions options_;
  std::vector<Grid> grids_;     // [k]: 2^k samples per side
  std::shared_ptr<const std::vector<int>> per_side_;  // per patch
  const Grid* grid_ = nullptr;  // the current shooter's
  int shooter_ = -1;
  double near_;
  std::shared_ptr<HemicubeProjection> own_;              // reused unless someone still shares it
  std::shared_ptr<const HemicubeProjection> current_;    // own_ or another renderer's
  // Scratch
  std::vector<double> acc_;
  std::vector<int> touched_;
  std::vector<double> zbuf_;
  std::vector<int> item_;
  std::vector<double> column_x_, row_y_;  // fixed_cell's rays through the cell's pixel centres
};

}  // namespace gcsim::radiosity
