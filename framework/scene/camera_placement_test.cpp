// The course's camera placement: centred on the scene, the file's direction and distance kept.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "framework/scene/camera_placement.h"

namespace pt {
namespace {

TEST(FrameworkCamera, CentredOnTheSceneAlongTheFilesDirection) {
  // The course's Cornell box camera: at (0,3,0), looking down -y, up +z; the box spans
  // z 0..1.5, so the camera sits at floor height until it is centred.
  Camera c;
  c.camera_to_world = glm::mat4(glm::vec4(-1, 0, 0, 0), glm::vec4(0, 0, 1, 0),
                                glm::vec4(0, 1, 0, 0), glm::vec4(0, 3, 0, 1));
  Bounds3 box;
  box.grow(glm::vec3(-1, -1, 0));
  box.grow(glm::vec3(1, 1, 1.5f));
  centre_camera_on(box, &c);
  glm::vec3 p(c.camera_to_world[3]);
  float d = glm::length(glm::vec3(0, 3, 0) - glm::vec3(0, 0, 0.75f));
  EXPECT_NEAR(p.x, 0.0f, 1e-6f);
  EXPECT_NEAR(p.y, d, 1e-5f);
  EXPECT_NEAR(p.z, 0.75f, 1e-6f);
  // Orientation untouched: still looking down -y.
  EXPECT_EQ(glm::vec3(c.camera_to_world[2]), glm::vec3(0, 1, 0));
}

TEST(FrameworkCamera, EmptyBoundsLeaveTheCamera) {
  Camera c;
  c.camera_to_world[3] = glm::vec4(1, 2, 3, 1);
  centre_camera_on(Bounds3{}, &c);
  EXPECT_EQ(glm::vec3(c.camera_to_world[3]), glm::vec3(1, 2, 3));
}

}  // namespace
}  // namespace pt
