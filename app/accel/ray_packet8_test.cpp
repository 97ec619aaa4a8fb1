// Packets of rays from one point: each box test of a packet gives each ray its own Box4Ray
// test's answer bit for bit, the packet's one test never rules out a box a ray enters, and the
// wide tree's walk of a packet answers each ray as occluded() does, on the course's scenes and
// on rays made to be awkward (zero, tiny and mixed-sign directions, rays that cannot be traced).
// SOLUTION-ONLY FILE: not in the student handout, since it is the instructor's build's speed.
#include "app/accel/ray_packet8.h"

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "app/accel/wide_bvh.h"
#include "framework/testing/test_paths.h"
#include "parts/2-bvh/tests/bvh_check.h"

namespace pt {
namespace {

/// Eight rays from `origin`: towards points of a small patch around `target` (a light's
/// samples), or, when `spread`, in directions of every sign; some lanes then made awkward.
std::vector<Ray> bundle(std::mt19937& rng, glm::vec3 origin, glm::vec3 target, bool spread,
                        bool awkward) {
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<Ray> rays(8);
  for (Ray& r : rays) {
    glm::vec3 to = spread ? origin + glm::vec3(u(rng), u(rng), u(rng))
                          : target + 0.1f * glm::vec3(u(rng), 0.0f, u(rng));
    glm::vec3 d = to - origin;
    const float len = glm::length(d);
    r.o = origin;
    r.d = len > 0.0f ? d / len : glm::vec3(0.0f, 1.0f, 0.0f);
    r.tmin = 0.0f;
    r.tmax = spread ? std::numeric_limits<float>::infinity() : len * 0.999f;
  }
  if (awkward) {
    const float inf = std::numeric_limits<float>::infinity();
    switch (std::uniform_int_distribution<int>(0, 5)(rng)) {
      case 0: rays[2].d.x = 0.0f; break;                 // runs inside a slab: 1/0
      case 1: rays[3].d.y = -0.0f; break;                // -0: the negative octant
      case 2: rays[1].d.z = 1e-40f; break;               // a reciprocal that overflows
      case 3: rays[0].d = glm::vec3(0.0f); break;        // cannot be traced
      case 4: rays[4].tmax = std::nanf(""); break;       // cannot be traced
      default: rays[5].o.x = std::nextafter(rays[5].o.x, inf); break;  // another origin
    }
  }
  return rays;
}

TEST(RayPacket8, BoxTestsAreEachRaysOwn) {
#if PT_ACCEL_PACKETS
  std::mt19937 rng(51);
  std::uniform_real_distribution<float> u(-2.0f, 2.0f);
  int entered = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    Box4 boxes[2];
    for (int k = 0; k < 8; ++k) {
      glm::vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
      if (trial % 7 == 0 && k == 5) a = glm::vec3(INFINITY), b = glm::vec3(-INFINITY);  // empty
      for (int axis = 0; axis < 3; ++axis) {
        boxes[k / 4].bounds[axis][k % 4] = std::fmin(a[axis], b[axis]);
        boxes[k / 4].bounds[3 + axis][k % 4] = std::fmax(a[axis], b[axis]);
      }
    }
    const glm::vec3 origin(u(rng), u(rng), u(rng));
    const std::vector<Ray> rays =
        bundle(rng, origin, glm::vec3(u(rng), 1.5f, u(rng)), trial % 3 == 0, trial % 5 == 0);
    const unsigned offered = 0xFFu & ~unsigned(trial % 4);  // sometimes not the first lanes
    const RayPacket8 packet(rays.data(), offered);
    const unsigned may = packet_may_enter8(boxes, packet);
    for (int j = 0; j < 8; ++j) {
      if (!(packet.lanes >> j & 1u)) continue;
      const Box4Ray single(rays[j]);
      float t_entry[8];
      const unsigned own = intersect_box8(boxes, single, rays[j].tmax, t_entry);
      entered += own != 0;
      ASSERT_EQ(own & ~may, 0u) << "trial " << trial << ": the packet's test ruled out a box ray "
                                << j << " enters";
      ASSERT_EQ(ray_enters8(boxes, j, packet), own) << "trial " << trial << ", ray " << j;
      for (int k = 0; k < 8; ++k)
        ASSERT_EQ(rays_entering(boxes, k, packet) >> j & 1u, own >> k & 1u)
            << "trial " << trial << ", ray " << j << ", box " << k;
    }
  }
  EXPECT_GT(entered, 1000) << "hardly a box entered: not a test";
#else
  GTEST_SKIP() << "no AVX2 in this build: no packets";
#endif
}

/// occluded_together answers the first ray offered always, only rays offered, and each as
/// occluded() does.
void expect_packets_agree(const Scene& scene) {
  const Bvh binary(scene, BvhOptions{});
  const WideBvh wide(scene, binary);
  std::mt19937 rng(7);
  const std::vector<Ray> probes = test::random_rays(scene, 4000, 51);
  const Bounds3 b = scene.bounds();
  const glm::vec3 light((b.lo.x + b.hi.x) / 2, b.hi.y - 0.01f * (b.hi.y - b.lo.y), (b.lo.z + b.hi.z) / 2);
  int packed = 0, blocked = 0, answered_in_all = 0;
  for (size_t i = 0; i < probes.size(); ++i) {
    SurfaceHit hit;
    if (!wide.intersect(probes[i], &hit)) continue;
    const glm::vec3 from = hit.p + 1e-4f * hit.ng;
    const std::vector<Ray> rays = bundle(rng, from, light, i % 4 == 0, i % 3 == 0);
    for (unsigned offered = 0xFFu; offered; offered &= offered - 1) {
      unsigned answered = 0;
      const unsigned occluded = wide.occluded_together(rays.data(), offered, &answered);
      const int first = __builtin_ctz(offered);
      ASSERT_TRUE(answered >> first & 1u) << "probe " << i;
      ASSERT_EQ(answered & ~offered, 0u) << "probe " << i;
      ASSERT_EQ(occluded & ~answered, 0u) << "probe " << i;
      packed += __builtin_popcount(answered) > 1;
      answered_in_all += __builtin_popcount(answered);
      for (unsigned l = answered; l; l &= l - 1) {
        const int j = __builtin_ctz(l);
        blocked += wide.occluded(rays[j]);
        ASSERT_EQ(occluded >> j & 1u, unsigned(wide.occluded(rays[j])))
            << "probe " << i << ", ray " << j << ", offered " << offered;
      }
    }
  }
#if PT_ACCEL_PACKETS
  EXPECT_GT(packed, 100) << "hardly a packet made: not a test";
#endif
  EXPECT_GT(blocked, 100) << "hardly a ray blocked: not a test";
  EXPECT_GT(answered_in_all, blocked) << "every ray blocked: not a test";
}

class RayPacket8CourseScene : public testing::TestWithParam<std::string> {};

TEST_P(RayPacket8CourseScene, WalkAnswersEachRayAsOccludedDoes) {
  Scene scene;
  std::string why;
  if (!test::try_load(std::string(pt::test::shared_scenes_dir()) + "/" + GetParam(), &scene, &why))
    GTEST_SKIP() << why << " (the course's scenes live beside the project, in ../shared)";
  expect_packets_agree(scene);
}

INSTANTIATE_TEST_SUITE_P(Scenes, RayPacket8CourseScene,
                         testing::Values("sky/CBspheres_lambertian.dae", "sky/CBbunny.dae",
                                         "sky/CBgems.dae", "sky/CBempty.dae"),
                         [](const testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param.substr(4);
                           return name.substr(0, name.find('.'));
                         });

}  // namespace
}  // namespace pt
