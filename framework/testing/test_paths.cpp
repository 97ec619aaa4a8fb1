// Not needed for the assignment.
// The build tree's paths, given by CMake to this one file (cmake/PtTesting.cmake).
#include "framework/testing/test_paths.h"

namespace pt::test {

const char* source_dir() { return PT_TEST_SOURCE_DIR; }
const char* shared_scenes_dir() { return PT_TEST_SOURCE_DIR "/../shared/scenes/cs184"; }
const char* shared_rays_dir() { return PT_TEST_SOURCE_DIR "/../shared/rays"; }
const char* binary_dir() { return PT_TEST_BINARY_DIR; }

}  // namespace pt::test
