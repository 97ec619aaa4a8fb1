// Not needed for the assignment.
// The error a scene loader throws: which file, which element, what is wrong.
#pragma once

#include <stdexcept>
#include <string>

namespace pt {

/// A scene that cannot be loaded. what() reads "FILE: <element ...>: what is wrong", so the
/// person who wrote the file can find the line to fix.
class SceneError : public std::runtime_error {
 public:
  SceneError(const std::string& file, const std::string& element, const std::string& message)
      : std::runtime_error(file + ": " + (element.empty() ? "" : element + ": ") + message),
        file_(file),
        element_(element) {}
  const std::string& file() const { return file_; }
  const std::string& element() const { return element_; }

 private:
  std::string file_, element_;
};

}  // namespace pt
