// Not needed for the assignment.
// spawn_ray and spawn_ray_to: their rays leave and stop where the error bounds say.
#include "framework/geometry/spawn_ray.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace pt {
namespace {

// What the offsets are for: the origin is outside the shading point's error box on the side the
// ray leaves to, and the end stops short of the target's box on the side the ray comes from.
TEST(FrameworkSpawnRay, TheRayStartsAndEndsOutsideBothErrorBoxes) {
  SurfaceHit hit;
  hit.p = glm::vec3(0.5f, 0.25f, 0.0f);
  hit.p_error = glm::vec3(1e-6f, 1e-6f, 1e-6f);
  hit.ng = glm::vec3(0.0f, 0.0f, 1.0f);
  const glm::vec3 p(0.4f, 0.3f, 1.0f), p_error(1e-6f), n(0.0f, 0.0f, -1.0f);
  const glm::vec3 w = glm::normalize(p - hit.p);
  const Ray r = spawn_ray_to(hit, w, p, p_error, n);
  EXPECT_GT(r.o.z, hit.p.z + hit.p_error.z);
  EXPECT_LT(r.at(r.tmax).z, p.z - p_error.z);
  EXPECT_GT(r.tmax, 0.99f);
  // The bounce ray leaves on its direction's side, below the surface as above it.
  const Ray up = spawn_ray(hit, glm::vec3(0.0f, 0.0f, 1.0f));
  const Ray down = spawn_ray(hit, glm::vec3(0.0f, 0.0f, -1.0f));
  EXPECT_GT(up.o.z, hit.p.z + hit.p_error.z);
  EXPECT_LT(down.o.z, hit.p.z - hit.p_error.z);
  // A target (with no surface) at the ray's own origin: nothing between, an empty interval.
  EXPECT_EQ(spawn_ray_to(hit, w, r.o, glm::vec3(0.0f), glm::vec3(0.0f)).tmax, 0.0f);
}

}  // namespace
}  // namespace pt
