// Part 2 (stress): the BVH gives brute force's answers on 100,000 random rays over each of the
// course's two bunnies (about 30,000 triangles each), where brute force takes tens of seconds.
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parts/2-bvh/tests/bvh_check.h"

namespace pt {
namespace {

using test::Case;
using test::case_name;
using test::kRays;

class Part2BvhBigCourseScene : public testing::TestWithParam<Case> {};

TEST_P(Part2BvhBigCourseScene, MatchesBruteForce) {
  Scene scene;
  std::string why;
  if (!test::try_load(std::string(PT_SHARED_SCENES_DIR) + "/" + GetParam().path, &scene, &why))
    GTEST_SKIP() << why << " (the course's scenes live beside the project, in ../shared)";
  test::check_against_brute_force(scene, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Scenes, Part2BvhBigCourseScene,
                         testing::Values(Case{"sky/CBbunny.dae", BvhSplitMethod::sah, 4, kRays},
                                         Case{"sky/bunny.dae", BvhSplitMethod::median, 4, kRays}),
                         case_name);

}  // namespace
}  // namespace pt
