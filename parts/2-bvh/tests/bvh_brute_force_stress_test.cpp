// Part 2 (stress): the BVH gives brute force's answers on 100,000 random rays over each of the
// course's two bunnies (about 30,000 triangles each), where brute force takes tens of seconds.
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "2-bvh/tests/bvh_check.h"

namespace pt {
namespace {

constexpr size_t kRays = 100000;

/// A scene, a split method and a leaf size to check.
struct Case {
  std::string path;  ///< relative to the project's scenes/ or the course's scene folder
  BvhSplitMethod split;
  int leaf;
  size_t rays;
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.path << (c.split == BvhSplitMethod::sah ? " sah" : " median") << " leaf " << c.leaf;
}

std::string case_name(const testing::TestParamInfo<Case>& info) {
  std::string name = info.param.path;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name + (info.param.split == BvhSplitMethod::sah ? "_sah" : "_median") + "_leaf" +
         std::to_string(info.param.leaf);
}

void check(const Scene& scene, const Case& c) {
  BvhOptions options;
  options.split = c.split;
  options.max_leaf_size = c.leaf;
  const Bvh bvh(scene, options);
  const std::vector<Ray> rays = test::random_rays(scene, c.rays, 2024);
  const test::Comparison r = test::compare_with_brute_force(scene, bvh, rays);
  // The rays must exercise both answers, or agreement would say little.
  EXPECT_GT(r.hits, r.rays / 10) << "too few hits to be a test";
  EXPECT_LT(r.hits, r.rays) << "no misses at all";
  EXPECT_EQ(r.nearest_differ, 0u) << r.examples;
  EXPECT_EQ(r.occluded_differ, 0u) << r.examples;
  EXPECT_EQ(r.anyhit_vs_nearest, 0u) << r.examples;
  EXPECT_EQ(r.part1_not_ulp_tie, 0u) << r.examples;
  if (r.part1_differ > 0)
    std::printf("note: Part 1's BruteForce kept an ulp-farther tie on %zu of %zu rays\n",
                r.part1_differ, r.rays);
}

class Part2BvhBigCourseScene : public testing::TestWithParam<Case> {};

TEST_P(Part2BvhBigCourseScene, MatchesBruteForce) {
  Scene scene;
  std::string why;
  if (!test::try_load(std::string(PT_SHARED_SCENES_DIR) + "/" + GetParam().path, &scene, &why))
    GTEST_SKIP() << why << " (the course's scenes live beside the project, in ../shared)";
  check(scene, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Scenes, Part2BvhBigCourseScene,
                         testing::Values(Case{"sky/CBbunny.dae", BvhSplitMethod::sah, 4, kRays},
                                         Case{"sky/bunny.dae", BvhSplitMethod::median, 4, kRays}),
                         case_name);

}  // namespace
}  // namespace pt
