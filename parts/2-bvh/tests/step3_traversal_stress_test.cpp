// Part 2, step 3 (traversal), the long checks (the instructor's CI, not a grade): the BVH gives
// brute force's answers on 100,000 random rays over the meshes where brute force takes tens of
// seconds: the course's two bunnies (about 30,000 triangles each), the teapot, the banana and the
// gems, and the project's coil with three tree shapes. The graded step keeps the small scenes.
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "framework/testing/test_paths.h"
#include "parts/2-bvh/tests/bvh_check.h"

namespace pt {
namespace {

using test::Case;
using test::case_name;
using test::kRays;

class traversal : public testing::TestWithParam<Case> {};

TEST_P(traversal, big_course_scene_matches_brute_force) {
  Scene scene;
  std::string why;
  if (!test::try_load(std::string(pt::test::shared_scenes_dir()) + "/" + GetParam().path, &scene, &why))
    GTEST_SKIP() << why << " (the course's scenes live beside the project, in ../shared)";
  test::check_against_brute_force(scene, GetParam());
}

INSTANTIATE_TEST_SUITE_P(, traversal,
                         testing::Values(Case{"sky/CBbunny.dae", BvhSplitMethod::sah, 4, kRays},
                                         Case{"sky/bunny.dae", BvhSplitMethod::median, 4, kRays},
                                         Case{"sky/CBgems.dae", BvhSplitMethod::sah, 4, kRays},
                                         Case{"meshedit/teapot.dae", BvhSplitMethod::sah, 4, kRays},
                                         Case{"keenan/banana.dae", BvhSplitMethod::median, 2, kRays}),
                         case_name);

TEST(traversal_project, coil_matches_brute_force_with_three_tree_shapes) {
  Scene scene;
  std::string why;
  if (!test::try_load(std::string(pt::test::source_dir()) + "/scenes/cornell_coil.dae", &scene, &why))
    GTEST_SKIP() << why;
  for (const Case& c : {Case{"cornell_coil.dae", BvhSplitMethod::sah, 4, kRays},
                        Case{"cornell_coil.dae", BvhSplitMethod::median, 1, kRays},
                        Case{"cornell_coil.dae", BvhSplitMethod::sah, 16, kRays}})
    test::check_against_brute_force(scene, c);
}

}  // namespace
}  // namespace pt
