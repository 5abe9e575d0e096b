#include "apps/common/scene/scene_error.hpp"

#include <utility>

namespace gcsim::scene {

namespace {

std::string located(const std::string& file, int line, const std::string& message) {
  return line > 0 ? file + ":" + std::to_string(line) + ": " + message : file + ": " + message;
}

}  // namespace

SceneError::SceneError(std::string f, int l, std::string m)
    : std::runtime_error(located(f, l, m)), file(std::move(f)), line(l), message(std::move(m)) {}

SceneError::SceneError(std::string f, int l, std::string m, const std::string& what)
    : std::runtime_error(what), file(std::move(f)), line(l), message(std::move(m)) {}

}  // namespace gcsim::scene
