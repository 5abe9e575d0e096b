// gcsim scene info: a scene's counts (the columns of thesis table 4.1), bounds, lights and camera,
// and its export as WORLD and ENTITY files.
#include <filesystem>
#include <fstream>
#include <memory>

#include <fmt/format.h>

#include "apps/radiosity/app/commands.hpp"
#include "apps/radiosity/builtin_scenes.hpp"
#include "apps/common/scene/world_loader.hpp"

namespace gcsim::radiosity::app {

namespace {

struct SceneInfoFlags {
  std::string scene;
  std::string export_dir;
};

void print_counts(const Scene& scene, const std::string& asked) {
  const auto c = scene.counts();
  auto t = thesis_counts(asked);
  if (t.instances == 0) t = thesis_counts(scene.name);  // an exported built-in scene keeps its name
  fmt::print("scene {} ({})\n", scene.name, asked);
  fmt::print("{:<10} {:>9} {:>9} {:>8} {:>9} {:>9}\n", "", "instances", "surfaces", "patches", "elements", "vertices");
  fmt::print("{:<10} {:>9} {:>9} {:>8} {:>9} {:>9}\n", "this", c.instances, c.surfaces, c.patches, c.elements, c.vertices);
  if (t.instances > 0)
    fmt::print("{:<10} {:>9} {:>9} {:>8} {:>9} {:>9}   {}\n", "thesis", t.instances, t.surfaces, t.patches, t.elements,
               t.vertices, t == c ? "(equal)" : "(DIFFERENT)");
}

void print_geometry(const Scene& scene) {
  Vec3 lo = scene.vertices.at(0), hi = lo;
  for (const auto& v : scene.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
  fmt::print("bounds    ({:g}, {:g}, {:g}) .. ({:g}, {:g}, {:g})\n", lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
  double emitted = 0;
  int lights = 0;
  for (const auto& p : scene.patches)
    if (channel_sum(scene.surfaces[p.surface].exitance) > 0) {
      ++lights;
      emitted += channel_sum(scene.surfaces[p.surface].exitance) * p.area;
    }
  fmt::print("lights    {} emitting patches, emitted energy (r+g+b) {:g}\n", lights, emitted);
  if (scene.camera)
    fmt::print("camera    eye ({:g}, {:g}, {:g}) target ({:g}, {:g}, {:g}) fov {:g}\n", scene.camera->eye.x, scene.camera->eye.y,
               scene.camera->eye.z, scene.camera->look_at.x, scene.camera->look_at.y, scene.camera->look_at.z,
               scene.camera->fov_y_degrees);
}

void export_world(const World& world, const SceneInfoFlags& f) {
  std::filesystem::create_directories(f.export_dir);
  std::vector<std::string> names;
  for (std::size_t i = 0; i < world.entities.size(); ++i) {
    std::string name = fmt::format("entity{}.ent", i);
    std::ofstream(std::filesystem::path(f.export_dir) / name) << format_entity(world.entities[i]);
    names.push_back(name);
  }
  const std::string wname = fmt::format("{}.wld", f.scene.find('/') == std::string::npos ? f.scene : "scene");
  std::ofstream(std::filesystem::path(f.export_dir) / wname) << format_world(world, names);
  fmt::print("exported  {}/{}\n", f.export_dir, wname);
}

}  // namespace

void add_scene_info_command(pipeline::CommandGroups& g) {
  auto f = std::make_shared<SceneInfoFlags>();
  CLI::App* cmd = g.scene->add_subcommand(
      "info",
      "Print a scene's counts of instances, surfaces, patches, elements and vertices (the columns of the\n"
      "thesis's table 4.1), next to the thesis's figures for the built-in scenes.");
  cmd->add_option("scene", f->scene, "room, picroom, cornell or the path of a TOML scene file or a WORLD file")->required();
  cmd->add_option("--export", f->export_dir, "Also write the scene as WORLD and ENTITY files into this directory");
  cmd->callback([f] {
    const World world = load_scene_world(f->scene);
    const Scene scene = flatten(world);
    print_counts(scene, f->scene);
    print_geometry(scene);
    if (!f->export_dir.empty()) export_world(world, *f);
  });
}

}  // namespace gcsim::radiosity::app
