// Part 1: camera rays — field of view, camera placement, thin-lens focus.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "parts/1-raygen/camera_ray.h"

namespace pt {
namespace {

float angle_between(const glm::vec3& a, const glm::vec3& b) {
  return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f));
}

// The left and right edge rays span hfov exactly; the bottom and top ones the vertical angle that
// the image's aspect gives, 2·atan(tan(hfov/2)/aspect).
TEST(camera_ray, corners_match_the_field_of_view) {
  Camera cam;
  cam.hfov_degrees = 60.0f;
  for (float aspect : {1.0f, 4.0f / 3.0f, 0.5f, 2.35f}) {
    const float hfov = glm::radians(60.0f);
    const float vfov = 2.0f * std::atan(std::tan(hfov / 2) / aspect);
    Ray l = generate_camera_ray(cam, aspect, {0.0f, 0.5f}, {0.5f, 0.5f});
    Ray r = generate_camera_ray(cam, aspect, {1.0f, 0.5f}, {0.5f, 0.5f});
    Ray b = generate_camera_ray(cam, aspect, {0.5f, 0.0f}, {0.5f, 0.5f});
    Ray t = generate_camera_ray(cam, aspect, {0.5f, 1.0f}, {0.5f, 0.5f});
    EXPECT_NEAR(angle_between(l.d, r.d), hfov, 1e-5f) << "aspect " << aspect;
    EXPECT_NEAR(angle_between(b.d, t.d), vfov, 1e-5f) << "aspect " << aspect;
    // (0,0) is the bottom-left: left is -x, bottom is -y, the view looks down -z.
    EXPECT_LT(l.d.x, 0.0f);
    EXPECT_GT(r.d.x, 0.0f);
    EXPECT_LT(b.d.y, 0.0f);
    EXPECT_GT(t.d.y, 0.0f);
    Ray corner = generate_camera_ray(cam, aspect, {0.0f, 0.0f}, {0.5f, 0.5f});
    EXPECT_NEAR(corner.d.x / -corner.d.z, -std::tan(hfov / 2), 1e-5f);
    EXPECT_NEAR(corner.d.y / -corner.d.z, -std::tan(hfov / 2) / aspect, 1e-5f);
    for (const Ray& ray : {l, r, b, t, corner}) {
      EXPECT_NEAR(glm::length(ray.d), 1.0f, 1e-6f);
      EXPECT_EQ(ray.o, glm::vec3(0.0f));
      EXPECT_EQ(ray.tmin, 0.0f);
      // tmax reaches the far plane z = -zfar along this ray.
      EXPECT_NEAR(ray.o.z + ray.tmax * ray.d.z, -cam.zfar, 1e-3f);
    }
  }
}

// A rotated, translated camera: rays start at its position and the centre ray looks where the
// matrix's -z axis points.
TEST(camera_ray, camera_to_world_is_applied) {
  Camera cam;
  const glm::vec3 eye(3.0f, -2.0f, 7.5f), look_at(-1.0f, 4.0f, 0.5f), up(0.0f, 0.0f, 1.0f);
  cam.camera_to_world = glm::inverse(glm::lookAt(eye, look_at, up));
  Ray c = generate_camera_ray(cam, 1.5f, {0.5f, 0.5f}, {0.5f, 0.5f});
  EXPECT_NEAR(glm::length(c.o - eye), 0.0f, 1e-5f);
  EXPECT_NEAR(angle_between(c.d, look_at - eye), 0.0f, 1e-3f);
  // The top of the image is towards `up`, the right towards forward x up.
  Ray top = generate_camera_ray(cam, 1.5f, {0.5f, 1.0f}, {0.5f, 0.5f});
  Ray right = generate_camera_ray(cam, 1.5f, {1.0f, 0.5f}, {0.5f, 0.5f});
  EXPECT_GT(glm::dot(top.d - c.d, up), 0.0f);
  EXPECT_GT(glm::dot(right.d - c.d, glm::cross(look_at - eye, up)), 0.0f);
}

// Thin lens: rays through one film point from all over the aperture meet on the focal plane at
// the pinhole ray's point, and start on the lens disk.
TEST(camera_ray, thin_lens_rays_converge_on_the_focal_plane) {
  Camera cam;
  cam.lens_radius = 0.25f;
  cam.focal_distance = 4.0f;
  cam.camera_to_world = glm::translate(glm::mat4(1.0f), glm::vec3(1.0f, 2.0f, 3.0f)) *
                        glm::rotate(glm::mat4(1.0f), 0.7f, glm::vec3(0.3f, 1.0f, 0.2f));
  const glm::mat4 world_to_camera = glm::inverse(cam.camera_to_world);
  const glm::vec2 film(0.3f, 0.8f);
  Camera pinhole = cam;
  pinhole.lens_radius = 0.0f;
  Ray p = generate_camera_ray(pinhole, 1.25f, film, {0.5f, 0.5f});
  const glm::vec3 pd = glm::vec3(world_to_camera * glm::vec4(p.d, 0.0f));
  const glm::vec3 focus = glm::vec3(world_to_camera * glm::vec4(p.o, 1.0f)) +
                          (-cam.focal_distance / pd.z) * pd;
  float max_radius = 0.0f;
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j) {
      Ray r = generate_camera_ray(cam, 1.25f, film, {(i + 0.5f) / 16, (j + 0.5f) / 16});
      const glm::vec3 o = glm::vec3(world_to_camera * glm::vec4(r.o, 1.0f));
      const glm::vec3 d = glm::vec3(world_to_camera * glm::vec4(r.d, 0.0f));
      EXPECT_NEAR(o.z, 0.0f, 1e-5f);
      EXPECT_LE(std::hypot(o.x, o.y), cam.lens_radius * (1 + 1e-5f));
      max_radius = std::max(max_radius, std::hypot(o.x, o.y));
      const glm::vec3 on_plane = o + (-cam.focal_distance - o.z) / d.z * d;
      EXPECT_NEAR(glm::length(on_plane - focus), 0.0f, 1e-4f);
      EXPECT_NEAR(glm::length(r.d), 1.0f, 1e-6f);
    }
  EXPECT_GT(max_radius, 0.9f * cam.lens_radius);  // the aperture is used, not just its centre
}

// The lens point is uniform over the aperture's area: on a stratified grid of lens samples, the
// mean of r^2 is R^2/2 (r = R*sqrt(u)); a radius uniform in [0, R] gives R^2/3, crowding the
// centre.
TEST(camera_ray, lens_points_are_uniform_over_the_aperture) {
  Camera cam;
  cam.lens_radius = 0.5f;
  cam.focal_distance = 2.0f;
  double mean_r2 = 0.0;
  const int n = 32;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Ray r = generate_camera_ray(cam, 1.0f, {0.4f, 0.6f}, {(i + 0.5f) / n, (j + 0.5f) / n});
      mean_r2 += double(r.o.x) * r.o.x + double(r.o.y) * r.o.y;
    }
  mean_r2 /= double(n * n);
  EXPECT_NEAR(mean_r2 / (0.25), 0.5, 0.01)
      << "the mean squared distance of the lens points from the centre, over R^2: 1/2 for points "
         "uniform over the disk's area";
}

}  // namespace
}  // namespace pt
