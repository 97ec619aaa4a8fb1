// Part 4, step 1 (path): a camera ray's radiance, the emission it sees plus what its hit sends
// back after at least one bounce, and no more work than the depth asks for.
#include <gtest/gtest.h>

#include "parts/4-global/tests/path_scenes.h"

namespace pt {
namespace {

TEST(path, depth_one_samples_no_bounce) {
  test::Rig rig(test::enclosure(0.5f, 1.0f));
  rig.ctx.max_depth = 1;
  Rng rng(1);
  Ray r;
  estimate_global_illumination(rig.ctx, r, rng);
  EXPECT_EQ(rig.query.intersect_calls, 1) << "only the camera ray is traced";
  EXPECT_EQ(rig.query.occluded_calls, rig.ctx.light_samples) << "and the light's shadow rays";
}

}  // namespace
}  // namespace pt
