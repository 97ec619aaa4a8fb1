// Part 3, step 5 (one_bounce): the two direct estimators, chosen by the settings, estimate the
// same integral.
#include <gtest/gtest.h>

#include "framework/image/render_estimate.h"
#include "framework/render/pixel_stats.h"
#include "framework/stats/block_ttest.h"
#include "parts/3-direct/tests/direct_scenes.h"

namespace pt {
namespace {

// A small Cornell-like box lit by its emissive ceiling, rendered at 16×16 by a pinhole.
Scene lit_box() {
  Scene s;
  uint32_t white = test::add_material(s, glm::vec3(0.7f));
  uint32_t red = test::add_material(s, glm::vec3(0.7f, 0.1f, 0.1f));
  uint32_t lamp = test::add_material(s, glm::vec3(0.0f), glm::vec3(3.0f));
  test::add_quad(s, {-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}, white);  // floor
  test::add_quad(s, {-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}, {1, -1, -1}, white);  // back
  test::add_quad(s, {-1, -1, -1}, {-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}, red);    // left
  test::add_quad(s, {-0.9f, 0.99f, -0.9f}, {0.9f, 0.99f, -0.9f}, {0.9f, 0.99f, 0.9f},
                 {-0.9f, 0.99f, 0.9f}, lamp);
  test::add_triangle(s, {-0.3f, -1, 0.2f}, {0.5f, -1, -0.3f}, {0.1f, 0.2f, 0.0f}, white);
  return s;
}

RenderEstimate render_box(const Scene& scene, bool hemisphere, int spp, float scale,
                          uint64_t seed) {
  test::Rig rig(scene);
  rig.ctx.hemisphere = hemisphere;
  rig.ctx.light_samples = 4;
  const int W = 16, H = 16;
  RenderEstimate e;
  e.width = W;
  e.height = H;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      Rng rng(seed, uint64_t(y * W + x));
      PixelStats st;
      for (int i = 0; i < spp; ++i) {
        glm::vec2 j = rng.next_2d();
        Ray r;
        r.o = glm::vec3(0.0f, 0.0f, 3.5f);
        r.d = glm::normalize(glm::vec3((x + j.x) / W - 0.5f, 0.5f - (y + j.y) / H, -1.2f));
        st.add(scale * test::direct_only(rig.ctx, r, rng));
      }
      e.mean.push_back(glm::vec3(st.mean));
      e.variance.push_back(glm::vec3(st.variance()));
      e.count.push_back(float(st.count));
    }
  return e;
}

// The two direct estimators estimate the same integral: the block t-test (family-wise 0.01)
// finds no difference, and does find a 5% bias.
TEST(one_bounce, hemisphere_and_importance_sampling_converge_to_the_same_image) {
  Scene s = lit_box();
  RenderEstimate importance = render_box(s, false, 256, 1.0f, 1);
  RenderEstimate hemisphere = render_box(s, true, 2048, 1.0f, 2);
  BlockTestOptions opt;
  opt.block_size = 4;
  opt.alpha = 0.01;
  BlockTestResult same = block_t_test(importance, hemisphere, opt);
  EXPECT_TRUE(same.pass) << same.summary;
  RenderEstimate biased = render_box(s, false, 256, 0.95f, 3);
  BlockTestResult differ = block_t_test(biased, hemisphere, opt);
  EXPECT_FALSE(differ.pass) << "a 5% darker image was not detected: " << differ.summary;
}

}  // namespace
}  // namespace pt
