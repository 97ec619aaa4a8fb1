// Part 1's functions in a judge: each returns what the probe's record says the student's
// function returned for this call (record.h), so the test decides on the student's answers.
#include "grader/judge/replay.h"
#include "parts/1-raygen/camera_ray.h"
#include "parts/1-raygen/pixel_loop.h"
#include "parts/1-raygen/sphere_intersect.h"
#include "parts/1-raygen/triangle_intersect.h"

namespace pt {
using judge::Cursor;
using judge::Fn;
using judge::JudgeCall;

Ray generate_camera_ray(const Camera&, float, glm::vec2, glm::vec2) {
  JudgeCall call(Fn::generate_camera_ray);
  Cursor& out = call.finish();
  Ray r = out.get<Ray>();
  judge::all_read(Fn::generate_camera_ray, out);
  return r;
}

Ray camera_ray_through_pixel(const Camera&, const PixelRef&, glm::vec2, glm::vec2) {
  JudgeCall call(Fn::camera_ray_through_pixel);
  Cursor& out = call.finish();
  Ray r = out.get<Ray>();
  judge::all_read(Fn::camera_ray_through_pixel, out);
  return r;
}

void estimate_pixel(const Camera&, const PixelRef&, int, Rng& rng, const RadianceFn& radiance,
                    PixelStats* stats) {
  const Fn fn = Fn::estimate_pixel;
  JudgeCall call(fn);
  Cursor& out = call.finish([&](int which, Cursor& args) {
    if (which != 0) throw judge::RecordError("estimate_pixel has one callback");
    Ray ray = args.get<Ray>();
    Rng g = args.get<Rng>();
    glm::vec3 v = radiance(ray, g);
    Cursor answer = call.callback_answer();
    judge::expect_same_answer(fn, answer, v);
    judge::expect_same_answer(fn, answer, g);
    return answer;
  });
  rng = out.get<Rng>();
  if (judge::same_presence(fn, out, stats)) *stats = out.get<PixelStats>();
  judge::all_read(fn, out);
}

bool intersect_triangle(const Ray&, const glm::vec3&, const glm::vec3&, const glm::vec3&,
                        TriangleHit* hit) {
  const Fn fn = Fn::intersect_triangle;
  JudgeCall call(fn);
  Cursor& out = call.finish();
  bool met = judge::get_bool(fn, out);
  if (judge::same_presence(fn, out, hit)) *hit = out.get<TriangleHit>();
  judge::all_read(fn, out);
  return met;
}

glm::vec3 interpolate_normal(const TriangleHit&, const glm::vec3&, const glm::vec3&,
                             const glm::vec3&) {
  JudgeCall call(Fn::interpolate_normal);
  Cursor& out = call.finish();
  glm::vec3 n = out.get<glm::vec3>();
  judge::all_read(Fn::interpolate_normal, out);
  return n;
}

bool intersect_sphere(const Ray&, const Sphere&, float* t) {
  const Fn fn = Fn::intersect_sphere;
  JudgeCall call(fn);
  Cursor& out = call.finish();
  bool met = judge::get_bool(fn, out);
  if (judge::same_presence(fn, out, t)) *t = out.get<float>();
  judge::all_read(fn, out);
  return met;
}

}  // namespace pt
