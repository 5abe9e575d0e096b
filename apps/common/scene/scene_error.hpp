#pragma once
// The one error every scene loader throws (each format's own type derives from it): a mistake in a
// scene's file, with the file, the line (0: none, e.g. a missing file) and what was expected, so
// the gcsim command catches one type for all of them (apps/cli/errors.cpp).
#include <stdexcept>
#include <string>

namespace gcsim::scene {

class SceneError : public std::runtime_error {
 public:
  // what() reads "FILE:LINE: MESSAGE", or "FILE: MESSAGE" when line is 0.
  SceneError(std::string file, int line, std::string message);
  std::string file;
  int line;
  std::string message;

 protected:
  // For a format whose what() is worded otherwise (the WORLD reader always prints the line).
  SceneError(std::string file, int line, std::string message, const std::string& what);
};

}  // namespace gcsim::scene
