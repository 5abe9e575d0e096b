#pragma once
// Radiosity's public header: the one a composite (apps/render, apps/calibration) includes. What it
// gives them, and nothing else of the library:
//   the scene            Scene (the thesis's World gridded into patches and elements), built-in scenes
//   the program          ParallelRadiosity and its options (cell assignment, form-factor exchange
//                        and merge), the progressive solver and what it reports, and the media hook
//                        (PathTransmittance) a renderer with participating media supplies
//   the display          element corners and the Gouraud renderer, for the unified renderer's view
//   the thesis figures   tables 4.1 to 4.8, which calibration fits and predicts, and the
//                        thesis's program (program_preset, thesis_workload) it runs
// tests/structure/app_doors.py fails when a composite includes any other header of this app.
#include "apps/radiosity/builtin_scenes.hpp"
#include "apps/radiosity/cell_assignment.hpp"
#include "apps/radiosity/element_corners.hpp"
#include "apps/radiosity/form_factor_exchange.hpp"
#include "apps/radiosity/form_factor_merge.hpp"
#include "apps/radiosity/gouraud_renderer.hpp"
#include "apps/radiosity/parallel_radiosity.hpp"
#include "apps/radiosity/path_transmittance.hpp"
#include "apps/radiosity/program_preset.hpp"
#include "apps/radiosity/progressive_solver.hpp"
#include "apps/radiosity/scene.hpp"
#include "apps/radiosity/thesis_tables.hpp"
#include "apps/radiosity/thesis_workload.hpp"
