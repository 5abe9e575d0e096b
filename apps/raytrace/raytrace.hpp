#pragma once
// The ray tracer's public header: the one a composite (apps/render) includes. What it gives it, and
// nothing else of the library:
//   the scene            Scene (float spheres and triangles) and its lowering from the shared
//                        scene description
//   the program          ParallelRenderJob (tile distributions, the per-processor program), the
//                        sequential render, RenderSettings, and the host threads rendering ahead
//   the hooks            RayMedia (what media do to a ray) and the optics of mirrors and glass,
//                        for a renderer that adds participating media
// tests/structure/app_doors.py fails when a composite includes any other header of this app.
#include "apps/raytrace/lower_scene.hpp"
#include "apps/raytrace/optics.hpp"
#include "apps/raytrace/parallel_render.hpp"
#include "apps/raytrace/ray_media.hpp"
#include "apps/raytrace/render.hpp"
#include "apps/raytrace/render_settings.hpp"
#include "apps/raytrace/scene.hpp"
#include "apps/raytrace/tile_prefetch.hpp"
