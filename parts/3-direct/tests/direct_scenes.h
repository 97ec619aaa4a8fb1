// Scenes the Part 3 step tests share, each with a known answer, and the step's own estimator
// called on its own: the rig finds the hit (its exact ray query, not Parts 1-2) and shades it with
// its own Lambertian (not the student's DiffuseBsdf of step 1), and no zero-bounce term or
// one_bounce_radiance (steps 2 and 5) stands between the test and the estimator it grades.
#pragma once

#include <string>

#include <glm/vec3.hpp>
#include <gtest/gtest.h>

#include "framework/scene/collada_loader.h"
#include "framework/testing/lighting_rig.h"
#include "parts/3-direct/direct_lighting.h"

namespace pt::test {

/// Significance of each known-answer t-test.
constexpr double kDirectAlpha = 0.001;

/// A hit of the rig's query, shaded with the rig's Lambertian in place of the student's.
using RigPoint = ShadedByRig<ShadingPoint, DiffuseBsdf>;

/// Direct light reflected towards `ray`'s origin at its first hit, by step 3's
/// estimate_direct_hemisphere (`hemisphere`) or step 4's estimate_direct_importance alone: the
/// emission the ray itself sees is not added. Zero when the ray hits nothing.
inline glm::vec3 reflected_at_hit(const Rig& rig, bool hemisphere, const Ray& ray, Rng& rng) {
  SurfaceHit hit;
  if (!rig.query.intersect(ray, &hit)) return glm::vec3(0.0f);
  const RigPoint p(rig.ctx.scene, ray, hit);
  return hemisphere ? estimate_direct_hemisphere(rig.ctx, p.point, rng)
                    : estimate_direct_importance(rig.ctx, p.point, rng);
}

/// The estimator reflected_at_hit calls, as sample_values wants it.
inline Estimator direct_estimator(const Rig& rig, bool hemisphere) {
  return [&rig, hemisphere](const Ray& r, Rng& g) { return reflected_at_hit(rig, hemisphere, r, g); };
}

/// What a known-answer test's failing ratio to the exact value means, for the estimator it
/// graded taking `n` samples (ctx.light_samples).
inline std::string estimator_hint(bool hemisphere, int n, double mean, double expected) {
  const double dn = n;
  if (hemisphere)
    return ratio_hint(mean, expected,
                      {{1.0 / (2.0 * M_PI), "each direction's f·L·cosθ not divided by its density 1/(2π)?"},
                       {0.5, "a factor 2 lost: a uniform hemisphere direction's density is 1/(2π), not 1/π? Or half the "
                             "rays sent into the surface: a local direction used as a world one "
                             "(sp.frame.to_world)?"},
                       {2.0, "twice: divided by 1/(4π), the whole sphere's density, not the hemisphere's 1/(2π)?"},
                       {dn, "the samples summed, not averaged?"}});
  return ratio_hint(mean, expected,
                    {{dn, "each light's samples summed, not averaged?"},
                     {1.0 / dn, "each light's sum divided by the sample count twice?"},
                     {M_PI, "π times: the sample's f·L·cosθ without the BSDF's 1/π, or a density off by π?"}});
}

/// What an estimate of exactly zero under an open sky means.
inline std::string sky_unseen_hint(bool hemisphere) {
  return hemisphere ? ": no light at all under an open sky: does a direction that escapes see the "
                      "environment (ctx.lights.environment_radiance)?"
                    : ": no light at all under an open sky: is the environment light sampled like "
                      "any other light of ctx.lights?";
}

/// A diffuse unit sphere of albedo rho at the origin under a uniform sky of radiance L.
inline Scene sphere_under_sky(float rho, float L) {
  Scene s;
  uint32_t m = add_material(s, glm::vec3(rho));
  s.spheres.push_back(Sphere{glm::vec3(0.0f), 1.0f, m});
  s.lights.push_back(ambient_light(glm::vec3(L)));
  return s;
}

/// An area light's panel hangs just under a ceiling, facing down (as in the course's Cornell
/// boxes). The light shines down only, so its panel must glow on that side only: seen from
/// above, and for the ceiling over it, whichever estimator is used.
inline Scene panel_under_ceiling() {
  Scene s;
  const uint32_t white = add_material(s, glm::vec3(0.5f));
  const uint32_t glow = add_material(s, glm::vec3(0.0f), glm::vec3(5.0f));
  add_quad(s, {-2, -2, 1}, {2, -2, 1}, {2, 2, 1}, {-2, 2, 1}, white);  // ceiling
  add_square_ceiling_light(s, 0.5f, 0.99f, glm::vec3(5.0f), glow);  // the panel and its light
  return s;
}

/// The mean radiance of a floor point under the panel of panel_under_ceiling(), over `n`
/// estimates: lit, by either estimator (the panel's lit side faces the floor).
inline double floor_under_panel_light(bool hemisphere, int n = 400) {
  Scene s = panel_under_ceiling();
  const uint32_t floor = add_material(s, glm::vec3(0.5f));
  add_quad(s, {-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}, floor);
  Rig rig(s);
  Rng rng(11);
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    Ray r;
    r.o = glm::vec3(0.1f, -0.1f, 0.5f);
    r.d = glm::vec3(0.0f, 0.0f, -1.0f);
    sum += reflected_at_hit(rig, hemisphere, r, rng).x;
  }
  return sum / n;
}

/// A diffuse plane of albedo 0.3 facing a uniform sky of radiance 1.5.
inline Scene plane_under_sky() {
  Scene s;
  uint32_t m = add_material(s, glm::vec3(0.3f));
  add_quad(s, {-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}, m);
  s.lights.push_back(ambient_light(glm::vec3(1.5f)));
  return s;
}

/// A ray from above the plane, at a random point of a unit square over its centre.
inline Ray ray_at_plane(Rng& g) {
  Ray r;
  r.o = glm::vec3(g.next_float() - 0.5f, g.next_float() - 0.5f, 1.0f);
  r.d = glm::normalize(glm::vec3(0.1f, -0.2f, -1.0f));
  return r;
}

/// A convex diffuse sphere of albedo ρ under a uniform sky L never sees itself: L_out = ρL, by
/// hemisphere or light sampling. Expects it within chance.
inline void expect_sphere_under_sky_is_rho_times_l(bool hemisphere) {
  const float rho = 0.6f, L = 2.0f;
  Rig rig(sphere_under_sky(rho, L));
  rig.ctx.light_samples = 4;
  auto xs = sample_values(direct_estimator(rig, hemisphere), ray_at_unit_sphere, 20000, 11);
  auto c = t_test_mean(xs, rho * L, kDirectAlpha);
  EXPECT_TRUE(c.pass) << "a sphere under a uniform sky: mean " << c.mean << " ± " << c.stderr_
                      << ", expected " << rho * L
                      << (c.mean == 0.0 ? sky_unseen_hint(hemisphere)
                                        : estimator_hint(hemisphere, 4, c.mean, rho * L));
}

/// A diffuse plane facing a uniform sky, seen from above: ρL as well (it sees only sky), by
/// hemisphere or light sampling. Expects it within chance.
inline void expect_plane_under_sky_is_rho_times_l(bool hemisphere) {
  Rig rig(plane_under_sky());
  rig.ctx.light_samples = 2;
  auto xs = sample_values(direct_estimator(rig, hemisphere), ray_at_plane, 20000, 5);
  auto c = t_test_mean(xs, 0.3 * 1.5, kDirectAlpha);
  EXPECT_TRUE(c.pass) << "a plane under a uniform sky: mean " << c.mean << " ± " << c.stderr_
                      << ", expected 0.45"
                      << (c.mean == 0.0 ? sky_unseen_hint(hemisphere)
                                        : estimator_hint(hemisphere, 2, c.mean, 0.45));
}

/// A diffuse plane of albedo 0.3 seen from below, its underside facing a uniform sky of radiance
/// 1.5, with a black plane half a unit above it: the point sees only sky through the hemisphere
/// on the viewer's side (its shading normal points down, -z in the world), ρL again. Directions
/// left in the shading frame (local z taken as world z) go up into the black plane: nothing.
inline Scene plane_seen_from_below() {
  Scene s;
  const uint32_t grey = add_material(s, glm::vec3(0.3f));
  const uint32_t black = add_material(s, glm::vec3(0.0f));
  add_quad(s, {-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}, grey);
  add_quad(s, {-50, -50, 0.5f}, {50, -50, 0.5f}, {50, 50, 0.5f}, {-50, 50, 0.5f}, black);
  s.lights.push_back(ambient_light(glm::vec3(1.5f)));
  return s;
}

/// The plane of plane_seen_from_below from below: ρL (0.45), by hemisphere or light sampling,
/// within chance. The shading frame's z is the world's -z here, so a direction used in the wrong
/// frame (local for world, or world for local) meets the black plane instead of the sky.
inline void expect_plane_seen_from_below_is_rho_times_l(bool hemisphere) {
  Rig rig(plane_seen_from_below());
  rig.ctx.light_samples = 2;
  auto xs = sample_values(
      direct_estimator(rig, hemisphere),
      [](Rng& g) {
        Ray r;
        r.o = glm::vec3(g.next_float() - 0.5f, g.next_float() - 0.5f, -1.0f);
        r.d = glm::normalize(glm::vec3(0.1f, -0.2f, 1.0f));
        return r;
      },
      20000, 6);
  auto c = t_test_mean(xs, 0.3 * 1.5, kDirectAlpha);
  EXPECT_TRUE(c.pass) << "the underside of a plane (shading normal -z in the world) under a uniform "
                      << "sky: mean " << c.mean << " ± " << c.stderr_ << ", expected 0.45"
                      << (c.mean < 0.05 ? ": next to nothing: a direction used in the wrong frame "
                                          "(sp.frame.to_world for a ray, sp.frame.to_local for "
                                          "f and cosθ)?"
                                        : estimator_hint(hemisphere, 2, c.mean, 0.45));
}

/// The sum of 64 estimates at the point of the ceiling over the panel, seen from below, by
/// hemisphere or light sampling (64 samples each).
inline glm::vec3 ceiling_over_panel_light(bool hemisphere) {
  Rig rig(panel_under_ceiling());
  rig.ctx.light_samples = 64;
  Ray up;
  up.o = glm::vec3(0.1f, 0.2f, 0.995f);
  up.d = glm::vec3(0.0f, 0.0f, 1.0f);
  SurfaceHit hit;
  if (!rig.query.intersect(up, &hit)) return glm::vec3(-1.0f);  // never: the ceiling is there
  const RigPoint p(rig.ctx.scene, up, hit);
  Rng rng(5);
  glm::vec3 sum(0.0f);
  for (int i = 0; i < 64; ++i)
    sum += hemisphere ? estimate_direct_hemisphere(rig.ctx, p.point, rng)
                      : estimate_direct_importance(rig.ctx, p.point, rng);
  return sum;
}

/// A closed box whose six faces are one CGL emitter (radiance 2) with a phong diffuse colour 0.8,
/// as Blender writes the course's light panels. The course reads such a material as emission
/// only: every ray inside sees exactly the radiance. Were the panels to reflect their diffuse
/// colour as well, the irradiance πE inside the uniform enclosure would add a·E to every
/// direct-light estimate (E/(1 − a) over all bounces).
struct EmitterBox {
  static constexpr double kRadiance = 2.0, kDiffuse = 0.8;
};
constexpr char kEmitterBoxDae[] = R"(<?xml version="1.0"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <library_effects><effect id="glow-fx"><profile_COMMON><technique sid="common"><phong>
    <emission><color>0 0 0 1</color></emission><diffuse><color>0.8 0.8 0.8 1</color></diffuse>
  </phong></technique></profile_COMMON>
  <extra><technique profile="CGL"><emission><radiance>2 2 2</radiance></emission></technique></extra>
  </effect></library_effects>
  <library_materials><material id="glow" name="glow"><instance_effect url="#glow-fx"/></material></library_materials>
  <library_geometries><geometry id="box"><mesh>
    <source id="box-p"><float_array id="box-pa" count="24">-1 -1 -1 1 -1 -1 -1 1 -1 1 1 -1 -1 -1 1 1 -1 1 -1 1 1 1 1 1</float_array>
      <technique_common><accessor source="#box-pa" count="8" stride="3"/></technique_common></source>
    <vertices id="box-v"><input semantic="POSITION" source="#box-p"/></vertices>
    <polylist material="glow" count="6"><input semantic="VERTEX" source="#box-v" offset="0"/>
      <vcount>4 4 4 4 4 4</vcount><p>0 2 3 1 4 5 7 6 0 1 5 4 2 6 7 3 0 4 6 2 1 3 7 5</p></polylist>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="s"><node id="n"><instance_geometry url="#box">
    <bind_material><technique_common><instance_material symbol="glow" target="#glow"/></technique_common></bind_material>
  </instance_geometry></node></visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>)";
inline Scene emitter_box() {
  return load_collada_string(kEmitterBoxDae, "emitter_box.dae", [](const std::string&) {});
}

/// Inside the emitter box, by hemisphere or light sampling: the panels are emitters, which
/// reflect nothing, so every estimate at them is exactly zero (the camera sees their E, never
/// E(1 + a)). A test that zero is right proves nothing alone (a stub returns it), so the same box
/// read as diffuse panels of albedo a, which do reflect, must give a·E (within chance).
inline void expect_emitter_box_reflects_nothing(bool hemisphere) {
  const double E = EmitterBox::kRadiance, a = EmitterBox::kDiffuse;
  const Scene box = emitter_box();
  ASSERT_EQ(box.triangles.size(), 12u);
  {
    Rig rig(box);
    rig.ctx.light_samples = 4;
    auto xs = sample_values(direct_estimator(rig, hemisphere), ray_from_inside, 400, 3);
    for (double x : xs)
      ASSERT_EQ(x, 0.0) << (hemisphere ? "hemisphere" : "importance")
                        << ": an emitter panel reflects nothing (its BSDF is black)";
  }
  Scene reflecting = box;
  for (Material& m : reflecting.materials) m.kind = MaterialKind::diffuse;
  Rig rig(reflecting);
  rig.ctx.light_samples = 4;
  auto xs = sample_values(direct_estimator(rig, hemisphere), ray_from_inside, 4000, 4);
  auto c = t_test_mean(xs, a * E, kDirectAlpha);
  EXPECT_TRUE(c.pass) << (hemisphere ? "hemisphere" : "importance")
                      << ", panels read as diffuse (albedo a = " << a << ") in a box glowing E = "
                      << E << ": mean " << c.mean << " ± " << c.stderr_ << ", expected a·E = "
                      << a * E << estimator_hint(hemisphere, 4, c.mean, a * E);
}

/// CBcoil's panel and light disagree (disagreeing_panel_scene): the floor under them reflects
/// ρ·L·F with the light's radiance over the light's own rectangle (F by the corner formula), by
/// hemisphere or light sampling alike (hemisphere rays that took the panel's emission instead
/// would bring twice as much). Expects it within chance.
inline void expect_floor_lit_by_the_lights_rectangle(bool hemisphere) {
  using P = DisagreeingPanel;
  const double expected = P::floor_radiance(0.4, 0.0);
  Rig rig(disagreeing_panel_scene());
  rig.ctx.light_samples = 4;
  auto xs = sample_values(
      direct_estimator(rig, hemisphere),
      [](Rng&) {
        Ray r;
        r.o = glm::vec3(0.4f, 0.0f, 0.2f);
        r.d = glm::vec3(0.0f, 0.0f, -1.0f);
        return r;
      },
      hemisphere ? 40000 : 10000, 9);
  auto c = t_test_mean(xs, expected, kDirectAlpha);
  EXPECT_TRUE(c.pass) << (hemisphere ? "hemisphere" : "importance") << ": mean " << c.mean
                      << " ± " << c.stderr_ << ", expected " << expected
                      << estimator_hint(hemisphere, 4, c.mean, expected);
}

}  // namespace pt::test
