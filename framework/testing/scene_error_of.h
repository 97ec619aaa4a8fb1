// Not needed for the assignment.
// The message a scene text is refused with, for tests of the loader's errors.
#pragma once

#include <string>

#include <gtest/gtest.h>

#include "framework/scene/collada_loader.h"
#include "framework/scene/scene_error.h"

namespace pt {

/// Loads `xml` as the file `name` and returns its error message; fails the calling test if the
/// text loads, or if the error names another file.
inline std::string error_of(const std::string& xml, const std::string& name) {
  try {
    load_collada_string(xml, name, [](const std::string&) {});
  } catch (const SceneError& e) {
    EXPECT_EQ(e.file(), name);
    return e.what();
  }
  ADD_FAILURE() << "loaded without an error";
  return "";
}

}  // namespace pt
