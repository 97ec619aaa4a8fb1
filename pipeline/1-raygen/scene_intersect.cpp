// Not needed for the assignment: the definitions of pipeline/1-raygen/scene_intersect.h.
#include "pipeline/1-raygen/scene_intersect.h"

#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "framework/math/float_error.h"
#include "parts/1-raygen/sphere_intersect.h"
#include "parts/1-raygen/triangle_intersect.h"

namespace pt {

namespace {

bool all_finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

bool triangle_surface_hit(const Scene& scene, uint32_t primitive, const TriangleHit& th,
                          SurfaceHit* hit) {
  const Triangle& tri = scene.triangles[primitive];
  return triangle_surface_hit(scene, primitive, th, scene.positions[tri.v[0]],
                              scene.positions[tri.v[1]], scene.positions[tri.v[2]], tri.v, hit);
}

bool triangle_surface_hit(const Scene& scene, uint32_t primitive, const TriangleHit& th,
                          const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
                          const uint32_t vertex[3], SurfaceHit* hit) {
  // A triangle whose corners are collinear in float has no normal to shade or offset along: it
  // is treated as the zero-area sliver it is.
  const glm::vec3 cross = glm::cross(p1 - p0, p2 - p0);
  const float len = glm::length(cross);
  if (!(len > 0.0f) || !std::isfinite(len)) return false;
  glm::vec3 ng = cross / len;

  // The point from the barycentrics rather than o + t·d: its error does not grow with t
  // (pbrt-v4, 6.8.4: the sum of three products and two additions is within γ7 of each term).
  const glm::vec3 a = th.b0 * p0, b = th.b1 * p1, c = th.b2 * p2;
  hit->p = a + b + c;
  hit->p_error = gamma(7) * (glm::abs(a) + glm::abs(b) + glm::abs(c));

  glm::vec3 n = ng;
  if (!scene.normals.empty()) {
    const glm::vec3 ns = interpolate_normal(th, scene.normals[vertex[0]], scene.normals[vertex[1]],
                                            scene.normals[vertex[2]]);
    // Corner normals that cancel out (or a student's NaN) leave the geometric normal in charge.
    if (all_finite(ns) && glm::dot(ns, ns) > 0.0f) n = ns;
  }
  // The modeller's normals say which side is outside, whatever the winding.
  if (glm::dot(ng, n) < 0.0f) ng = -ng;

  hit->t = th.t;
  hit->ng = ng;
  hit->n = n;
  hit->primitive = primitive;
  hit->material = scene.triangles[primitive].material;
  return true;
}

namespace {

bool intersect_triangle_primitive(const Scene& scene, uint32_t primitive, const Ray& ray,
                                  SurfaceHit* hit) {
  const Triangle& tri = scene.triangles[primitive];
  TriangleHit th;
  if (!intersect_triangle(ray, scene.positions[tri.v[0]], scene.positions[tri.v[1]],
                          scene.positions[tri.v[2]], &th))
    return false;
  return triangle_surface_hit(scene, primitive, th, hit);
}

bool intersect_sphere_primitive(const Scene& scene, uint32_t primitive, const Ray& ray,
                                SurfaceHit* hit) {
  const Sphere& s = scene.spheres[primitive - scene.triangles.size()];
  float t;
  if (!intersect_sphere(ray, s, &t)) return false;

  // o + t·d carries the error of t, which is large for a far sphere; pushing the point back onto
  // the surface along its radius leaves only the rounding of that projection. With q = p - c:
  // the subtraction, the length (three products, two sums and a square root), the ratio r/|q|
  // and the product put each component of c + q·r/|q|'s second term within γ5·|q| of a point of the
  // sphere (the direction being slightly off does not matter: any point of the surface will
  // do); adding c rounds once more, by u·|p|. (pbrt-v4 states γ5·|p| in the sphere's own space,
  // where c = 0; in world space the centre's offset adds the γ1·|p| term.)
  glm::vec3 q = ray.at(t) - s.center;
  const float len = glm::length(q);
  if (!(len > 0.0f) || !std::isfinite(len)) return false;
  q *= s.radius / len;
  hit->p = s.center + q;
  hit->p_error = gamma(5) * glm::abs(q) + gamma(2) * glm::abs(hit->p);

  const glm::vec3 n = q / s.radius;
  hit->t = t;
  hit->ng = n;
  hit->n = n;
  hit->primitive = primitive;
  hit->material = s.material;
  return true;
}

}  // namespace

bool intersect_primitive(const Scene& scene, uint32_t primitive, const Ray& ray, SurfaceHit* hit) {
  return scene.is_triangle(primitive) ? intersect_triangle_primitive(scene, primitive, ray, hit)
                                      : intersect_sphere_primitive(scene, primitive, ray, hit);
}

bool primitive_occludes(const Scene& scene, uint32_t primitive, const Ray& ray) {
  if (scene.is_triangle(primitive)) {
    const Triangle& tri = scene.triangles[primitive];
    TriangleHit th;
    return intersect_triangle(ray, scene.positions[tri.v[0]], scene.positions[tri.v[1]],
                              scene.positions[tri.v[2]], &th);
  }
  float t;
  return intersect_sphere(ray, scene.spheres[primitive - scene.triangles.size()], &t);
}

bool BruteForce::intersect(const Ray& ray, SurfaceHit* hit) const {
  if (!is_traceable(ray)) return false;  // as every ray query answers it
  Ray r = ray;
  bool found = false;
  const uint32_t n = scene_.primitive_count();
  for (uint32_t i = 0; i < n; ++i) {
    if (intersect_primitive(scene_, i, r, hit)) {
      r.tmax = hit->t;  // later primitives must beat this one
      found = true;
    }
  }
  return found;
}

bool BruteForce::occluded(const Ray& ray) const {
  if (!is_traceable(ray)) return false;
  const uint32_t n = scene_.primitive_count();
  for (uint32_t i = 0; i < n; ++i)
    if (primitive_occludes(scene_, i, ray)) return true;
  return false;
}

}  // namespace pt
