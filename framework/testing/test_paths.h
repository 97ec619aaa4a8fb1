// Not needed for the assignment.
// Where a test finds the project's sources, the course's shared scenes and ray sets, and its own
// build tree. The paths are compiled into one object per build tree (test_paths.cpp), not into
// every test: a second tree of the same sources (the handout's round trip, the bundle, a mutant's
// copy) then compiles its tests to the same objects, which the compiler cache hands back.
#pragma once

namespace pt::test {

/// The project folder (the one holding parts/, framework/, reference/).
const char* source_dir();
/// The course's COLLADA scenes, beside the project (`../shared/scenes/cs184`); may not exist.
const char* shared_scenes_dir();
/// The shared ray sets for traversal comparisons (`../shared/rays`); may not exist.
const char* shared_rays_dir();
/// The build tree the test was built in.
const char* binary_dir();

}  // namespace pt::test
