// Not needed for the assignment.
// The course's camera placement: centred on the scene, the file's direction and distance kept.
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

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

// (b) Huge finite coordinates overflowed float on the way (the distance's square), which placed
// the camera at NaN: its rays were all NaN. The placement is finite, or an exception says why.
TEST(FrameworkCamera, HugeCoordinatesPlaceTheCameraFinitelyOrThrow) {
  Camera c;
  c.camera_to_world[3] = glm::vec4(0, 0, 3e19f, 1);
  Bounds3 box;
  box.grow(glm::vec3(-3e19f, -3e19f, -1));
  box.grow(glm::vec3(3e19f, 3e19f, 1));
  centre_camera_on(box, &c);
  const glm::vec3 p(c.camera_to_world[3]);
  EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
  EXPECT_FLOAT_EQ(p.z, 3e19f);
  // A camera so far from the scene that, moved to look at its centre, it leaves float's range.
  Camera far;
  far.camera_to_world[2] = glm::vec4(1, 0, 0, 0);  // looking down -X
  far.camera_to_world[3] = glm::vec4(-3e38f, 3e38f, 0, 1);
  Bounds3 wide;
  wide.grow(glm::vec3(3e38f, -3e38f, 0));
  wide.grow(glm::vec3(3e38f, -3e38f, 0));
  EXPECT_THROW(centre_camera_on(wide, &far), std::range_error);
}

// The course's default view of its Cornell boxes: 1.5 × the box's diagonal from its centre (4.80
// for the 2 × 2 × 1.5 box, where the file's camera is 3.09 away), and at -r 480 360 the
// pixels of its 800 × 600 window: the half field of view's tangent × 0.6.
TEST(FrameworkCamera, CourseViewAtTheCoursesUsualResolution) {
  Camera c;
  c.camera_to_world = glm::mat4(glm::vec4(-1, 0, 0, 0), glm::vec4(0, 0, 1, 0),
                                glm::vec4(0, 1, 0, 0), glm::vec4(0, 3, 0, 1));
  c.hfov_degrees = 49.13434f;
  const float tan_before = std::tan(glm::radians(c.hfov_degrees) / 2);
  Bounds3 box;
  box.grow(glm::vec3(-1, -1, 0));
  box.grow(glm::vec3(1, 1, 1.5f));
  place_course_camera(box, 480, 360, &c);
  const glm::vec3 p(c.camera_to_world[3]);
  EXPECT_NEAR(p.x, 0.0f, 1e-6f);
  EXPECT_NEAR(p.y, 1.5f * std::sqrt(4.0f + 4.0f + 2.25f), 1e-5f);
  EXPECT_NEAR(p.y, 4.80f, 5e-3f);
  EXPECT_NEAR(p.z, 0.75f, 1e-6f);
  EXPECT_EQ(glm::vec3(c.camera_to_world[2]), glm::vec3(0, 1, 0));
  EXPECT_NEAR(std::tan(glm::radians(c.hfov_degrees) / 2), 0.6f * tan_before, 1e-6f);
}

// The course's window itself (800 × 600) keeps the file's field of view; a smaller image shows
// the middle of that window, pixel for pixel.
TEST(FrameworkCamera, CourseViewKeepsThePixelSizeOfItsWindow) {
  for (int w : {800, 160, 1600}) {
    Camera c;
    c.hfov_degrees = 40.0f;
    const float tan_before = std::tan(glm::radians(c.hfov_degrees) / 2);
    place_course_camera(Bounds3{}, w, w * 3 / 4, &c);
    EXPECT_NEAR(std::tan(glm::radians(c.hfov_degrees) / 2), tan_before * float(w) / 800.0f,
                1e-6f * float(w))
        << w;
  }
}

}  // namespace
}  // namespace pt
