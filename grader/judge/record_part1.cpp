// Part 1's probe: each graded function of Part 1, recorded as the test calls it (record.h).
#include "grader/judge/record.h"
#include "grader/judge/wrap.h"
#include "parts/1-raygen/camera_ray.h"
#include "parts/1-raygen/pixel_loop.h"
#include "parts/1-raygen/sphere_intersect.h"
#include "parts/1-raygen/triangle_intersect.h"

#define GENERATE_CAMERA_RAY "_ZN2pt19generate_camera_rayERKNS_6CameraEfN3glm3vecILi2EfLNS3_9qualifierE0EEES6_"
#define CAMERA_RAY_THROUGH_PIXEL "_ZN2pt24camera_ray_through_pixelERKNS_6CameraERKNS_8PixelRefEN3glm3vecILi2EfLNS6_9qualifierE0EEES9_"
#define ESTIMATE_PIXEL "_ZN2pt14estimate_pixelERKNS_6CameraERKNS_8PixelRefEiRNS_3RngERKSt8functionIFN3glm3vecILi3EfLNS9_9qualifierE0EEERKNS_3RayES7_EEPNS_10PixelStatsE"
#define INTERSECT_TRIANGLE "_ZN2pt18intersect_triangleERKNS_3RayERKN3glm3vecILi3EfLNS3_9qualifierE0EEES8_S8_PNS_11TriangleHitE"
#define INTERPOLATE_NORMAL "_ZN2pt18interpolate_normalERKNS_11TriangleHitERKN3glm3vecILi3EfLNS3_9qualifierE0EEES8_S8_"
#define INTERSECT_SPHERE "_ZN2pt16intersect_sphereERKNS_3RayERKNS_6SphereEPf"

namespace pt::judge {
namespace real {
Ray generate_camera_ray(const Camera&, float, glm::vec2, glm::vec2) PT_REAL(GENERATE_CAMERA_RAY);
Ray camera_ray_through_pixel(const Camera&, const PixelRef&, glm::vec2, glm::vec2) PT_REAL(CAMERA_RAY_THROUGH_PIXEL);
void estimate_pixel(const Camera&, const PixelRef&, int, Rng&, const RadianceFn&, PixelStats*) PT_REAL(ESTIMATE_PIXEL);
bool intersect_triangle(const Ray&, const glm::vec3&, const glm::vec3&, const glm::vec3&, TriangleHit*) PT_REAL(INTERSECT_TRIANGLE);
glm::vec3 interpolate_normal(const TriangleHit&, const glm::vec3&, const glm::vec3&, const glm::vec3&) PT_REAL(INTERPOLATE_NORMAL);
bool intersect_sphere(const Ray&, const Sphere&, float*) PT_REAL(INTERSECT_SPHERE);
}  // namespace real

Ray wrap_generate_camera_ray(const Camera&, float, glm::vec2, glm::vec2) PT_WRAP(GENERATE_CAMERA_RAY);
Ray wrap_generate_camera_ray(const Camera& camera, float aspect, glm::vec2 film, glm::vec2 lens) {
  ProbeCall call(Fn::generate_camera_ray);
  Ray r = real::generate_camera_ray(camera, aspect, film, lens);
  call.out.put(r);
  call.returned();
  return r;
}

Ray wrap_camera_ray_through_pixel(const Camera&, const PixelRef&, glm::vec2, glm::vec2) PT_WRAP(CAMERA_RAY_THROUGH_PIXEL);
Ray wrap_camera_ray_through_pixel(const Camera& camera, const PixelRef& px, glm::vec2 offset, glm::vec2 lens) {
  ProbeCall call(Fn::camera_ray_through_pixel);
  Ray r = real::camera_ray_through_pixel(camera, px, offset, lens);
  call.out.put(r);
  call.returned();
  return r;
}

void wrap_estimate_pixel(const Camera&, const PixelRef&, int, Rng&, const RadianceFn&, PixelStats*) PT_WRAP(ESTIMATE_PIXEL);
void wrap_estimate_pixel(const Camera& camera, const PixelRef& px, int samples, Rng& rng,
                         const RadianceFn& radiance, PixelStats* stats) {
  ProbeCall call(Fn::estimate_pixel);
  RadianceFn recorded = [&](const Ray& ray, Rng& g) {
    ProbeCallback cb(Fn::estimate_pixel, 0);
    cb.args.put(ray);
    cb.args.put(g);
    cb.begin();
    glm::vec3 v = radiance(ray, g);
    cb.answer.put(v);
    cb.answer.put(g);
    cb.end();
    return v;
  };
  real::estimate_pixel(camera, px, samples, rng, radiance ? recorded : radiance, stats);
  call.out.put(rng);
  call.out.put(uint8_t(stats != nullptr));
  if (stats) call.out.put(*stats);
  call.returned();
}

bool wrap_intersect_triangle(const Ray&, const glm::vec3&, const glm::vec3&, const glm::vec3&, TriangleHit*) PT_WRAP(INTERSECT_TRIANGLE);
bool wrap_intersect_triangle(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                             const glm::vec3& p2, TriangleHit* hit) {
  ProbeCall call(Fn::intersect_triangle);
  bool met = real::intersect_triangle(ray, p0, p1, p2, hit);
  call.out.put(uint8_t(met));
  call.out.put(uint8_t(hit != nullptr));
  if (hit) call.out.put(*hit);
  call.returned();
  return met;
}

glm::vec3 wrap_interpolate_normal(const TriangleHit&, const glm::vec3&, const glm::vec3&, const glm::vec3&) PT_WRAP(INTERPOLATE_NORMAL);
glm::vec3 wrap_interpolate_normal(const TriangleHit& hit, const glm::vec3& n0, const glm::vec3& n1,
                                  const glm::vec3& n2) {
  ProbeCall call(Fn::interpolate_normal);
  glm::vec3 n = real::interpolate_normal(hit, n0, n1, n2);
  call.out.put(n);
  call.returned();
  return n;
}

bool wrap_intersect_sphere(const Ray&, const Sphere&, float*) PT_WRAP(INTERSECT_SPHERE);
bool wrap_intersect_sphere(const Ray& ray, const Sphere& sphere, float* t) {
  ProbeCall call(Fn::intersect_sphere);
  bool met = real::intersect_sphere(ray, sphere, t);
  call.out.put(uint8_t(met));
  call.out.put(uint8_t(t != nullptr));
  if (t) call.out.put(*t);
  call.returned();
  return met;
}

}  // namespace pt::judge
