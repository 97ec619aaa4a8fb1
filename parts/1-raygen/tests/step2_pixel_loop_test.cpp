// Part 1, step 2 (pixel_loop): a pixel and a point in it to a camera ray; the pixel loop, where
// its rays go and what it adds up. Where a ray went is read through the student's own camera
// (step 1's generate_camera_ray), so only this step's mapping is graded here.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "parts/1-raygen/camera_ray.h"
#include "parts/1-raygen/pixel_loop.h"

namespace pt {
namespace {

/// Where a ray of the default camera (at the origin, looking down -z) meets the plane z = -1.
glm::vec2 on_plane(const Ray& r) { return {r.d.x / -r.d.z, r.d.y / -r.d.z}; }

/// The film point whose camera ray (by the student's own generate_camera_ray, step 1) has the
/// direction of `r`: Newton's method on the map from film to the plane z = -1, differences for
/// its derivative. The checks of this step use it instead of the camera's exact inverse, so that
/// a bug of step 1 (a shifted or scaled field of view) is on both sides and costs step 1 only.
glm::vec2 film_of(const Camera& cam, float aspect, const Ray& r) {
  const glm::vec2 target = on_plane(r);
  glm::vec2 f(0.5f);
  auto at = [&](glm::vec2 g) { return on_plane(generate_camera_ray(cam, aspect, g, {0.5f, 0.5f})); };
  for (int i = 0; i < 6; ++i) {
    const float h = 1e-3f;
    const glm::vec2 p = at(f), dx = (at(f + glm::vec2(h, 0)) - p) / h,
                    dy = (at(f + glm::vec2(0, h)) - p) / h;
    const float det = dx.x * dy.y - dx.y * dy.x;
    if (!(std::abs(det) > 0.0f)) break;
    const glm::vec2 e = target - p;
    f += glm::vec2(e.x * dy.y - e.y * dy.x, dx.x * e.y - dx.y * e.x) / det;
  }
  return f;
}

TEST(pixel_loop, camera_ray_through_pixel_maps_the_offset_to_the_film) {
  Camera cam;
  const PixelRef px{7, 2, 20, 10};  // column 7, row 2 from the top
  for (glm::vec2 offset : {glm::vec2(0.0f), glm::vec2(1.0f), glm::vec2(0.5f), glm::vec2(0.25f, 0.75f)}) {
    const Ray r = camera_ray_through_pixel(cam, px, offset, {0.5f, 0.5f});
    const glm::vec2 film((7.0f + offset.x) / 20, 1.0f - (2.0f + offset.y) / 10);
    const glm::vec2 f = film_of(cam, 2.0f, r);
    EXPECT_NEAR(f.x, film.x, 1e-4f) << offset.x << "," << offset.y;
    EXPECT_NEAR(f.y, film.y, 1e-4f) << offset.x << "," << offset.y;
    const Ray expect = generate_camera_ray(cam, 2.0f, film, {0.5f, 0.5f});
    EXPECT_NEAR(glm::length(r.d - expect.d), 0.0f, 1e-6f);
  }
}

TEST(pixel_loop, one_sample_goes_through_the_pixel_centre) {
  Camera cam;
  const PixelRef px{7, 2, 20, 10};  // column 7, row 2 from the top
  std::vector<Ray> rays;
  RadianceFn record = [&](const Ray& r, Rng&) {
    rays.push_back(r);
    return glm::vec3(1.0f);
  };
  Rng rng(3);
  PixelStats stats;
  estimate_pixel(cam, px, 1, rng, record, &stats);
  ASSERT_EQ(rays.size(), 1u);
  Ray expect = generate_camera_ray(cam, 2.0f, {7.5f / 20, 1.0f - 2.5f / 10}, {0.5f, 0.5f});
  EXPECT_NEAR(glm::length(rays[0].d - expect.d), 0.0f, 1e-6f);
  const glm::vec2 f = film_of(cam, 2.0f, rays[0]);
  EXPECT_NEAR(f.x, 7.5f / 20, 1e-4f);
  EXPECT_NEAR(f.y, 1.0f - 2.5f / 10, 1e-4f);
  EXPECT_EQ(stats.count, 1);
}

TEST(pixel_loop, jittered_samples_stay_in_their_pixel) {
  Camera cam;
  const PixelRef px{3, 5, 8, 6};
  std::vector<glm::vec2> films;
  RadianceFn record = [&](const Ray& r, Rng&) {
    films.push_back(film_of(cam, 8.0f / 6.0f, r));
    return glm::vec3(0.0f);
  };
  Rng rng(17);
  PixelStats stats;
  estimate_pixel(cam, px, 4096, rng, record, &stats);
  ASSERT_EQ(films.size(), 4096u);
  const float x0 = 3.0f / 8, x1 = 4.0f / 8, y0 = 1.0f - 6.0f / 6, y1 = 1.0f - 5.0f / 6;
  const float tol = 1e-4f;
  glm::vec2 lo(1e9f), hi(-1e9f);
  for (const glm::vec2& f : films) {
    EXPECT_GE(f.x, x0 - tol);
    EXPECT_LE(f.x, x1 + tol);
    EXPECT_GE(f.y, y0 - tol);
    EXPECT_LE(f.y, y1 + tol);
    lo = glm::min(lo, f), hi = glm::max(hi, f);
  }
  // Jittered over the whole pixel, not stuck at its centre: with 4096 uniform samples the
  // chance that no sample falls in the outer 2% of the pixel on one side is (0.98)^4096 < 1e-35.
  EXPECT_LT(lo.x, x0 + 0.02f / 8);
  EXPECT_GT(hi.x, x1 - 0.02f / 8);
  EXPECT_LT(lo.y, y0 + 0.02f / 6);
  EXPECT_GT(hi.y, y1 - 0.02f / 6);
}

// The order of the random numbers is part of the contract: for each sample its offset, then its
// lens sample only when the camera has a lens, then whatever the sample's radiance draws. The same
// seed then gives the same image in every renderer that keeps it (the viewer's pixel inspector,
// a re-render of one tile). The expected rays come from the student's own
// camera_ray_through_pixel, so only the loop's order is graded here.
TEST(pixel_loop, draws_the_offset_then_the_lens_sample) {
  for (const float lens_radius : {0.0f, 0.2f}) {
    Camera cam;
    cam.lens_radius = lens_radius;
    cam.focal_distance = 3.0f;
    const PixelRef px{3, 5, 16, 12};
    std::vector<Ray> rays;
    RadianceFn record = [&](const Ray& r, Rng& rng) {
      rays.push_back(r);
      rng.next_float();  // the sample's own draw, after the camera's
      return glm::vec3(1.0f);
    };
    Rng rng(11), mine(11);
    PixelStats stats;
    estimate_pixel(cam, px, 8, rng, record, &stats);
    ASSERT_EQ(rays.size(), 8u) << "lens radius " << lens_radius;
    for (size_t i = 0; i < rays.size(); ++i) {
      const glm::vec2 offset = mine.next_2d();
      const glm::vec2 lens = lens_radius > 0.0f ? mine.next_2d() : glm::vec2(0.5f);
      mine.next_float();
      const Ray expect = camera_ray_through_pixel(cam, px, offset, lens);
      EXPECT_EQ(rays[i].o, expect.o) << "sample " << i << ", lens radius " << lens_radius;
      EXPECT_EQ(rays[i].d, expect.d) << "sample " << i << ", lens radius " << lens_radius
                                     << ": not the offset, then the lens sample only with a lens";
    }
  }
}

TEST(pixel_loop, stats_hold_the_average_of_the_samples) {
  Camera cam;
  std::vector<glm::vec3> values;
  int k = 0;
  RadianceFn radiance = [&](const Ray&, Rng&) {
    glm::vec3 v(float(k % 7), 0.5f * float(k % 3), 2.0f);
    ++k;
    values.push_back(v);
    return v;
  };
  Rng rng(1);
  PixelStats stats;
  estimate_pixel(cam, PixelRef{0, 0, 4, 4}, 37, rng, radiance, &stats);
  ASSERT_EQ(values.size(), 37u);
  glm::dvec3 sum(0.0);
  for (const glm::vec3& v : values) sum += glm::dvec3(v);
  EXPECT_EQ(stats.count, 37);
  EXPECT_NEAR(stats.mean.x, sum.x / 37, 1e-12);
  EXPECT_NEAR(stats.mean.y, sum.y / 37, 1e-12);
  EXPECT_NEAR(stats.mean.z, 2.0, 1e-12);
}

}  // namespace
}  // namespace pt
