// Not needed for the assignment: the definitions of framework/lights/sampled_lights.h.
#include "framework/lights/sampled_lights.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "framework/math/float_error.h"
#include "framework/math/frame.h"
#include "framework/sampling/warp.h"

namespace pt {
namespace {

bool finite_positive(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) &&
         (v.x > 0 || v.y > 0 || v.z > 0);
}

// Whether triangle (a, b, c) is a panel of parallelogram light `l`: its corners in the light's
// plane (within a thousandth of the light's size) and its centroid inside the light. The course's
// panels are the light's face but not its exact outline (CBspheres' panel is 0.8 × 0.6 where its
// light is 0.6 × 0.8), so the outline is not required to match. A classification of scene data,
// not a ray test.
bool on_parallelogram(const SampledLight& l, const glm::vec3& a, const glm::vec3& b,
                      const glm::vec3& c) {
  const glm::vec3 n_raw = glm::cross(l.edge_u, l.edge_v);
  const float n2 = glm::dot(n_raw, n_raw);
  const float size = std::max(glm::length(l.edge_u), glm::length(l.edge_v));
  const float tol = 1e-3f;
  for (const glm::vec3& q : {a, b, c})
    if (std::abs(glm::dot(q - l.corner, l.normal)) > tol * size) return false;
  glm::vec3 d = (a + b + c) / 3.0f - l.corner;
  float s = glm::dot(glm::cross(d, l.edge_v), n_raw) / n2;
  float t = glm::dot(glm::cross(l.edge_u, d), n_raw) / n2;
  return s >= 0 && s <= 1 && t >= 0 && t <= 1;
}

// Parameter t > 0 where the ray (o, w) meets the parallelogram, or 0 for a miss.
float hit_parallelogram(const SampledLight& l, const glm::vec3& o, const glm::vec3& w) {
  const glm::vec3 n_raw = glm::cross(l.edge_u, l.edge_v);
  float denom = glm::dot(w, n_raw);
  if (denom == 0.0f) return 0.0f;
  float t = glm::dot(l.corner - o, n_raw) / denom;
  if (!(t > 0.0f) || !std::isfinite(t)) return 0.0f;
  glm::vec3 d = o + t * w - l.corner;
  const float n2 = glm::dot(n_raw, n_raw);
  float s = glm::dot(glm::cross(d, l.edge_v), n_raw) / n2;
  float v = glm::dot(glm::cross(l.edge_u, d), n_raw) / n2;
  return (s >= 0 && s <= 1 && v >= 0 && v <= 1) ? t : 0.0f;
}

// Attenuation of a point or spot light at distance d: the inverse square of a physical point
// light, divided by the COLLADA attenuation polynomial (1 with the file's defaults).
float point_falloff(const Light* light, float d) {
  float att = 1.0f;
  if (light)
    att = light->constant_attenuation + light->linear_attenuation * d +
          light->quadratic_attenuation * d * d;
  float denom = d * d * att;
  return denom > 0.0f && std::isfinite(denom) ? 1.0f / denom : 0.0f;
}

// 1 − cosθmax of the cone a sphere of radius r subtends from distance² dist2 (> r²), computed
// as sin²/(1 + cos) so that small, far spheres do not round it to zero.
float sphere_cone_one_minus_cos(float r, float dist2) {
  float sin2 = std::min(1.0f, r * r / dist2);
  return sin2 / (1.0f + safe_sqrt(1.0f - sin2));
}

// Unit normal of triangle (a, b, c) by its winding, turned to the side of `side` when that is
// non-zero; zero for a degenerate triangle. Sampling, pdf and emission of a one-sided panel all
// ask this one function, so they agree on which side of each triangle glows.
glm::vec3 triangle_normal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                          const glm::vec3& side) {
  glm::vec3 n = glm::cross(b - a, c - a);
  const float len = glm::length(n);
  if (!(len > 0.0f) || !std::isfinite(len)) return glm::vec3(0.0f);
  n /= len;
  return glm::dot(n, side) < 0.0f ? -n : n;
}

// Each of `triangles`' corners and triangle_normal, in their order.
std::vector<SampledLight::SampledTriangle> sampled_triangles(const Scene& scene,
                                                             const std::vector<uint32_t>& triangles,
                                                             const glm::vec3& side) {
  std::vector<SampledLight::SampledTriangle> out;
  out.reserve(triangles.size());
  for (uint32_t prim : triangles) {
    const Triangle& tri = scene.triangles[prim];
    SampledLight::SampledTriangle t;
    t.a = scene.positions[tri.v[0]];
    t.b = scene.positions[tri.v[1]];
    t.c = scene.positions[tri.v[2]];
    t.n = triangle_normal(t.a, t.b, t.c, side);
    out.push_back(t);
  }
  return out;
}

std::string number(float v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", double(v));
  return buf;
}
std::string rgb(const glm::vec3& v) {
  if (v.x == v.y && v.y == v.z) return number(v.x);
  return "(" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ")";
}
bool same_radiance(const glm::vec3& a, const glm::vec3& b) {
  const float scale = std::max({std::abs(a.x), std::abs(a.y), std::abs(a.z), std::abs(b.x),
                                std::abs(b.y), std::abs(b.z)});
  const glm::vec3 d = glm::abs(a - b);
  return std::max({d.x, d.y, d.z}) <= 1e-5f * scale;
}

// How area light `l`'s panel (its triangles) compares with the light: whether the two have one
// shape (the panel covers the light's parallelogram and no more), and the warning to give when
// they differ in shape or radiance ("" when they agree).
struct PanelComparison {
  bool same_shape = false;
  std::string warning;
};
PanelComparison compare_panel(const Scene& scene, const SampledLight& l,
                              const std::vector<uint32_t>& panel) {
  const glm::vec3 n_raw = glm::cross(l.edge_u, l.edge_v);
  const float n2 = glm::dot(n_raw, n_raw);
  float s_lo = 1e30f, s_hi = -1e30f, t_lo = 1e30f, t_hi = -1e30f, area = 0.0f;
  const Material* different = nullptr;
  for (uint32_t prim : panel) {
    const Triangle& tri = scene.triangles[prim];
    const glm::vec3 &a = scene.positions[tri.v[0]], &b = scene.positions[tri.v[1]],
                    &c = scene.positions[tri.v[2]];
    area += 0.5f * glm::length(glm::cross(b - a, c - a));
    for (const glm::vec3& q : {a, b, c}) {
      const glm::vec3 d = q - l.corner;
      const float s = glm::dot(glm::cross(d, l.edge_v), n_raw) / n2;
      const float t = glm::dot(glm::cross(l.edge_u, d), n_raw) / n2;
      s_lo = std::min(s_lo, s), s_hi = std::max(s_hi, s);
      t_lo = std::min(t_lo, t), t_hi = std::max(t_hi, t);
    }
    const Material& m = scene.materials[tri.material];
    if (!different && !same_radiance(m.emission, l.radiance)) different = &m;
  }
  const float tol = 1e-3f;
  PanelComparison out;
  out.same_shape = std::abs(s_lo) <= tol && std::abs(s_hi - 1.0f) <= tol &&
                   std::abs(t_lo) <= tol && std::abs(t_hi - 1.0f) <= tol &&
                   std::abs(area - l.area) <= tol * l.area;
  if (out.same_shape && !different) return out;
  const Material& shown = different ? *different : scene.materials[scene.triangles[panel[0]].material];
  const float lu = glm::length(l.edge_u), lv = glm::length(l.edge_v);
  const std::string name = l.source ? l.source->name : std::string();
  out.warning =
      "<light name=\"" + name + "\"> (a CGL area light, " + number(lu) + " × " + number(lv) +
      ", radiance " + rgb(l.radiance) + ") and its panel (material \"" + shown.name + "\", " +
      number((s_hi - s_lo) * lu) + " × " + number((t_hi - t_lo) * lv) +
      " along the light's edges, area " + number(area) + ", emission " + rgb(shown.emission) +
      ") differ in " + (out.same_shape ? "radiance" : different ? "shape and radiance" : "shape") +
      "; as the course renders it, the light's rectangle with its radiance lights the scene (light "
      "samples, hemisphere and BSDF samples all reach it) and the panel, glowing with the light's "
      "radiance, is what the camera, mirrors and glass show";
  return out;
}

// The end of every panel and mesh sample: the point q = wa + wb + wc on the light (the sum in
// that order), its error bound γ6·(|wa| + |wb| + |wc|) (plus `slack`, when not null), and the
// light's normal n there. Fills ls and returns whether the point can send light towards p.
// Inlined into both of its callers: a call would add to every light sample's chain.
[[gnu::always_inline]] inline bool finish_surface_sample(const SampledLight& l, const glm::vec3& p,
                                                         const glm::vec3& wa, const glm::vec3& wb,
                                                         const glm::vec3& wc, const glm::vec3& n,
                                                         bool one_sided, const glm::vec3* slack,
                                                         LightSample* ls) {
  // Uniform on the light's whole surface: 1 / area, whichever triangle the point is on; nothing
  // from the back of a one-sided panel. The point's error: each term of the sum is within γ6 of
  // its size (the corners' products and the sum's two roundings), plus the quad's slack.
  const glm::vec3 q = wa + wb + wc;
  const glm::vec3 d = q - p;
  const float dist = glm::length(d);
  if (!(dist > 0.0f) || !std::isfinite(dist)) return false;
  const glm::vec3 wi = d / dist;
  const float cos_l = glm::dot(-wi, n);
  if (one_sided && !(cos_l > 0.0f)) return false;
  ls->wi = wi;
  ls->target.distance = dist;
  ls->target.p = q;
  ls->target.p_error = gamma(6) * (glm::abs(wa) + glm::abs(wb) + glm::abs(wc));
  if (slack) ls->target.p_error += *slack;
  ls->target.n = n;
  ls->pdf = area_to_solid_angle_pdf(l.inv_area, dist, cos_l);
  ls->L = ls->pdf > 0.0f ? l.radiance : glm::vec3(0.0f);
  return true;
}

// Triangle (a, b, c) as the directions from p to its points: a spherical triangle of corners
// A, B, C (unit vectors), of angle alpha at A, and of solid angle omega = alpha + beta + gamma − π.
// usable when it subtends at least kMinSolidAngle (below that the sum of angles loses the
// difference to rounding, and area sampling's 1/d² is harmless anyway) and is not edge-on.
struct SphericalTriangle {
  glm::dvec3 A{0.0}, B{0.0}, C{0.0};
  double alpha = 0.0, omega = 0.0;
  bool usable = false;
};
constexpr double kMinSolidAngle = 1e-3;

SphericalTriangle spherical_triangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b,
                                     const glm::vec3& c) {
  SphericalTriangle s;
  const glm::dvec3 da = glm::dvec3(a) - glm::dvec3(p), db = glm::dvec3(b) - glm::dvec3(p),
                   dc = glm::dvec3(c) - glm::dvec3(p);
  const double la = glm::length(da), lb = glm::length(db), lc = glm::length(dc);
  if (!(la > 0.0 && lb > 0.0 && lc > 0.0)) return s;
  s.A = da / la, s.B = db / lb, s.C = dc / lc;
  // The angle at a corner is the one between the great circles through it: between the normals
  // of the planes each pair of corners spans with the centre.
  const glm::dvec3 n_ab = glm::cross(s.A, s.B), n_bc = glm::cross(s.B, s.C), n_ca = glm::cross(s.C, s.A);
  const double l_ab = glm::length(n_ab), l_bc = glm::length(n_bc), l_ca = glm::length(n_ca);
  if (!(l_ab > 1e-12 && l_bc > 1e-12 && l_ca > 1e-12)) return s;
  auto angle = [](const glm::dvec3& u, double lu, const glm::dvec3& v, double lv) {
    return std::acos(std::clamp(glm::dot(u, v) / (lu * lv), -1.0, 1.0));
  };
  s.alpha = angle(n_ab, l_ab, -n_ca, l_ca);
  const double beta = angle(n_bc, l_bc, -n_ab, l_ab);
  const double gamma_ = angle(n_ca, l_ca, -n_bc, l_bc);
  s.omega = s.alpha + beta + gamma_ - M_PI;
  s.usable = s.omega >= kMinSolidAngle && std::isfinite(s.omega) &&
             std::abs(glm::dot(s.A, n_bc)) > 1e-9;  // not seen edge-on
  return s;
}

// A direction uniform in solid angle over spherical triangle s (Arvo 1995): the sub-triangle
// A B C' of area u.x·omega fixes C' on the arc AC, then the direction lies on the arc B C' at
// the cosine 1 − u.y (1 − C'·B) from B.
glm::dvec3 sample_spherical_triangle(const SphericalTriangle& s, glm::vec2 u) {
  const double area = double(u.x) * s.omega;
  const double sn = std::sin(area - s.alpha), cs = std::cos(area - s.alpha);
  const double ca = std::cos(s.alpha), sa = std::sin(s.alpha);
  const double uu = cs - ca;
  const double vv = sn + sa * glm::dot(s.A, s.B);
  const double q = std::clamp(((vv * cs - uu * sn) * ca - vv) / ((vv * sn + uu * cs) * sa), -1.0, 1.0);
  const glm::dvec3 along_ac = s.C - glm::dot(s.C, s.A) * s.A;
  const glm::dvec3 c1 = q * s.A + std::sqrt(std::max(0.0, 1.0 - q * q)) * glm::normalize(along_ac);
  const double z = 1.0 - double(u.y) * (1.0 - glm::dot(c1, s.B));
  const glm::dvec3 along = c1 - glm::dot(c1, s.B) * s.B;
  const double len = glm::length(along);
  if (!(len > 0.0)) return s.B;
  return z * s.B + std::sqrt(std::max(0.0, 1.0 - z * z)) * (along / len);
}

// Where a mesh light's triangle is seen from p under a usable solid angle, its point is drawn
// uniformly in that solid angle, not by area: a point just above a two-sided light (CBempty's
// ceiling, a centimetre above its panel) saw area sampling's 1/d² weights, unbiased but so
// heavy-tailed that a thousand samples a pixel left whole blocks darker than MIS. The point is
// where the direction meets the triangle's plane, written as barycentric terms as area sampling
// writes it (so its error bound is the same); the density is the pick's over omega.
bool sample_triangle_by_solid_angle(const SampledLight& l, const SampledLight::SampledTriangle& t,
                                    const SphericalTriangle& s, float pick, const glm::vec3& p,
                                    glm::vec2 u, LightSample* ls) {
  const glm::dvec3 w = sample_spherical_triangle(s, u);
  const glm::dvec3 a(t.a), b(t.b), c(t.c), o(p);
  const glm::dvec3 e1 = b - a, e2 = c - a, n = glm::cross(e1, e2);
  const double denom = glm::dot(w, n);
  if (!(std::abs(denom) > 0.0)) return false;
  const glm::dvec3 q = o + (glm::dot(a - o, n) / denom) * w;
  const glm::dvec3 v = q - a;
  const double d00 = glm::dot(e1, e1), d01 = glm::dot(e1, e2), d11 = glm::dot(e2, e2);
  const double d20 = glm::dot(v, e1), d21 = glm::dot(v, e2), den = d00 * d11 - d01 * d01;
  if (!(den > 0.0)) return false;
  double wb = std::max(0.0, (d11 * d20 - d01 * d21) / den), wc = std::max(0.0, (d00 * d21 - d01 * d20) / den);
  double wa = std::max(0.0, 1.0 - wb - wc);
  const double sum = wa + wb + wc;
  wa /= sum, wb /= sum, wc /= sum;
  if (!finish_surface_sample(l, p, float(wa) * t.a, float(wb) * t.b, float(wc) * t.c, t.n, false,
                             nullptr, ls))
    return false;
  if (ls->pdf > 0.0f) ls->pdf = float(double(pick) / s.omega);
  return true;
}

// The probability of picking triangle (a, b, c) of light l: its area over the light's, the area
// computed as the set computed it.
float triangle_pick_probability(const SampledLight& l, const glm::vec3& a, const glm::vec3& b,
                                const glm::vec3& c) {
  return 0.5f * glm::length(glm::cross(b - a, c - a)) * l.inv_area;
}

// A point on one of mesh light l's triangles, picked with probability area / l.area and uniformly
// on it (by solid angle where the triangle is seen under a usable one, above); two-sided. Fills
// ls and returns whether the point can send light towards p. Every light sample of a mesh light
// comes here: its triangle's corners and normal are read from the light's own table, and
// 1 / area is the light's.
bool sample_triangles(const SampledLight& l, const glm::vec3& p, glm::vec2 u, LightSample* ls) {
  int cell;
  const float x = l.triangle_pick.sample_continuous(u.x, nullptr, &cell);
  const float u0 = std::clamp(x * float(l.triangle_pick.size()) - float(cell), 0.0f, 1.0f);
  const SampledLight::SampledTriangle& t = l.sampled_triangles[cell];
  if (t.n == glm::vec3(0.0f)) return false;
  const SphericalTriangle s = spherical_triangle(p, t.a, t.b, t.c);
  if (s.usable)
    return sample_triangle_by_solid_angle(l, t, s, triangle_pick_probability(l, t.a, t.b, t.c), p,
                                          {u0, u.y}, ls);
  const glm::vec3 bary = square_to_uniform_triangle({u0, u.y});
  return finish_surface_sample(l, p, bary.x * t.a, bary.y * t.b, bary.z * t.c, t.n, false,
                               nullptr, ls);
}

// A point of a panel light: corner + u.x·edge_u + u.y·edge_v, uniform on the light's rectangle
// (density 1 / area), one-sided. The terms' rounding is within γ6 of their sizes; panel_slack
// widens the box to take in the panel's triangles (SampledLight says what it covers).
bool sample_quad(const SampledLight& l, const glm::vec3& p, glm::vec2 u, LightSample* ls) {
  return finish_surface_sample(l, p, l.corner, u.x * l.edge_u, u.y * l.edge_v, l.normal, true,
                               &l.panel_slack, ls);
}

// A panel's or mesh's sample from p into *ls (LightSample{} where its point cannot light p).
[[gnu::always_inline]] inline void sample_surface(const SampledLight& l, const glm::vec3& p, glm::vec2 u,
                                                  LightSample* ls) {
  const bool found = l.quad ? sample_quad(l, p, u, ls) : sample_triangles(l, p, u, ls);
  if (!found) *ls = LightSample{};
}

// Whether panel l's triangles are two that tile a parallelogram (sharing an edge, their far
// corners x and y with x + y = the shared edge's ends, to rounding): if so, sets l's corner, edges
// and panel_slack to it. Every course light's panel is such a quad.
void find_quad(SampledLight* l) {
  if (l->sampled_triangles.size() != 2) return;
  const SampledLight::SampledTriangle &t1 = l->sampled_triangles[0], &t2 = l->sampled_triangles[1];
  if (t1.n == glm::vec3(0.0f) || t2.n == glm::vec3(0.0f)) return;
  const glm::vec3 c1[3] = {t1.a, t1.b, t1.c}, c2[3] = {t2.a, t2.b, t2.c};
  auto in = [](const glm::vec3& q, const glm::vec3* c) {
    return q == c[0] || q == c[1] || q == c[2];
  };
  int x = -1, y = -1, shared = 0;  // x: t1's corner off the shared edge, y: t2's
  for (int i = 0; i < 3; ++i) {
    if (in(c1[i], c2))
      ++shared;
    else
      x = i;
    if (!in(c2[i], c1)) y = i;
  }
  if (shared != 2 || x < 0 || y < 0) return;
  const glm::vec3 s1 = c1[(x + 1) % 3], s2 = c1[(x + 2) % 3];
  const glm::vec3 far = s1 + s2 - c1[x];  // the parallelogram's fourth corner
  const glm::vec3 slack = glm::abs(far - c2[y]);
  const glm::vec3 scale = glm::abs(s1) + glm::abs(s2) + glm::abs(c1[x]) + glm::abs(c2[y]);
  for (int k = 0; k < 3; ++k)
    if (!(slack[k] <= gamma(4) * scale[k])) return;  // not a parallelogram but for rounding
  // Both triangles' normals are already turned to the light's side (sampled_triangles), so the
  // first one's stands for the quad's.
  l->corner = c1[x];
  l->edge_u = s1 - c1[x];
  l->edge_v = s2 - c1[x];
  // The far corner's offset, and the rounding of computing it, both bound how far a point of the
  // parallelogram near it can be from the second triangle.
  l->panel_slack = slack + gamma(3) * scale;
  l->quad = true;
}

// How far panel l's triangles reach from its rectangle's plane, per axis: each corner's distance
// from the plane along the normal, plus γ7 of its coordinates (a triangle hit's error bound), so
// that a ray ending short of a sample's error box widened by this ends short of the panel too.
glm::vec3 panel_depth(const SampledLight& l) {
  glm::vec3 depth(0.0f);
  for (const SampledLight::SampledTriangle& t : l.sampled_triangles)
    for (const glm::vec3& q : {t.a, t.b, t.c})
      depth = glm::max(depth, std::abs(glm::dot(q - l.corner, l.normal)) * glm::abs(l.normal) +
                                  gamma(7) * glm::abs(q));
  return depth;
}

}  // namespace

SampledLights::SampledLights(const Scene& scene, const EnvironmentMap* environment)
    : scene_(scene), environment_(environment) {
  for (const Light& light : scene.lights) {
    SampledLight s;
    s.source = &light;
    s.radiance = light.radiance;
    if (light.kind == LightKind::ambient) {
      if (finite_positive(light.radiance)) ambient_ += light.radiance;
      continue;
    }
    if (!finite_positive(light.radiance)) continue;
    switch (light.kind) {
      case LightKind::point: s.kind = SampledLightKind::point; break;
      case LightKind::spot: s.kind = SampledLightKind::spot; break;
      case LightKind::directional:
        s.kind = SampledLightKind::directional;
        if (!(glm::length(light.direction) > 0.0f)) continue;
        break;
      case LightKind::area: {
        s.kind = SampledLightKind::parallelogram;
        s.edge_u = light.edge_u;
        s.edge_v = light.edge_v;
        s.corner = light.position - 0.5f * light.edge_u - 0.5f * light.edge_v;
        glm::vec3 n = glm::cross(light.edge_u, light.edge_v);
        s.area = glm::length(n);
        if (!(s.area > 0.0f) || !std::isfinite(s.area)) continue;  // nothing to emit from
        s.normal = n / s.area;
        if (glm::dot(s.normal, light.direction) < 0.0f) s.normal = -s.normal;
        break;
      }
      case LightKind::ambient: break;
    }
    lights_.push_back(std::move(s));
  }

  primitive_light_.assign(scene.primitive_count(), -1);
  const size_t scene_lights = lights_.size();
  std::map<uint32_t, SampledLight> meshes;  // by material, so the order is deterministic
  std::map<uint32_t, std::vector<float>> mesh_areas;
  std::vector<std::vector<uint32_t>> panels(scene_lights);
  std::vector<std::vector<float>> panel_areas(scene_lights);
  for (uint32_t i = 0; i < scene.triangles.size(); ++i) {
    const Triangle& tri = scene.triangles[i];
    if (tri.material >= scene.materials.size() || !scene.materials[tri.material].emissive())
      continue;
    const glm::vec3 &a = scene.positions[tri.v[0]], &b = scene.positions[tri.v[1]],
                    &c = scene.positions[tri.v[2]];
    float area = 0.5f * glm::length(glm::cross(b - a, c - a));
    if (!(area > 0.0f) || !std::isfinite(area)) continue;  // degenerate: never hit, never sampled
    int panel_of = -1;
    for (size_t k = 0; k < scene_lights && panel_of < 0; ++k)
      if (lights_[k].kind == SampledLightKind::parallelogram && on_parallelogram(lights_[k], a, b, c))
        panel_of = int(k);
    if (panel_of >= 0) {
      panels[panel_of].push_back(i);
      panel_areas[panel_of].push_back(area);
      continue;
    }
    SampledLight& m = meshes[tri.material];
    m.kind = SampledLightKind::mesh;
    m.radiance = scene.materials[tri.material].emission;
    m.triangles.push_back(i);
    mesh_areas[tri.material].push_back(area);
    m.area += area;
  }
  // An area light with a panel: sampled on the light's own rectangle (its corner, edges and
  // normal, set above), and seen by the camera through the panel's triangles. Where the two have
  // one shape, the panel's own parallelogram is sampled instead: the same points with the same
  // density, and each sample's error box then covers the triangles the camera sees.
  for (size_t k = 0; k < scene_lights; ++k) {
    if (panels[k].empty()) continue;
    SampledLight& l = lights_[k];
    PanelComparison comparison = compare_panel(scene, l, panels[k]);
    if (!comparison.warning.empty()) warnings_.push_back(std::move(comparison.warning));
    l.kind = SampledLightKind::panel;
    l.triangles = std::move(panels[k]);
    l.triangle_pick = Distribution1D(panel_areas[k]);
    l.sampled_triangles = sampled_triangles(scene, l.triangles, l.normal);
    if (comparison.same_shape) {
      SampledLight panel_quad = l;
      find_quad(&panel_quad);
      if (panel_quad.quad) {
        l.corner = panel_quad.corner;
        l.edge_u = panel_quad.edge_u;
        l.edge_v = panel_quad.edge_v;
        l.panel_slack = panel_quad.panel_slack;
        l.normal = panel_quad.sampled_triangles[0].n;
        l.area = 0.0f;
        for (float a : panel_areas[k]) l.area += a;
      }
    }
    l.quad = true;
    l.panel_slack += panel_depth(l);
    for (uint32_t prim : l.triangles) primitive_light_[prim] = int(k);
  }
  for (auto& [material, m] : meshes) {
    m.triangle_pick = Distribution1D(mesh_areas[material]);
    m.sampled_triangles = sampled_triangles(scene, m.triangles, glm::vec3(0.0f));
    for (uint32_t prim : m.triangles) primitive_light_[prim] = int(lights_.size());
    lights_.push_back(std::move(m));
  }
  for (uint32_t i = 0; i < scene.spheres.size(); ++i) {
    const Sphere& sp = scene.spheres[i];
    if (sp.material >= scene.materials.size() || !scene.materials[sp.material].emissive()) continue;
    if (!(sp.radius > 0.0f) || !std::isfinite(sp.radius)) continue;
    SampledLight s;
    s.kind = SampledLightKind::sphere;
    s.radiance = scene.materials[sp.material].emission;
    s.sphere = i;
    s.area = 4.0f * kPi * sp.radius * sp.radius;
    primitive_light_[scene.triangles.size() + i] = int(lights_.size());
    lights_.push_back(std::move(s));
  }
  if (finite_positive(ambient_)) {
    SampledLight s;
    s.kind = SampledLightKind::uniform_environment;
    s.radiance = ambient_;
    lights_.push_back(std::move(s));
  } else {
    ambient_ = glm::vec3(0.0f);
  }
  if (environment_) {
    SampledLight s;
    s.kind = SampledLightKind::image_environment;
    lights_.push_back(std::move(s));
  }
  for (SampledLight& l : lights_)
    if (l.area > 0.0f) l.inv_area = 1.0f / l.area;
}

glm::vec3 SampledLights::environment_radiance(const glm::vec3& dir) const {
  glm::vec3 L = ambient_;
  if (environment_) L += environment_->radiance(dir);
  return L;
}

LightSample SampledLights::make_sample(int index, const SurfaceHit& hit, glm::vec2 u) const {
  const SampledLight& l = lights_[index];
  // One named sample, returned on every path, so it is built in the caller's place.
  LightSample ls;
  if (l.kind == SampledLightKind::panel || l.kind == SampledLightKind::mesh)
    sample_surface(l, hit.p, u, &ls);
  else
    ls = sample_other(l, hit, u);
  return ls;
}

LightSample SampledLights::sample_other(const SampledLight& l, const SurfaceHit& hit,
                                   glm::vec2 u) const {
  LightSample ls;
  const glm::vec3 p = hit.p;
  auto finish_at = [&](const glm::vec3& q, const glm::vec3& q_error, const glm::vec3& n) {
    glm::vec3 d = q - p;
    float dist = glm::length(d);
    if (!(dist > 0.0f) || !std::isfinite(dist)) return false;
    ls.wi = d / dist;
    ls.target.distance = dist;
    ls.target.p = q;
    ls.target.p_error = q_error;
    ls.target.n = n;
    return true;
  };
  switch (l.kind) {
    case SampledLightKind::point:
    case SampledLightKind::spot: {
      const glm::vec3 pos = l.source->position;
      if (!finish_at(pos, glm::vec3(0.0f), glm::vec3(0.0f))) return {};
      float scale = point_falloff(l.source, ls.target.distance);
      if (l.kind == SampledLightKind::spot) {
        float cos_angle = glm::dot(-ls.wi, glm::normalize(l.source->direction));
        float cos_half = std::cos(glm::radians(0.5f * l.source->falloff_degrees));
        if (!(cos_angle >= cos_half)) return {};
        if (l.source->falloff_exponent > 0.0f)
          scale *= std::pow(std::max(0.0f, cos_angle), l.source->falloff_exponent);
      }
      ls.L = l.radiance * scale;
      ls.pdf = 1.0f;
      ls.target.delta = true;
      return ls;
    }
    case SampledLightKind::directional:
      ls.wi = -glm::normalize(l.source->direction);
      ls.L = l.radiance;
      ls.pdf = 1.0f;
      ls.target.delta = true;
      return ls;
    case SampledLightKind::parallelogram: {
      glm::vec3 q = l.corner + u.x * l.edge_u + u.y * l.edge_v;
      glm::vec3 err = gamma(5) * (glm::abs(l.corner) + glm::abs(u.x * l.edge_u) +
                                  glm::abs(u.y * l.edge_v));
      if (!finish_at(q, err, l.normal)) return {};
      float cos_l = glm::dot(-ls.wi, l.normal);
      if (!(cos_l > 0.0f)) return {};  // the back of a one-sided light
      ls.pdf = area_to_solid_angle_pdf(1.0f / l.area, ls.target.distance, cos_l);
      ls.L = ls.pdf > 0.0f ? l.radiance : glm::vec3(0.0f);
      return ls;
    }
    case SampledLightKind::panel:
    case SampledLightKind::mesh:
      return {};  // make_sample() samples these
    case SampledLightKind::sphere: {
      const Sphere& s = scene_.spheres[l.sphere];
      glm::vec3 dc = s.center - p;
      float dist2 = glm::dot(dc, dc);
      float r = s.radius;
      glm::vec3 q;
      if (dist2 > r * r) {
        // Outside: directions of the cone the sphere subtends, then where each meets it.
        float one_minus_cos = sphere_cone_one_minus_cos(r, dist2);
        if (!(one_minus_cos > 0.0f)) return {};
        Frame frame(dc / std::sqrt(dist2));
        glm::vec3 w = frame.to_world(square_to_uniform_cone(u, one_minus_cos));
        double bd = glm::dot(glm::dvec3(w), glm::dvec3(dc));
        double disc = double(r) * r - (double(dist2) - bd * bd);
        double t = disc > 0.0 ? bd - std::sqrt(disc) : bd;  // tangent rays touch at bd
        q = p + float(t) * w;
        glm::vec3 n = glm::normalize(q - s.center);
        if (!finish_at(q, gamma(5) * (glm::abs(q) + glm::vec3(r)), n)) return {};
        ls.wi = w;  // the cone's direction, whatever the rounding of q
        ls.pdf = uniform_cone_pdf(one_minus_cos);
      } else {
        // Inside: uniform points of the surface, seen from within.
        glm::vec3 n = square_to_uniform_sphere(u);
        q = s.center + r * n;
        if (!finish_at(q, gamma(5) * (glm::abs(s.center) + glm::vec3(r)), n)) return {};
        ls.pdf = area_to_solid_angle_pdf(1.0f / l.area, ls.target.distance, glm::dot(ls.wi, n));
      }
      ls.L = ls.pdf > 0.0f && std::isfinite(ls.pdf) ? l.radiance : glm::vec3(0.0f);
      if (!std::isfinite(ls.pdf)) ls.pdf = 0.0f;
      return ls;
    }
    case SampledLightKind::uniform_environment:
      ls.wi = square_to_uniform_sphere(u);
      ls.pdf = uniform_sphere_pdf();
      ls.L = l.radiance;
      return ls;
    case SampledLightKind::image_environment:
      ls.wi = environment_->sample(u, &ls.pdf);
      ls.L = ls.pdf > 0.0f ? environment_->radiance(ls.wi) : glm::vec3(0.0f);
      return ls;
  }
  return ls;
}

float SampledLights::pdf(int index, const SurfaceHit& hit, const glm::vec3& wi,
                    const SurfaceHit* on_light) const {
  const SampledLight& l = lights_[index];
  switch (l.kind) {
    case SampledLightKind::point:
    case SampledLightKind::spot:
    case SampledLightKind::directional:
      return 0.0f;
    case SampledLightKind::parallelogram:
    case SampledLightKind::panel: {
      // Where the direction crosses the light's rectangle, wherever the ray ended: whether it
      // reached the light is emitted_along's answer.
      (void)on_light;
      float t = hit_parallelogram(l, hit.p, wi);
      float cos_l = glm::dot(-wi, l.normal);
      if (!(t > 0.0f) || !(cos_l > 0.0f)) return 0.0f;
      return area_to_solid_angle_pdf(1.0f / l.area, t, cos_l);
    }
    case SampledLightKind::mesh: {
      if (!on_light || light_of_primitive(on_light->primitive) != index) return 0.0f;
      const Triangle& tri = scene_.triangles[on_light->primitive];
      const glm::vec3 &a = scene_.positions[tri.v[0]], &b = scene_.positions[tri.v[1]],
                      &c = scene_.positions[tri.v[2]];
      const SphericalTriangle s = spherical_triangle(hit.p, a, b, c);
      if (s.usable) return float(double(triangle_pick_probability(l, a, b, c)) / s.omega);
      return area_to_solid_angle_pdf(1.0f / l.area, glm::length(on_light->p - hit.p),
                                     glm::dot(wi, on_light->ng));
    }
    case SampledLightKind::sphere: {
      if (!on_light || light_of_primitive(on_light->primitive) != index) return 0.0f;
      const Sphere& s = scene_.spheres[l.sphere];
      glm::vec3 dc = s.center - hit.p;
      float dist2 = glm::dot(dc, dc);
      if (dist2 > s.radius * s.radius)
        return uniform_cone_pdf(sphere_cone_one_minus_cos(s.radius, dist2));
      return area_to_solid_angle_pdf(1.0f / l.area, glm::length(on_light->p - hit.p),
                                     glm::dot(wi, on_light->ng));
    }
    case SampledLightKind::uniform_environment:
      return on_light ? 0.0f : uniform_sphere_pdf();
    case SampledLightKind::image_environment:
      return on_light ? 0.0f : environment_->pdf(wi);
  }
  return 0.0f;
}

glm::vec3 SampledLights::emitted(int index, const SurfaceHit& on_light, const glm::vec3& wi) const {
  const SampledLight& l = lights_[index];
  switch (l.kind) {
    case SampledLightKind::panel: {
      if (on_light.primitive >= scene_.triangles.size()) return glm::vec3(0.0f);
      const Triangle& tri = scene_.triangles[on_light.primitive];
      const glm::vec3 n = triangle_normal(scene_.positions[tri.v[0]], scene_.positions[tri.v[1]],
                                          scene_.positions[tri.v[2]], l.normal);
      return glm::dot(-wi, n) > 0.0f ? l.radiance : glm::vec3(0.0f);
    }
    case SampledLightKind::mesh:
    case SampledLightKind::sphere:
      return l.radiance;
    case SampledLightKind::uniform_environment:
      return l.radiance;
    case SampledLightKind::image_environment:
      return environment_->radiance(wi);
    default:
      (void)on_light;
      return glm::vec3(0.0f);
  }
}

glm::vec3 SampledLights::emitted_along(int index, const Ray& ray, const SurfaceHit* hit) const {
  const SampledLight& l = lights_[index];
  const bool hit_is_this_light = hit && light_of_primitive(hit->primitive) == index;
  switch (l.kind) {
    case SampledLightKind::panel: {
      // The light's rectangle, from its front, before anything the ray hit but its own panel
      // (which lies in the rectangle's plane and does not hide it).
      if (!(glm::dot(-ray.d, l.normal) > 0.0f)) return glm::vec3(0.0f);
      const float t = hit_parallelogram(l, ray.o, ray.d);
      if (!(t > ray.tmin)) return glm::vec3(0.0f);
      if (hit && !hit_is_this_light && !(hit->t >= t)) return glm::vec3(0.0f);
      return l.radiance;
    }
    case SampledLightKind::mesh:
    case SampledLightKind::sphere:
      return hit_is_this_light ? emitted(index, *hit, ray.d) : glm::vec3(0.0f);
    case SampledLightKind::uniform_environment:
    case SampledLightKind::image_environment:
      return hit ? glm::vec3(0.0f) : emitted(index, SurfaceHit{}, ray.d);
    default:
      return glm::vec3(0.0f);  // delta lights and area lights without a panel: no ray reaches them
  }
}

glm::vec3 SampledLights::radiance_along(const Ray& ray, const SurfaceHit* hit) const {
  glm::vec3 L(0.0f);
  for (int k = 0; k < int(lights_.size()); ++k) L += emitted_along(k, ray, hit);
  return L;
}

bool SampledLights::meets_only_own_panel(const RayQuery& query, const Ray& ray, int index) const {
  // Every finite light's samples lie on its own surface (a panel light's on its rectangle, with
  // the panel inside each sample's error box; a mesh's on its triangles), and the shadow ray stops
  // short of the sample's box, so whatever it meets is something else, in the way. Only a ray
  // leaving from between a panel and its light's plane (within panel_slack of it) can meet the
  // panel, which does not hide its light (as emitted_along says): it walks past it.
  const SampledLight& l = lights_[index];
  if (l.kind != SampledLightKind::panel ||
      glm::dot(ray.o - l.corner, l.normal) > glm::dot(l.panel_slack, glm::abs(l.normal)))
    return false;
  Ray rest = ray;
  SurfaceHit h;
  for (int i = 0; i < 8; ++i) {
    if (!query.intersect(rest, &h)) return true;
    if (light_of_primitive(h.primitive) != index) return false;
    // Past the hit; at least a float further, for a query whose t rounds to the one before.
    rest.tmin = std::max(h.t, std::nextafter(rest.tmin, std::numeric_limits<float>::infinity()));
  }
  return false;
}

}  // namespace pt
