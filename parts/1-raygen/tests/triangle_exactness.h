// Part 1: the ray-triangle test against exact rational arithmetic (CGAL's Gmpq), shared by step 3
// (triangle: every correct test, watertight or not, epsilon-free) and step 5 (watertight: the
// cases a fixed epsilon gets wrong: grazing rays, tiny triangles, hits just past the origin).
//
// Every float input is a rational, so the exact answer is computable: the exact edge functions of
// the ray-frame projection, the exact determinant, and the exact t as a rational. The float test
// must agree with it wherever rounding cannot decide the answer. Where that is, is derived here.
//
// Notation: u = 2^-24 (unit roundoff), gamma(n) = n·u/(1 - n·u). q_i = p_i - o (the corners
// relative to the ray origin, in the permuted frame where |d_z| is the largest component), and
//   M = max_i max(|q_i.x|, |q_i.y|, |q_i.z|)  <=  |o|_inf + max_i |p_i|_inf.
//
// HIT/MISS BOUND. The float code computes sheared 2D corners A_i = (q.x + Sx·q.z, q.y + Sy·q.z),
// Sx = -d.x/d.z, Sy = -d.y/d.z, |Sx|,|Sy| <= 1. Each computed coordinate differs from its exact
// value by at most (to first order in u):
//   u(|q.x| + |q.z|)   the rounding of p - o, carried through the shear,
//   u|q.z|             the rounding of Sx,
//   u|q.z|             the rounding of the product Sx·q.z,
//   2u·M               the rounding of the sum (|A.x| <= 2M),
// so by 6u·M. The edge function e = A_i.x·A_j.y - A_i.y·A_j.x is then rounded in two products (a
// relative error u on one factor each, i.e. moving a corner by another u·|A| <= 2u·M per
// coordinate) and one subtraction (a relative error, which cannot change its sign); the double
// fallback at e == 0 is exact for the float corners. So the computed sign of each edge function is
// the exact sign for corners moved by at most 8u·M per coordinate, 8·sqrt(2)·u·M in the plane:
// we take delta = 16·u·M, leaving room for the second-order terms. Moving the corners by delta
// changes E_ij = cross(A_i, A_j) by at most delta·(|A_i| + |A_j|) + delta^2, so its sign is
// certain when
//   |E_ij| > delta·(|A_i| + |A_j|) + delta^2.
// Geometrically: |E_ij| / |A_i - A_j| is the distance, seen along the ray, between the ray and
// the edge's line, so the excluded zone is the band of half-width
//   eps_ij = delta·(|A_i| + |A_j|) / |A_i - A_j|,
// which is about 2·delta = 32·u·(|o| + |p|) for a ray that meets a reasonably shaped triangle
// face-on, and widens only where the problem itself is ill-conditioned (seen edge-on, or far along
// the line beyond a short edge). Both scale with the magnitudes |o| and |p_i|, as rounding does.
// Where every edge is outside its band, hit/miss must agree: 0 disagreements. An edge of two
// equal corners has no band: both tests compute exactly 0 for it (a repeated corner is never hit).
//
// T BOUND. With the exact E_i, Z_i = q_i.z/d.z and D = sum E_i, t = sum E_i Z_i / D. Each computed
// edge function is within Eb_i = delta·(|A_j| + |A_k|) + delta^2 + 2u|E_i| of E_i, each z_i within
// gamma(3)|Z_i| (difference, reciprocal, product), the two sums add gamma(3) and gamma(2). As
// sum E_i Z_i = t·D exactly, the errors of the E_i only enter through (Z_i - t):
//   |t_float - t| <= [ sum Eb_i·|Z_i - t| + gamma(7)·sum (|E_i| + Eb_i)·|Z_i|
//                      + gamma(3)·|t|·sum (|E_i| + Eb_i) ] / (|D| - sum Eb_i - gamma(2)·sum(|E_i|+Eb_i))
//                   + gamma(2)·(|t| + that)
// and the stated relative bound is that divided by t. For a ray meeting a triangle face-on, far
// from its edges and in front of the origin, (Z_i - t) is small and sum|E_i| = |D|, so the bound is
// about 10·u·max|Z_i|/t: a few ulps. It grows exactly where t is ill-conditioned (grazing rays,
// where the triangle spans a long stretch of the ray and D is small). Hits whose t is within this
// bound of tmin, tmax or of the float test's own conservative cut (t must exceed its error bound,
// pbrt-v4 6.8.7) are excluded as well: rounding may legitimately decide those either way.
#pragma once

#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include <glm/geometric.hpp>

#include "framework/math/float_error.h"
#include "framework/sampling/rng.h"
#include "framework/testing/probe_mode.h"
#include "parts/1-raygen/triangle_intersect.h"

namespace pt::test {

using Q = CGAL::Gmpq;
constexpr double kU = 0x1p-24;
constexpr double g(int n) { return n * kU / (1 - n * kU); }

struct Case {
  Ray ray;
  glm::vec3 p[3];
};

struct Tally {
  long cases = 0, exact_hits = 0, float_hits = 0, near_edge = 0, near_t_end = 0, small_t = 0,
       disagreements = 0, t_checked = 0, t_over_bound = 0, behind = 0;
  double max_rel_t_err = 0, max_err_over_bound = 0;
  void add(const Tally& o) {
    cases += o.cases, exact_hits += o.exact_hits, float_hits += o.float_hits, small_t += o.small_t;
    near_edge += o.near_edge, near_t_end += o.near_t_end, disagreements += o.disagreements;
    behind += o.behind;
    t_checked += o.t_checked, t_over_bound += o.t_over_bound;
    max_rel_t_err = std::max(max_rel_t_err, o.max_rel_t_err);
    max_err_over_bound = std::max(max_err_over_bound, o.max_err_over_bound);
  }
};

/// Compares one case with the exact answer and counts it. Hits whose exact t is below `min_t`
/// are not compared (counted as small_t): step 3 leaves them to step 5. A t counts as over its
/// bound beyond `t_slack` times the bound (1: the watertight test's own rounding; step 3 allows
/// any correct float test's, a Möller–Trumbore test's t on a large triangle among them).
inline void check(const Case& c, Tally* tally, const char* kind, double min_t = 0.0,
                  double t_slack = 1.0, bool strict_behind = false) {
  ++tally->cases;
  const Ray& r = c.ray;
  TriangleHit fh;
  const bool float_hit = intersect_triangle(r, c.p[0], c.p[1], c.p[2], &fh);
  tally->float_hits += float_hit;
  if (is_probe()) return;  // the exact answer is the judge's to compute

  // The same permutation as the float code (a choice of frame, not an approximation).
  const glm::vec3 ad = glm::abs(r.d);
  const int kz = (ad.x > ad.y) ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
  const int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  ASSERT_NE(r.d[kz], 0.0f);
  const Q dx(r.d[kx]), dy(r.d[ky]), dz(r.d[kz]);
  const Q sx = -dx / dz, sy = -dy / dz;
  Q ax[3], ay[3], z[3];
  double m = 0;
  for (int i = 0; i < 3; ++i) {
    Q qx = Q(c.p[i][kx]) - Q(r.o[kx]), qy = Q(c.p[i][ky]) - Q(r.o[ky]);
    Q qz = Q(c.p[i][kz]) - Q(r.o[kz]);
    m = std::max({m, std::abs(qx.to_double()), std::abs(qy.to_double()), std::abs(qz.to_double())});
    ax[i] = qx + sx * qz;
    ay[i] = qy + sy * qz;
    z[i] = qz / dz;
  }
  Q e[3];
  for (int i = 0; i < 3; ++i) {
    int j = (i + 1) % 3, k = (i + 2) % 3;  // edge function i is the edge (j, k) facing corner i
    e[i] = ax[j] * ay[k] - ay[j] * ax[k];
  }
  const bool any_neg = e[0] < 0 || e[1] < 0 || e[2] < 0;
  const bool any_pos = e[0] > 0 || e[1] > 0 || e[2] > 0;
  const Q det = e[0] + e[1] + e[2];
  const bool inside = !(any_neg && any_pos) && det != 0;

  // Hit/miss bound (see the top of the file), with 1% headroom for evaluating it in double.
  const double delta = 16.0 * kU * m * 1.01;
  double alen[3], eb[3], ed[3];
  for (int i = 0; i < 3; ++i) alen[i] = std::hypot(ax[i].to_double(), ay[i].to_double());
  bool near_edge = false;
  for (int i = 0; i < 3; ++i) {
    int j = (i + 1) % 3, k = (i + 2) % 3;
    ed[i] = std::abs(e[i].to_double());
    eb[i] = delta * (alen[j] + alen[k]) + delta * delta + 2 * kU * ed[i];
    if (c.p[j] == c.p[k]) continue;  // a repeated corner: both sides compute exactly 0
    if (ed[i] <= (delta * (alen[j] + alen[k]) + delta * delta) * 1.01) near_edge = true;
  }
  if (near_edge) {
    ++tally->near_edge;
    return;
  }

  bool exact_hit = false;
  double t = 0, bound = std::numeric_limits<double>::infinity();
  if (inside) {
    const Q tq = (e[0] * z[0] + e[1] * z[1] + e[2] * z[2]) / det;
    t = tq.to_double();
    // `strict_behind` (step 5): a plane at or behind the origin is never a hit, however close.
    // A test that reports t only above its own error bound never reports one; without that cut
    // rounding turns t = 0 into a tiny positive t, the ray's own surface hit again.
    if (strict_behind && !(tq > Q(r.tmin)) && float_hit) {
      if (++tally->behind <= 5)
        ADD_FAILURE() << kind << ": a hit at t=" << fh.t << " where the exact t is " << t
                      << " (at or behind the origin): a t only rounding made, which must not "
                         "count (report a hit only where t exceeds its own error bound)";
      return;
    }
    exact_hit = tq > Q(r.tmin) && (std::isinf(r.tmax) || tq < Q(r.tmax));
    double num = 0, sum_e = 0, sum_eb = 0, max_z = 0, max_x = 0, max_y = 0;
    for (int i = 0; i < 3; ++i) {
      double zi = z[i].to_double();
      num += eb[i] * std::abs(zi - t) + g(7) * (ed[i] + eb[i]) * std::abs(zi);
      sum_e += ed[i], sum_eb += eb[i];
      max_z = std::max(max_z, std::abs(zi));
      max_x = std::max(max_x, std::abs(ax[i].to_double()));
      max_y = std::max(max_y, std::abs(ay[i].to_double()));
    }
    num += g(3) * std::abs(t) * (sum_e + sum_eb);
    const double den = std::abs(det.to_double()) - sum_eb - g(2) * (sum_e + sum_eb);
    if (den > 0) bound = num / den + g(2) * (std::abs(t) + num / den);
    // The float code's own cut, evaluated on exact values (twice, for its rounding).
    const double err_z = g(3) * max_z, err_x = g(5) * (max_x + max_z),
                 err_y = g(5) * (max_y + max_z);
    const double err_e = 2 * (g(2) * max_x * max_y + err_y * max_x + err_x * max_y);
    const double max_e = std::max({ed[0], ed[1], ed[2]});
    const double cut = 2 * 3 * (g(3) * max_e * max_z + err_e * max_z + err_z * max_e) /
                       std::abs(det.to_double());
    const bool near_end = !(bound < std::numeric_limits<double>::infinity()) ||
                          std::abs(t - r.tmin) <= bound ||
                          (std::isfinite(r.tmax) && std::abs(t - r.tmax) <= bound) ||
                          (t > 0 && t - bound <= cut);
    if (near_end) {
      ++tally->near_t_end;
      return;
    }
    if (t < min_t) {
      ++tally->small_t;
      return;
    }
  }
  tally->exact_hits += exact_hit;
  if (exact_hit != float_hit) {
    if (++tally->disagreements <= 5)
      ADD_FAILURE() << kind << ": exact " << (exact_hit ? "hit" : "miss") << ", float "
                    << (float_hit ? "hit" : "miss") << " t=" << t << " o=(" << r.o.x << ","
                    << r.o.y << "," << r.o.z << ") d=(" << r.d.x << "," << r.d.y << "," << r.d.z
                    << ") p0=(" << c.p[0].x << "," << c.p[0].y << "," << c.p[0].z << ") p1=("
                    << c.p[1].x << "," << c.p[1].y << "," << c.p[1].z << ") p2=(" << c.p[2].x
                    << "," << c.p[2].y << "," << c.p[2].z << ")"
                    << (float_hit && !(fh.t > r.tmin && fh.t < r.tmax)
                            ? ": the hit's t = " + std::to_string(fh.t) +
                                  " lies outside the ray's interval (tmin, tmax) = (" +
                                  std::to_string(r.tmin) + ", " + std::to_string(r.tmax) + ")"
                            : std::string());
    return;
  }
  if (exact_hit) {
    ++tally->t_checked;
    const double err = std::abs(double(fh.t) - t);
    tally->max_rel_t_err = std::max(tally->max_rel_t_err, err / std::abs(t));
    tally->max_err_over_bound = std::max(tally->max_err_over_bound, err / bound);
    if (err > t_slack * bound && ++tally->t_over_bound <= 5)
      ADD_FAILURE() << kind << ": t=" << fh.t << " exact " << t << " bound " << bound;
  }
}

/// Case generators: every one aims some rays at the triangle's inside, some at its edges, some at
/// its corners and some anywhere, so both answers and the boundary between them all occur.
class Cases {
 public:
  explicit Cases(uint64_t seed) : rng_(seed) {}

  float uni(float lo, float hi) { return lo + (hi - lo) * rng_.next_float(); }
  glm::vec3 box(float s) { return glm::vec3(uni(-s, s), uni(-s, s), uni(-s, s)); }
  glm::vec3 unit() {
    glm::vec3 v;
    do v = box(1.0f);
    while (glm::dot(v, v) > 1.0f || glm::dot(v, v) < 1e-4f);
    return glm::normalize(v);
  }

  /// A target: inside (random barycentrics), on an edge (float lerp), at a corner, or near.
  glm::vec3 target(const glm::vec3 p[3], bool boundary = true) {
    const float pick = boundary ? rng_.next_float() : 0.7f * rng_.next_float();
    if (!boundary && pick >= 0.35f) {
      const int i = std::min(int(rng_.next_float() * 3), 2);
      return p[i] + glm::length(p[(i + 1) % 3] - p[i]) * box(1.0f);
    }
    if (pick < 0.35f) {
      float a = rng_.next_float(), b = rng_.next_float();
      if (a + b > 1) a = 1 - a, b = 1 - b;
      return p[0] + a * (p[1] - p[0]) + b * (p[2] - p[0]);
    }
    const int i = std::min(int(rng_.next_float() * 3), 2);
    if (pick < 0.75f) {
      const float s = rng_.next_float();
      return (1.0f - s) * p[i] + s * p[(i + 1) % 3];
    }
    if (pick < 0.9f) return p[i];
    return p[i] + 0.5f * glm::length(p[(i + 1) % 3] - p[i]) * box(1.0f);
  }

  /// The ray from o to `at`, sometimes with a finite tmax around the target (both sides of it).
  /// A random triangle of the box, its unit normal (+z where it has none) and a uniform point of
  /// it: where the rays that return to a surface or leave it start.
  void triangle_and_point(glm::vec3 p[3], glm::vec3* n, glm::vec3* at) {
    for (int i = 0; i < 3; ++i) p[i] = box(5);
    *n = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
    const bool finite = std::isfinite(n->x) && std::isfinite(n->y) && std::isfinite(n->z);
    if (!finite) *n = glm::vec3(0, 0, 1);
    float a = rng_.next_float(), b = rng_.next_float();
    if (a + b > 1) a = 1 - a, b = 1 - b;
    *at = p[0] + a * (p[1] - p[0]) + b * (p[2] - p[0]);
  }
  Case aim(const glm::vec3& o, const glm::vec3& at, const glm::vec3 p[3]) {
    Case c;
    c.ray.o = o;
    c.ray.d = at - o;
    if (c.ray.d == glm::vec3(0.0f)) c.ray.d = unit();
    if (rng_.next_float() < 0.15f) c.ray.tmax = uni(0.5f, 1.5f);
    for (int i = 0; i < 3; ++i) c.p[i] = p[i];
    return c;
  }

  /// Random corners and origin; rays at the inside, near it, or anywhere, never aimed at an edge.
  Case random() {
    glm::vec3 p[3] = {box(10), box(10), box(10)};
    const glm::vec3 o = box(10);
    if (rng_.next_float() < 0.3f) {
      Case c = aim(o, o + unit(), p);
      return c;
    }
    return aim(o, target(p, false), p);
  }
  /// Corners around `centre`, `size` across, and an origin `dist` away in a random direction.
  Case placed(glm::vec3 centre, float size, float dist) {
    glm::vec3 p[3] = {centre + box(size), centre + box(size), centre + box(size)};
    return aim(centre + dist * unit(), target(p), p);
  }
  Case edge_or_vertex() {
    glm::vec3 p[3] = {box(5), box(5), box(5)};
    const int i = std::min(int(rng_.next_float() * 3), 2);
    const glm::vec3 o = box(10);
    if (rng_.next_float() < 0.5f) return aim(o, p[i], p);
    const float s = rng_.next_float();
    return aim(o, (1.0f - s) * p[i] + s * p[(i + 1) % 3], p);
  }
  /// Rays that nearly lie in the triangle's plane: origin just off the plane, aimed across it.
  Case grazing() {
    glm::vec3 p[3] = {box(5), box(5), box(5)};
    const glm::vec3 n = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
    const float a = uni(-1, 2), b = uni(-1, 2);
    const glm::vec3 in_plane = p[0] + a * (p[1] - p[0]) + b * (p[2] - p[0]);
    const float lift = 10.0f * std::pow(10.0f, uni(-7, -1)) * (rng_.next_float() < 0.5f ? -1 : 1);
    return aim(in_plane + lift * n, target(p), p);
  }
  /// Rays that start just off the triangle (as a bounce or shadow ray does) and hit it at a
  /// small t: lift 1e-7 to 1e-2 along the normal, unit direction back at a point inside it.
  Case just_off() {
    glm::vec3 p[3], n, at;
    triangle_and_point(p, &n, &at);
    Case c;
    do {  // a lift below the point's rounding leaves no ray: draw again
      const float lift = std::pow(10.0f, uni(-7, -2)) * (rng_.next_float() < 0.5f ? -1 : 1);
      c.ray.o = at + lift * n;
    } while (c.ray.o == at);
    c.ray.d = glm::normalize(at - c.ray.o);
    for (int i = 0; i < 3; ++i) c.p[i] = p[i];
    return c;
  }
  /// Rays that leave the triangle's plane from within rounding of it (as a bounce from a hit
  /// point does): origin at most 1e-5 off the plane over a point inside, moving away from it at
  /// a clear angle, so the plane is at or behind the origin.
  Case leaving() {
    glm::vec3 p[3], n, at;
    triangle_and_point(p, &n, &at);
    const float side = rng_.next_float() < 0.5f ? -1.0f : 1.0f;
    Case c;
    c.ray.o = at + side * std::pow(10.0f, uni(-9, -5)) * n;
    glm::vec3 d;
    do d = glm::normalize(side * n + 0.8f * unit());
    while (!(side * glm::dot(d, n) > 0.2f));
    c.ray.d = d;
    for (int i = 0; i < 3; ++i) c.p[i] = p[i];
    return c;
  }
  Case needle() {
    const glm::vec3 a = box(5);
    const float thin = std::pow(10.0f, uni(-6, -3));
    glm::vec3 p[3] = {a, a + thin * box(1), a + box(3)};
    return aim(box(10), target(p), p);
  }
  Case degenerate() {
    // Integer corners on one line (exactly collinear), or a repeated corner.
    const glm::vec3 a(std::floor(uni(-20, 20)), std::floor(uni(-20, 20)), std::floor(uni(-20, 20)));
    const glm::vec3 w(std::floor(uni(-4, 5)), std::floor(uni(-4, 5)), std::floor(uni(-4, 5)));
    glm::vec3 p[3];
    if (rng_.next_float() < 0.5f) {
      p[0] = a, p[1] = a + std::floor(uni(1, 4)) * w, p[2] = a - std::floor(uni(1, 4)) * w;
    } else {
      p[0] = a, p[1] = a, p[2] = a + box(5);
    }
    std::swap(p[0], p[std::min(int(rng_.next_float() * 3), 2)]);
    return aim(box(30), target(p), p);
  }

 private:
  Rng rng_;
};

inline void print(const char* name, const Tally& t) {
  std::printf(
      "%-28s cases %7ld  exact hits %6ld  float hits %6ld  excluded near edge %5ld, near t ends "
      "%4ld, t below the step's least %ld  disagreements %ld (behind the origin %ld)  max rel t err %.3g (%.3g of bound)\n",
      name, t.cases, t.exact_hits, t.float_hits, t.near_edge, t.near_t_end, t.small_t, t.disagreements, t.behind,
      t.max_rel_t_err, t.max_err_over_bound);
}

template <typename Gen>
Tally run(const char* name, long n, Gen gen, double min_t = 0.0, double t_slack = 1.0,
          bool strict_behind = false) {
  Tally t;
  for (long i = 0; i < n; ++i) check(gen(), &t, name, min_t, t_slack, strict_behind);
  print(name, t);
  return t;
}

}  // namespace pt::test
