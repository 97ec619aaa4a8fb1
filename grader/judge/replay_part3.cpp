// Part 3's functions in a judge: each returns what the probe's record says the student's
// function returned for this call (record.h), so the test decides on the student's answers.
#include "grader/judge/replay.h"
#include "parts/3-direct/diffuse_bsdf.h"
#include "parts/3-direct/direct_lighting.h"

namespace pt {
using judge::Cursor;
using judge::Fn;
using judge::JudgeCall;

namespace {
glm::vec3 replay_vec3(Fn fn) {
  JudgeCall call(fn);
  Cursor& out = call.finish();
  glm::vec3 v = out.get<glm::vec3>();
  judge::all_read(fn, out);
  return v;
}

}  // namespace

glm::vec3 DiffuseBsdf::f(const glm::vec3&, const glm::vec3&) const {
  return replay_vec3(Fn::diffuse_f);
}

glm::vec3 DiffuseBsdf::sample_f(const glm::vec3&, glm::vec2, glm::vec3* wi, float* pdf) const {
  const Fn fn = Fn::diffuse_sample_f;
  JudgeCall call(fn);
  Cursor& out = call.finish();
  glm::vec3 f = out.get<glm::vec3>();
  if (judge::same_presence(fn, out, wi)) *wi = out.get<glm::vec3>();
  if (judge::same_presence(fn, out, pdf)) *pdf = out.get<float>();
  judge::all_read(fn, out);
  return f;
}

float DiffuseBsdf::pdf(const glm::vec3&, const glm::vec3&) const {
  JudgeCall call(Fn::diffuse_pdf);
  Cursor& out = call.finish();
  float p = out.get<float>();
  judge::all_read(Fn::diffuse_pdf, out);
  return p;
}

glm::vec3 zero_bounce_radiance(const LightingContext& ctx, const Ray&, const SurfaceHit&) {
  const Fn fn = Fn::zero_bounce_radiance;
  JudgeCall call(fn);
  Cursor& out = judge::replay_rays(call, fn, ctx.query);
  glm::vec3 L = out.get<glm::vec3>();
  judge::all_read(fn, out);
  return L;
}
glm::vec3 estimate_direct_hemisphere(const LightingContext& ctx, const ShadingPoint&, Rng& rng) {
  return judge::replay_estimate(Fn::estimate_direct_hemisphere, ctx, rng);
}
glm::vec3 estimate_direct_importance(const LightingContext& ctx, const ShadingPoint&, Rng& rng) {
  return judge::replay_estimate(Fn::estimate_direct_importance, ctx, rng);
}
glm::vec3 one_bounce_radiance(const LightingContext& ctx, const ShadingPoint&, Rng& rng) {
  return judge::replay_estimate(Fn::one_bounce_radiance, ctx, rng);
}

}  // namespace pt
