// Not needed for the assignment.
// The lighting tests' ray query (test_scenes.h): CGAL's exact ray-triangle predicate, spheres by
// bisection. Kept apart from the rest of the framework because CGAL is slow to compile.
#include <algorithm>
#include <cmath>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <glm/geometric.hpp>

#include "framework/testing/test_scenes.h"

namespace pt::test {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

Kernel::Point_3 point(const glm::vec3& p) { return {p.x, p.y, p.z}; }

/// The root of g(t) = |oc + t·d|^2 - r^2 between lo and hi, where g changes sign (g is a convex
/// parabola, so it is monotone on either side of its minimum), by bisection until the interval
/// cannot shrink: slow, and no closed form on purpose.
double bisect(const glm::dvec3& oc, const glm::dvec3& d, double r2, double lo, double hi) {
  auto g = [&](double t) {
    const glm::dvec3 x = oc + t * d;
    return glm::dot(x, x) - r2;
  };
  const bool rising = g(hi) > 0.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = lo + 0.5 * (hi - lo);
    if (!(mid > lo && mid < hi)) break;
    if ((g(mid) > 0.0) == rising) hi = mid;
    else lo = mid;
  }
  return lo + 0.5 * (hi - lo);
}

void fill(SurfaceHit* hit, double t, const glm::dvec3& p, const glm::dvec3& ng, uint32_t prim,
          uint32_t material) {
  hit->t = float(t);
  hit->p = glm::vec3(p);
  hit->p_error = gamma(3) * glm::abs(hit->p);
  hit->ng = glm::vec3(ng);
  hit->n = hit->ng;
  hit->primitive = prim;
  hit->material = material;
}

}  // namespace

bool DoubleQuery::nearest(const Ray& ray, SurfaceHit* hit, bool any) const {
  const glm::dvec3 o(ray.o), d(ray.d);
  double best = ray.tmax;
  bool found = false;
  const Kernel::Ray_3 cgal_ray(point(ray.o), Kernel::Vector_3(ray.d.x, ray.d.y, ray.d.z));
  for (uint32_t i = 0; i < s_.triangles.size(); ++i) {
    const Triangle& tri = s_.triangles[i];
    const glm::vec3 &fa = s_.positions[tri.v[0]], &fb = s_.positions[tri.v[1]],
                    &fc = s_.positions[tri.v[2]];
    const Kernel::Point_3 a = point(fa), b = point(fb), c = point(fc);
    if (CGAL::collinear(a, b, c)) continue;  // never hit, and CGAL's triangle needs an area
    if (!CGAL::do_intersect(cgal_ray, Kernel::Triangle_3(a, b, c))) continue;
    // The ray meets the triangle (exactly decided); its distance is where it meets the plane.
    const glm::dvec3 da(fa), normal = glm::cross(glm::dvec3(fb) - da, glm::dvec3(fc) - da);
    const double t = glm::dot(normal, da - o) / glm::dot(normal, d);
    if (!(t > ray.tmin && t < best)) continue;  // also a ray in the triangle's plane (t NaN)
    best = t;
    found = true;
    if (any) return true;
    const glm::dvec3 p = o + t * d;
    fill(hit, t, p, glm::normalize(normal), i, tri.material);
    if (!s_.normals.empty()) {
      int corner = 0;
      double nearest_d2 = INFINITY;
      for (int k = 0; k < 3; ++k) {
        const glm::dvec3 e = glm::dvec3(s_.positions[tri.v[k]]) - p;
        if (glm::dot(e, e) < nearest_d2) nearest_d2 = glm::dot(e, e), corner = k;
      }
      const glm::vec3 n = s_.normals[tri.v[corner]];
      if (glm::dot(n, n) > 0.0f) hit->n = glm::normalize(n);
      if (glm::dot(hit->n, hit->ng) < 0.0f) hit->n = -hit->n;
    }
  }
  for (uint32_t j = 0; j < s_.spheres.size(); ++j) {
    const Sphere& sp = s_.spheres[j];
    const glm::dvec3 oc = o - glm::dvec3(sp.center);
    const double r = sp.radius, r2 = r * r, dd = glm::dot(d, d);
    if (!(dd > 0.0)) continue;
    // The ray's closest approach to the centre splits it into the two monotone halves of g.
    const double tm = -glm::dot(oc, d) / dd;
    const glm::dvec3 v = oc + tm * d;
    if (!(glm::dot(v, v) < r2)) continue;
    const double reach = 2.0 * r / std::sqrt(dd);  // beyond it the ray is outside the sphere
    double t = bisect(oc, d, r2, tm - reach, tm);
    if (!(t > ray.tmin && t < best)) {
      t = bisect(oc, d, r2, tm, tm + reach);
      if (!(t > ray.tmin && t < best)) continue;
    }
    best = t;
    found = true;
    if (any) return true;
    glm::dvec3 n = glm::normalize(o + t * d - glm::dvec3(sp.center));
    const glm::dvec3 p = glm::dvec3(sp.center) + r * n;
    fill(hit, t, p, n, uint32_t(s_.triangles.size() + j), sp.material);
    hit->p_error += gamma(4) * glm::abs(glm::vec3(sp.center)) + gamma(4) * sp.radius;
  }
  return found;
}

}  // namespace pt::test
