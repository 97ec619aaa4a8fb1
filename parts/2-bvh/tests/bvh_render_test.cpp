// Part 2: images rendered through the BVH are those rendered by brute force, pixel for pixel;
// and on the course's CBbunny ray sets, the BVH gives Intel Embree's answers.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parts/1-raygen/pixel_loop.h"
#include "parts/2-bvh/tests/bvh_check.h"
#include "parts/2-bvh/tests/bvh_test_inputs.h"
#include "framework/rays/ray_set.h"

namespace pt {
namespace {

class Part2BvhRender : public testing::TestWithParam<std::string> {};

TEST_P(Part2BvhRender, ImageEqualsBruteForcePixelForPixel) {
  Scene scene;
  std::string why;
  if (!test::try_load(std::string(PT_SOURCE_DIR) + "/scenes/" + GetParam(), &scene, &why))
    GTEST_SKIP() << why;
  const BruteForce bf(scene);
  const Bvh sah(scene), median(scene, BvhOptions{BvhSplitMethod::median, 1, 16, {}});
  const std::vector<glm::dvec3> want = test::render_normals(scene, bf, 48, 36, 4, 42);
  int lit = 0;
  for (const glm::dvec3& p : want) lit += p != glm::dvec3(0.0);
  EXPECT_GT(lit, 48 * 36 / 4) << "the camera should see the scene";
  for (const Bvh* bvh : {&sah, &median}) {
    const std::vector<glm::dvec3> got = test::render_normals(scene, *bvh, 48, 36, 4, 42);
    int differ = 0;
    for (size_t i = 0; i < want.size(); ++i) differ += got[i] != want[i];
    EXPECT_EQ(differ, 0) << (bvh == &sah ? "sah" : "median");
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, Part2BvhRender,
                         testing::Values("cornell_spheres.dae", "cornell_coil.dae"),
                         [](const testing::TestParamInfo<std::string>& info) {
                           return info.param.substr(0, info.param.find('.'));
                         });

TEST(Part2BvhSharedRays, CBbunnyAgreesWithEmbree) {
  Scene scene;
  std::string why;
  if (!test::try_load(std::string(PT_SHARED_SCENES_DIR) + "/sky/CBbunny.dae", &scene, &why))
    GTEST_SKIP() << why << " (the course's scenes live beside the project, in ../shared)";
  const std::string prefix = std::string(PT_SHARED_RAYS_DIR) + "/CBbunny.";
  if (!test::file_exists(prefix + "diffuse.rays"))
    GTEST_SKIP() << prefix << "*.rays are not there (the shared ray sets, ../shared/rays)";
  scene.spheres.clear();  // the sets count triangles only
  const Bvh bvh(scene);
  for (const char* set : {"primary", "diffuse", "shadow"}) {
    const bool occlusion = std::string(set) == "shadow";
    const std::vector<Ray> rays = read_ray_set(prefix + set + ".rays");
    const std::vector<float> answers = read_hit_set(prefix + set + ".hits");
    ASSERT_EQ(rays.size(), answers.size());
    std::atomic<size_t> differ{0}, hits{0};
    tbb::parallel_for(size_t(0), rays.size(), [&](size_t i) {
      float t;
      if (occlusion) {
        t = bvh.occluded(rays[i]) ? 1.0f : 0.0f;
      } else {
        SurfaceHit hit;
        t = bvh.intersect(rays[i], &hit) ? hit.t : INFINITY;
      }
      const float a = answers[i];
      hits += occlusion ? a == 1.0f : std::isfinite(a);
      // Two intersectors round differently: the same surface is within a part in 10^4.
      const bool same = (occlusion || std::isinf(a) || std::isinf(t))
                            ? a == t
                            : std::abs(a - t) <= 1e-4f * std::max(std::abs(a), std::abs(t));
      differ += !same;
    });
    // "All but a vanishing fraction" (ties and grazing hits): at most one ray in 10,000.
    EXPECT_LE(differ.load(), rays.size() / 10000) << set;
    EXPECT_GT(hits.load(), rays.size() / 10) << set << ": too few hits to be a test";
    std::printf("%s: %zu rays, %zu disagree with Embree\n", set, rays.size(), differ.load());
  }
}

}  // namespace
}  // namespace pt
