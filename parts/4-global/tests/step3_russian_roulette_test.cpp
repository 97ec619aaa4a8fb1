// Part 4, step 3 (russian_roulette): paths ended at random stay unbiased, and they end. The
// roulette is part of at_least_one_bounce_radiance, whose bounces are step 2's, so each check
// compares the student's own estimate with roulette against the same estimate without it (a
// bug of step 2 is in both and cancels), called at the hit the rig finds (not through step 1's
// estimate_global_illumination).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "framework/testing/draws_from_rng_only.h"
#include "parts/4-global/tests/path_scenes.h"

namespace pt {
namespace {

// With and without roulette, the same depth limit: the same mean. Depth 8 is deep enough that
// the roulette (from the second bounce on) ends most paths before the limit.
void expect_roulette_keeps_the_mean(const Scene& scene, bool hemisphere, uint64_t seed,
                                    const std::string& what) {
  test::Rig rig(scene);
  rig.ctx.max_depth = 8;
  rig.ctx.hemisphere = hemisphere;
  rig.ctx.russian_roulette = false;
  const auto off = test::sample_values(test::bounced(rig.ctx), test::ray_from_inside, 20000, seed);
  rig.ctx.russian_roulette = true;
  const auto on =
      test::sample_values(test::bounced(rig.ctx), test::ray_from_inside, 20000, seed + 1);
  double off_sum = 0;
  for (double x : off) off_sum += x;
  ASSERT_GT(off_sum, 0.0) << what << ": this check rests on step 2 (bounces): without roulette "
                          << "at_least_one_bounce_radiance brought no light back";
  const test::SameMean c = test::same_mean(on, off);
  EXPECT_TRUE(c.pass) << what << ", with roulette against without: " << c.text
                      << (c.x < c.y ? ": darker with roulette: a path that goes on with "
                                      "probability q must have what it brings back divided by q?"
                                    : ": brighter with roulette: divided by the chance to stop "
                                      "(1 - q) instead of the chance to go on (q), by q more than "
                                      "once, or where the path ended?");
}

TEST(russian_roulette, keeps_the_mean_in_a_glowing_enclosure) {
  expect_roulette_keeps_the_mean(test::enclosure(0.5f, 1.0f), false, 3, "enclosure, light sampling");
  expect_roulette_keeps_the_mean(test::enclosure(0.5f, 1.0f), true, 5, "enclosure, hemisphere sampling");
}

// Where going on and stopping are not equally likely: with albedo 0.5 the probability q of going
// on equals 1 - q, so dividing by the wrong one passes; at 0.8 and 0.3 it is off by a factor of
// 4 or more.
TEST(russian_roulette, keeps_the_mean_where_going_on_and_stopping_differ) {
  expect_roulette_keeps_the_mean(test::enclosure(0.8f, 1.0f), false, 21, "enclosure of albedo 0.8");
  expect_roulette_keeps_the_mean(test::enclosure(0.3f, 1.0f), true, 23, "enclosure of albedo 0.3");
}

// A point light of intensity π at the centre of a unit sphere of albedo 0.5, seen from inside.
TEST(russian_roulette, keeps_the_mean_of_a_point_light_inside_a_diffuse_sphere) {
  Scene s;
  uint32_t m = test::add_material(s, glm::vec3(0.5f));
  s.spheres.push_back(Sphere{glm::vec3(0.0f), 1.0f, m});
  Light l;
  l.kind = LightKind::point;
  l.radiance = glm::vec3(float(M_PI));
  s.lights.push_back(l);
  expect_roulette_keeps_the_mean(s, false, 8, "point light in a sphere");
}

// The bounce rays `paths` paths take in a closed box of albedo `albedo` with no light (so no
// shadow rays), each from a ray from inside it (drawn from an Rng seeded with `seed`) and
// estimated at its hit with depth limit `max_depth`, roulette on or off: every nearest-hit query
// but the paths' own first rays.
long bounce_rays_in_dark_box(float albedo, int max_depth, bool roulette, int paths, uint64_t seed) {
  Scene s;
  uint32_t m = test::add_material(s, glm::vec3(albedo));
  test::add_closed_cube(s, m);
  test::Rig rig(s);
  rig.ctx.max_depth = max_depth;
  rig.ctx.russian_roulette = roulette;
  Rng rng(seed);
  for (int i = 0; i < paths; ++i) {
    Ray r = test::ray_from_inside(rng);
    test::bounced_at_hit(rig.ctx, r, rng);
  }
  return rig.query.intersect_calls - paths;
}

// A closed box of albedo 0.5 (dark: no light, so no shadow rays) with no depth limit worth the
// name (1000): every path must still end by roulette, long before the limit (about two bounce
// rays with q the throughput, 0.5 here; a hundred with a fixed q of 0.99), and the first bounce
// is always taken (roulette from the first bounce on would give about one ray per path, not two;
// the standard error over 500 paths is about 0.06).
TEST(russian_roulette, ends_every_path) {
  const int n = 500;
  const double rays = double(bounce_rays_in_dark_box(0.5f, 1000, true, n, 9)) / n;
  EXPECT_GT(rays, 1.5) << "bounce rays per path: " << rays
                       << " (the first bounce is always taken, roulette plays from the second "
                          "on: about two on average here; about one means roulette on the first "
                          "bounce as well)";
  EXPECT_LT(rays, 500.0) << "bounce rays per path: " << rays
                         << " at depth limit 1000: paths do not end by roulette (is q ever below "
                            "1, and is the path stopped when the coin says so?)";
}

// Roulette plays from the second bounce on, whatever q is: in a closed dark box at depth limit 2,
// with roulette on, every path takes its first bounce, so exactly one bounce ray a path (a fixed
// q below 1 played at the first vertex takes about q of them; the average of ends_every_path
// cannot tell a q of 0.7 there, which still gives more than 1.5 rays a path).
TEST(russian_roulette, takes_every_first_bounce) {
  const int n = 400;
  const long rays = bounce_rays_in_dark_box(0.5f, 2, true, n, 31);
  EXPECT_EQ(rays, n) << n << " paths at depth limit 2 with roulette on traced " << rays
                     << " bounce rays; the first bounce is always taken (roulette plays from "
                        "depth 2 on), so each path traces exactly one: fewer means roulette "
                        "played at the first bounce";
}

// With roulette off (--no-rr, ctx.russian_roulette false) no path ends at random: in a closed
// dark box every path takes a bounce ray at each vertex up to the depth limit, exactly
// max_depth - 1 of them beyond the camera ray's.
TEST(russian_roulette, none_when_it_is_off) {
  const int n = 200;
  const double rays = double(bounce_rays_in_dark_box(0.3f, 6, false, n, 12)) / n;
  EXPECT_EQ(rays, 5.0) << "bounce rays per path with roulette off at depth limit 6, albedo 0.3: "
                       << rays << " (every path goes on to the limit: 5; fewer means paths "
                       << "ended at random although ctx.russian_roulette is false)";
}

// The roulette's coin comes from rng too: with roulette on, where a path ends decides the answer,
// so a coin of another generator gives two answers for the same numbers.
TEST(russian_roulette, draws_its_coin_from_rng_only) {
  test::Rig rig(test::enclosure(0.5f, 1.0f));
  rig.ctx.max_depth = 8;
  rig.ctx.russian_roulette = true;
  Rng g(9);
  const Ray r = test::ray_from_inside(g);
  test::expect_draws_from_rng_only("at_least_one_bounce_radiance with roulette", [&](Rng& rng) {
    return test::bounced_at_hit(rig.ctx, r, rng);
  }, 16);
}

}  // namespace
}  // namespace pt
